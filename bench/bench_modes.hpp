// The modes of moa_bench besides the default one (a libmoa run on one input), each in its own
// file. Every mode takes the arguments after its name and returns the exit status.
#pragma once

#include <stdexcept>
#include <string>

namespace moa::bench {

// A bad command line: main prints the message and the usage, exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

int sample_main(int argc, char **argv);  // sample_inputs.cpp: generate the inputs
int report_main(int argc, char **argv);  // report.cpp: results -> Markdown
int scan_main(int argc, char **argv);    // range_scan.cpp: a range scan of a mesh

}  // namespace moa::bench
