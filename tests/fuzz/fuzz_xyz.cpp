// libFuzzer target: the bytes are a .xyz file, read as points (XYZ reader).
#include "fuzz/fuzz_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  moa::fuzz::read_both_ways(moa::io::Format::Xyz, data, size);
  return 0;
}
