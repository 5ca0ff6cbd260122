// Inside-out regions told by ray parity. Where a sharp blade is narrower than about three
// spacings, the points of its two sides are each other's neighbours, and Algorithm 1 can carry
// one orientation class from one side round the blade onto the other with a fold in between:
// the far side comes out inside out, tied to the rest along the whole blade. Its seams with
// the faces grown the right way contradict it, but the minimum cut of the inside-out repair
// (orientation_repair.cpp) finds no small set of edges holding it: on 20k samples of a 40°
// blade a third of the surface stayed inside out, with about a thousand boundary edges.
//
// Rays tell inside from outside without any of that: a ray leaving a face on its outer side
// crosses the surface an even number of times, one leaving on its inner side an odd number.
// Each face casts one ray each way and votes; the votes, smoothed over their neighbours,
// mark regions that face the wrong way. A region whose votes say so clearly (many against it,
// few for it, few edges holding it), tied to regions whose votes, taken together, are as clear
// the other way, is cut free along its border and turned round; Algorithm 1 then grows over the
// seams again. On a surface whose sides a ray cannot tell apart (an open sheet, rays through a
// large hole) the votes are mostly blank, and nothing turns.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/growth_state.hpp"

namespace moa {
namespace {

// Rounds of smoothing: each adds the votes of the faces across the three edges.
constexpr int kSmoothingRounds = 3;
// A region's votes stand when it has at least this many faces and the votes that agree with
// it outnumber those that do not, plus the edges of its border, this many times.
constexpr std::size_t kMinRegionFaces = 32;
constexpr std::size_t kVoteMargin = 4;
// And the rays must speak for this share of its faces at least. On an open scan they leave
// through the openings and many votes are blank: on building.ply two regions with votes for 54
// and 86 % of their faces, tied to one with 60 %, were turned, which cost 21 more boundary
// edges and a sixth more time (the regrowth); a blade's regions have 94-98 %, man's 76-88 %.
constexpr double kMinVoteShare = 2.0 / 3.0;
// Rounds in which regions of fewer faces join the faces around them.
constexpr int kSpeckRounds = 4;
// A region held by fewer edges is left to the minimum cut of the inside-out repair
// (orientation_repair.cpp, up to 6 edges), which weighs the seams themselves: on the cow's
// vertex set, camel and elephant-with-holes (CGAL's data) the rays turned regions held by 1-3
// edges that the cut had kept: the first two were left with 51 and 28 more boundary edges, the
// elephant closed with one handle fewer than it has.
constexpr std::size_t kMinBorder = 7;
// The rays leave a little off the normal, a different way for each face, so that no ray of
// a regular grid runs along an edge and counts two faces there.
constexpr double kTilt = 0.05;

// +1: the face looks out as it is oriented; -1: in; 0: the rays cannot tell.
std::vector<int8_t> parity_votes(GrowthState &g) {
  // The points the crossing index holds (the caller's, where the judgment's are smoothed).
  const std::vector<Vec3> &w = g.points.placed();
  MeshState &mesh = g.mesh;
  std::vector<int8_t> votes(mesh.face_count(), 0);
  // The faces as oriented, looked up before the threads start: the lookup compresses the
  // orientation classes' paths as it goes.
  std::vector<Tri> oriented(mesh.face_count());
  for (uint32_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.alive(f)) oriented[f] = mesh.oriented(f);
  tbb::parallel_for(
      tbb::blocked_range<uint32_t>(0, uint32_t(mesh.face_count()), 1024),
      [&](const tbb::blocked_range<uint32_t> &range) {
        std::vector<uint32_t> hits;
        for (uint32_t f = range.begin(); f != range.end(); ++f) {
          if (!mesh.alive(f)) continue;
          const Tri &t = oriented[f];
          const Vec3 &a = w[t[0]], &b = w[t[1]], &c = w[t[2]];
          const Vec3 n = normalized(cross(b - a, c - a));
          if (!(dot(n, n) > 0.5)) continue;  // degenerate
          // A tilt from the face's index alone: the votes do not depend on the threads.
          const uint32_t h = f * 2654435761u;
          const Vec3 tilt{double(h & 0xff) / 255.0 - 0.5, double((h >> 8) & 0xff) / 255.0 - 0.5,
                          double((h >> 16) & 0xff) / 255.0 - 0.5};
          const Vec3 d = normalized(n + tilt * kTilt);
          const Vec3 centre = (a + b + c) * (1.0 / 3.0);
          const bool out_odd = g.crossings.faces_along_ray(centre, d, f, mesh, hits) % 2 == 1;
          const bool in_odd = g.crossings.faces_along_ray(centre, d * -1.0, f, mesh, hits) % 2 == 1;
          if (out_odd != in_odd) votes[f] = in_odd ? 1 : -1;
        }
      });
  return votes;
}

// A connected set of faces whose smoothed votes agree (all inward or all outward).
struct Region {
  bool inward = false;
  std::size_t faces = 0;
  std::size_t agreeing = 0, disagreeing = 0;  // raw votes
  std::size_t border = 0;                     // edges to faces of the other kind
  bool convincing() const {
    return faces >= kMinRegionFaces && agreeing >= kVoteMargin * (disagreeing + border) &&
           double(agreeing) >= kMinVoteShare * double(faces);
  }
};

}  // namespace

std::size_t turn_regions_against_ray_parity(GrowthState &g) {
  MeshState &mesh = g.mesh;
  const uint32_t count = uint32_t(mesh.face_count());
  g.crossings.add_all(mesh);  // every face committed for the rays
  const std::vector<int8_t> votes = parity_votes(g);

  const std::vector<uint32_t> across = mesh.faces_across();
  std::vector<int32_t> score(votes.begin(), votes.end()), next(count);
  for (int round = 0; round < kSmoothingRounds; ++round) {
    for (uint32_t f = 0; f < count; ++f) {
      int32_t s = score[f];
      for (int i = 0; i < 3; ++i)
        if (across[3 * f + i] != kNone) s += score[across[3 * f + i]];
      next[f] = s;
    }
    score.swap(next);
  }
  std::vector<int32_t>().swap(next);

  // The regions, in the order of their first faces.
  std::vector<uint32_t> region_of, queue;
  std::vector<Region> regions;
  auto find_regions = [&] {
    region_of.assign(count, kNone);
    regions.clear();
    for (uint32_t seed = 0; seed < count; ++seed) {
      if (region_of[seed] != kNone || !mesh.alive(seed)) continue;
      const uint32_t id = uint32_t(regions.size());
      Region r;
      r.inward = score[seed] < 0;
      region_of[seed] = id;
      queue.assign(1, seed);
      for (std::size_t k = 0; k < queue.size(); ++k) {
        const uint32_t f = queue[k];
        ++r.faces;
        r.agreeing += votes[f] == (r.inward ? -1 : 1);
        r.disagreeing += votes[f] == (r.inward ? 1 : -1);
        for (int i = 0; i < 3; ++i) {
          const uint32_t h = across[3 * f + i];
          if (h == kNone) continue;
          if ((score[h] < 0) != r.inward) {
            ++r.border;
          } else if (region_of[h] == kNone) {
            region_of[h] = id;
            queue.push_back(h);
          }
        }
      }
      regions.push_back(r);
    }
  };
  // Specks too small to be judged, where the smoothing left a few stray votes, join the faces
  // around them (specks next to each other may make a speck again: a few rounds).
  find_regions();
  for (int round = 0; round < kSpeckRounds; ++round) {
    bool joined = false;
    for (uint32_t f = 0; f < count; ++f) {
      if (region_of[f] == kNone) continue;
      const Region &r = regions[region_of[f]];
      if (r.faces >= kMinRegionFaces || r.border == 0) continue;
      score[f] = r.inward ? 0 : -1;
      joined = true;
    }
    if (!joined) break;
    find_regions();
  }

  // An inward region turns when its votes stand and so do those of the outward regions it is
  // tied to, taken together: the two sides disagree about each other only if both are sure. (A
  // whole piece facing inward has no border: it contradicts nothing, and closed pieces are
  // turned outward at the end.)
  std::vector<uint8_t> turns(regions.size(), 0);
  std::vector<std::pair<uint32_t, uint32_t>> ties;  // (inward region, outward region)
  for (uint32_t f = 0; f < count; ++f) {
    if (region_of[f] == kNone || !regions[region_of[f]].inward) continue;
    for (int i = 0; i < 3; ++i) {
      const uint32_t h = across[3 * f + i];
      if (h != kNone && !regions[region_of[h]].inward) ties.push_back({region_of[f], region_of[h]});
    }
  }
  std::sort(ties.begin(), ties.end());
  ties.erase(std::unique(ties.begin(), ties.end()), ties.end());
  std::vector<Region> tied(regions.size());  // the outward regions next to each, summed
  for (const auto &[in, out] : ties) {
    tied[in].faces += regions[out].faces;
    tied[in].agreeing += regions[out].agreeing;
    tied[in].disagreeing += regions[out].disagreeing;
    tied[in].border += regions[out].border;
  }
  for (std::size_t id = 0; id < regions.size(); ++id)
    turns[id] = regions[id].inward && regions[id].border >= kMinBorder &&
                regions[id].convincing() && tied[id].convincing();
  std::vector<uint32_t> turn, holding;
  for (uint32_t f = 0; f < count; ++f) {
    if (region_of[f] == kNone || !turns[region_of[f]]) continue;
    bool held = false;
    for (int i = 0; i < 3; ++i)
      held |= across[3 * f + i] != kNone && !regions[region_of[across[3 * f + i]]].inward;
    (held ? holding : turn).push_back(f);
  }
  const std::size_t turned = std::size_t(std::count(turns.begin(), turns.end(), 1));
  if (turned == 0) return 0;
  // Cut free along the border, and turned round.
  for (uint32_t f : holding) {
    mesh.remove(f);
    ++g.stats.triangles_removed;
  }
  // The crossing index needs no rebuild: its queries skip removed faces, and a turned face
  // keeps its corners and its place in the records the scene reads.
  mesh.reverse_faces(turn);
  return turned;
}

}  // namespace moa
