// Distance between a reconstructed mesh and the reference surface the points were sampled from:
// both one-sided distances, sampled on each surface and measured exactly (in double precision)
// to the closest point of the other surface through an Embree point-query tree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace moa::bench {

struct SurfaceDistance {
  double diagonal = 0;       // bounding-box diagonal of the reference; the unit of the ratios
  // Mesh -> reference: how far the reconstruction strays from the true surface.
  double max_to_reference = 0, mean_to_reference = 0;
  // Reference -> mesh: how much of the true surface the reconstruction misses (holes).
  double max_from_reference = 0, mean_from_reference = 0;
  size_t samples_mesh = 0, samples_reference = 0;

  // Symmetric Hausdorff distance and the mean of the two one-sided area-weighted means.
  double hausdorff() const {
    return max_to_reference > max_from_reference ? max_to_reference : max_from_reference;
  }
  double mean() const { return 0.5 * (mean_to_reference + mean_from_reference); }
};

// Both meshes as x y z per vertex and 3 indices per triangle. Each surface is sampled with at
// least `min_samples` points spread over its triangles by area (stratified: every triangle gets
// its share, so small features are not missed) plus all of its vertices; the means weight each
// sample by the area it stands for. Deterministic for a given seed. Uses all cores. Throws when
// either mesh has no triangle of positive area.
SurfaceDistance surface_distance(const std::vector<double> &mesh_xyz,
                                 const std::vector<uint32_t> &mesh_tri,
                                 const std::vector<double> &ref_xyz,
                                 const std::vector<uint32_t> &ref_tri, size_t min_samples = 200000,
                                 uint64_t seed = 1);

}  // namespace moa::bench
