// Exact decision whether two mesh faces intersect improperly (contract C5).
#pragma once

#include <cstdint>

namespace moa::quality {

// A face: its vertex indices and pointers to their coordinates. Must not be degenerate
// (distinct indices, not collinear, finite coordinates).
struct Face {
  uint32_t v[3];
  const double *p[3];
};

// True when the two faces share a point that is not a vertex or edge they share by index:
// faces without common vertices intersect if they touch at all; faces sharing a vertex if they
// share anything else; faces sharing an edge if they are coplanar and overlap; faces with the
// same three vertices always.
bool faces_intersect(const Face &t, const Face &u);

}  // namespace moa::quality
