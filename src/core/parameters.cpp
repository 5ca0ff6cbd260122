#include "core/parameters.hpp"

#include <vector>

namespace moa {
namespace {

struct ParamRow {
  const char *name;
  const char *description;
  double min_value;
  double max_value;
  bool integral;
  double Params::*field;
};

// Name, description, min, max, integral, field. Defaults live in one place only: the
// member initialisers of Params.
const ParamRow kRows[] = {
    {"threads",
     "worker threads for the parallel stages; 0 uses every core, and so does a number "
     "above that (or above the limit of a tbb::global_control the host application holds). "
     "The mesh does not depend on it",
     0, 1024, true, &Params::threads},
    {"neighbors",
     "k of the k-nearest-neighbour graph that supplies the candidate points; in a cloud "
     "sampled along lines (a CT contour stack) whose lists reach too few points of the next "
     "lines, up to five times the rank of the first such point (at most 96); in a cloud of "
     "thin walls (a far sheet within the lists), twice as many",
     8, 64, true, &Params::neighbors},
    {"sphere_radius",
     "radius R of the candidate sphere around a target segment's midpoint, "
     "in units of the local point spacing (never less than just over half the segment)",
     0.6, 8, false, &Params::sphere_radius},
    {"flatness_a",
     "threshold a of the topology judgment function T = (PD/b)^2 (PI/DI)^c: "
     "a triangle is rejected when a neighbour in its sphere has T >= a",
     0.01, 1e9, false, &Params::flatness_a},
    {"flatness_c", "exponent c of the topology judgment function T", 0.25, 4, false,
     &Params::flatness_c},
    {"edge_fold_angle",
     "degrees; two triangles sharing an edge must open at least this angle "
     "alpha (180 = flat), smaller is a fold; the loop module's last patch of a "
     "hole still open at the end may open down to 5",
     0, 179, false, &Params::edge_fold_angle},
    {"vertex_fold_angle",
     "degrees; two triangles sharing only a vertex whose centre directions "
     "make less than this angle alpha are examined by beta and gamma",
     0, 180, false, &Params::vertex_fold_angle},
    {"vertex_open_angle",
     "degrees; when beta and gamma both exceed this the vertex-sharing pair "
     "is a duplicated fan and rejected, unless its corners at the shared "
     "vertex lie side by side",
     0, 180, false, &Params::vertex_open_angle},
    {"max_normal_deviation",
     "degrees; largest angle between a triangle's normal and the local "
     "plane fitted at each of its vertices; at most 40 where every vertex lies "
     "in a thin wall (the far sheet, parallel, in its neighbour list); not "
     "measured at a vertex of a cloud of a few dozen points whose list holds "
     "half of the cloud or more and scatters about evenly every way (no plane)",
     1, 90, false, &Params::max_normal_deviation},
    {"hole_size",
     "widest hole the loop module closes, in units of the local point spacing; a loop's "
     "width is the largest distance from one of its vertices to the nearest vertex a "
     "quarter of the loop away, so a long narrow gap is a hole and an open scan's rim, as "
     "wide as the surface, a border. A loop up to 3 times as wide is a hole too when it is "
     "shorter than half the square root of its surface's vertex count and bends across a "
     "crease (a tear in a large surface, not the rim around it, nor a round hole through a "
     "smooth part of it, nor the flat rim of a tube's open end). Two loops of separate pieces "
     "that run side by side along their whole length, up to twice as far apart, are zipped "
     "shut (the strip between two halves of a CT stack grown apart along one gap between "
     "slices). In a contour stack a loop lying flat in one cut (a face parallel to the "
     "slices) is capped in its plane whatever its width",
     0, 1e9, false, &Params::hole_size},
    {"solid",
     "1 fills every hole whatever its size (the paper's solid models), leaving open only one "
     "that no filling passes the judgment for; 0 keeps large borders open",
     0, 1, true, &Params::solid},
    {"take_in_points", "1 lets the loop module take in points Algorithm 1 left out", 0, 1, true,
     &Params::take_in_points},
    {"smoothing",
     "noisy clouds: the judgment measures its angles on a copy of the points smoothed onto "
     "local quadrics, while the vertices stay the caller's points. 0 never; 1 when the cloud "
     "looks noisy (its scatter off the local plane shrinks relative to the neighbourhood as "
     "the neighbourhood grows, where a clean surface's curvature makes it grow; or, in a "
     "cloud sampled along lines, its lines are not plane curves); 2 always",
     0, 2, true, &Params::smoothing},
    {"edge_flips",
     "1 flips, once the mesh is complete, each edge whose two opposite angles sum past 180 "
     "degrees to the other diagonal of its quad, when that widens the pair's smallest angle, "
     "bends the surface no more (or less than 20 degrees) and crosses nothing; 0 keeps the "
     "triangles as Algorithm 1 and the loop module made them",
     0, 1, true, &Params::edge_flips},
};

}  // namespace

const ParamSpec *param_table(std::size_t &count) {
  static const std::vector<ParamSpec> table = [] {
    const Params defaults;
    std::vector<ParamSpec> out;
    for (const ParamRow &r : kRows)
      out.push_back({r.name, r.description, defaults.*(r.field), r.min_value, r.max_value,
                     r.integral, r.field});
    return out;
  }();
  count = table.size();
  return table.data();
}

const ParamSpec *find_param(std::string_view name) {
  std::size_t count = 0;
  const ParamSpec *table = param_table(count);
  for (std::size_t i = 0; i < count; ++i)
    if (name == table[i].name) return &table[i];
  return nullptr;
}

}  // namespace moa
