// libFuzzer target: the bytes are a .off file, read as points and as a mesh (OFF reader).
#include "fuzz/fuzz_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  moa::fuzz::read_both_ways(moa::io::Format::Off, data, size);
  return 0;
}
