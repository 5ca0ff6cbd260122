// Shared pieces of the core property tests: run moa::reconstruct on a generated input, check the
// result once with the independent checker, and turn each property into a pass/fail message.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/reconstruct.hpp"
#include "support/contract_checker.hpp"
#include "support/shapes.hpp"

namespace moa::test {

struct Run {
  std::vector<std::uint32_t> triangles;
  moa_stats stats{};
  std::string error;  // what reconstruct threw, if it threw
  double seconds = 0;
};

// The given parameters (the defaults unless a test asks otherwise) with this thread count.
Run run_reconstruct(const Points &points, unsigned threads, Params params = Params());

// One input and its first run (2 threads), checked once.
struct Case {
  std::string name;
  Points points;
  std::size_t duplicates = 0;  // exact duplicate points planted in the input
  Params params;               // every run of the case uses them
  Run run;
  ContractReport report;
};
Case make_case(const std::string &name, Points points, std::size_t duplicates = 0,
               const Params &params = Params());

// Each returns "" when the property holds, else a message for the failure report.
std::string contract_failure(const Case &c);         // C1-C5
std::string stats_failure(const Case &c);            // moa_stats agrees with the result
std::string determinism_failure(const Case &c);      // C6: again with 1 thread, the same triangles
// Closed, one component, the genus, and every unique point used (or at least the share
// min_used of them: on a noisy cloud a point two or three deviations off its surface may be too
// far off every face to be taken in).
std::string closed_failure(const Case &c, long genus, double min_used = 1.0);
std::string disk_failure(const Case &c);             // one disk using every point

}  // namespace moa::test

// Fails the running cmocka test with the message, if there is one. The message lives in a
// static so nothing is leaked when cmocka jumps out of the test.
#define MOA_EXPECT(message_expr)                                  \
  do {                                                            \
    static std::string moa_message_;                              \
    moa_message_ = (message_expr);                                \
    if (!moa_message_.empty()) fail_msg("%s", moa_message_.c_str()); \
  } while (0)

// The three properties every input must have, as cmocka tests named test_<shape>_<property>;
// <shape>_case() must return the shape's const Case&.
#define MOA_CONTRACT_TESTS(shape)                                                           \
  static void test_##shape##_contract(void **) { MOA_EXPECT(moa::test::contract_failure(shape##_case())); } \
  static void test_##shape##_stats(void **) { MOA_EXPECT(moa::test::stats_failure(shape##_case())); }       \
  static void test_##shape##_deterministic(void **) {                                       \
    MOA_EXPECT(moa::test::determinism_failure(shape##_case()));                             \
  }
#define MOA_CONTRACT_ENTRIES(shape)                                              \
  cmocka_unit_test(test_##shape##_contract), cmocka_unit_test(test_##shape##_stats), \
      cmocka_unit_test(test_##shape##_deterministic)
