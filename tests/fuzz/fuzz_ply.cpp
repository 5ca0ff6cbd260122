// libFuzzer target: the bytes are a .ply file, read as points and as a mesh (PLY reader).
#include "fuzz/fuzz_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  moa::fuzz::read_both_ways(moa::io::Format::Ply, data, size);
  return 0;
}
