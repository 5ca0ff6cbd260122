// Morton codes: three 21-bit grid coordinates interleaved bit by bit, so that cells near each
// other in space mostly get codes near each other. The points' internal order (point_set.cpp)
// and the crossing index's grid keys (intersection.cpp) both use them.
#pragma once

#include <cstdint>

namespace moa {

// The low 21 bits of v, spread to every third bit.
inline std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

// The Morton code of cell (x, y, z); only the low 21 bits of each coordinate count.
inline std::uint64_t morton_code(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
  return spread_bits(x) | spread_bits(y) << 1 | spread_bits(z) << 2;
}

}  // namespace moa
