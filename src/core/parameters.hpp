// The parameter table: one row per tunable of the reconstruction. Everything that lists,
// validates or documents parameters (the C ABI, `moa params`, the README) reads this table.
#pragma once

#include <cstddef>
#include <string_view>

namespace moa {

// Plain values handed to the core. Lengths are relative to the local point spacing so that the
// defaults work at any scale; angles are in degrees.
struct Params {
  double threads = 0;                // worker threads, 0 = all cores
  double neighbors = 20;             // k of the k-nearest-neighbour graph
  double sphere_radius = 2.0;        // R of the candidate sphere, in units of local spacing
  double flatness_a = 30.0;          // T threshold a
  double flatness_c = 1.0;           // T exponent c
  double edge_fold_angle = 30;       // minimum alpha between faces sharing an edge
  double vertex_fold_angle = 15;     // vertex alpha below which beta/gamma are examined
  double vertex_open_angle = 120;    // beta and gamma above which a vertex pair is a fold
  double max_normal_deviation = 55;  // triangle normal vs local plane normal
  double hole_size = 5;              // widest hole the loop module closes, in units of spacing
  double solid = 0;                  // 1: close every hole regardless of size
  double take_in_points = 1;         // 1: insert left-out points in the loop/finish stages
  double smoothing = 1;              // 0 never, 1 when the cloud looks noisy, 2 always
  double edge_flips = 1;             // 1: flip edges to the wider pair of faces at the end
};

struct ParamSpec {
  const char *name;
  const char *description;
  double default_value;
  double min_value;
  double max_value;
  bool integral;
  double Params::*field;
};

// The table, in a fixed order that is part of the documented interface.
const ParamSpec *param_table(std::size_t &count);
// Row by name, or nullptr.
const ParamSpec *find_param(std::string_view name);

}  // namespace moa
