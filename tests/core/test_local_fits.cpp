// The local fits under the neighbour, noise and smoothing stages, on point sets whose answer is
// known: a tilted cross whose scatter has off-diagonal terms (pca_frame's axes and spreads, and
// the two-sheet frame of two offset copies), and points lying exactly on a quadric, which the
// smoothing's quadric fit must leave where they are.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"
#include "core/kd_tree.hpp"
#include "core/pca.hpp"
#include "core/smoothing.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace {

using moa::Vec3;

// A rotation about an axis that is no coordinate axis, so that every scatter entry is non-zero.
struct Rotation {
  Vec3 col[3];
  Rotation() {
    const double a = 0.7, b = -0.4, c = 1.1;  // angles about x, then y, then z
    auto rx = [&](Vec3 v) {
      return Vec3{v.x, std::cos(a) * v.y - std::sin(a) * v.z,
                  std::sin(a) * v.y + std::cos(a) * v.z};
    };
    auto ry = [&](Vec3 v) {
      return Vec3{std::cos(b) * v.x + std::sin(b) * v.z, v.y,
                  -std::sin(b) * v.x + std::cos(b) * v.z};
    };
    auto rz = [&](Vec3 v) {
      return Vec3{std::cos(c) * v.x - std::sin(c) * v.y, std::sin(c) * v.x + std::cos(c) * v.y,
                  v.z};
    };
    col[0] = rz(ry(rx({1, 0, 0})));
    col[1] = rz(ry(rx({0, 1, 0})));
    col[2] = rz(ry(rx({0, 0, 1})));
  }
  Vec3 operator()(const Vec3 &v) const { return col[0] * v.x + col[1] * v.y + col[2] * v.z; }
};

void expect_axis(const Vec3 &got, const Vec3 &want) {
  // An axis has no sign.
  assert_true(std::fabs(std::fabs(moa::dot(got, want)) - 1.0) < 1e-12);
}

// The centre and six points at +-3, +-2, +-1 along the rotated axes: the scatter about the
// centre has the spreads 2 * 1, 2 * 4, 2 * 9 along rotated z, y, x.
std::vector<Vec3> tilted_cross(const Vec3 &centre) {
  const Rotation r;
  std::vector<Vec3> p{centre};
  for (double s : {1.0, -1.0}) {
    p.push_back(centre + r({3 * s, 0, 0}));
    p.push_back(centre + r({0, 2 * s, 0}));
    p.push_back(centre + r({0, 0, 1 * s}));
  }
  return p;
}

void test_pca_frame_of_a_tilted_cross(void **) {
  const Rotation r;
  const Vec3 centre{5, -2, 7};
  const std::vector<Vec3> p = tilted_cross(centre);
  const std::vector<uint32_t> nb{1, 2, 3, 4, 5, 6};
  const moa::PcaFrame f = moa::pca_frame(p, 0, nb.data(), unsigned(nb.size()));
  assert_true(moa::norm(f.centroid - centre) < 1e-12);
  const double spreads[3] = {2.0, 8.0, 18.0};
  for (int a = 0; a < 3; ++a) {
    assert_true(std::fabs(f.spread[a] - spreads[a]) < 1e-12);
    expect_axis(f.axis[a], r.col[2 - a]);
  }
  assert_true(std::fabs(moa::flatness_ratio(f) - std::sqrt(2.0 / 8.0)) < 1e-12);
}

// Two copies of the cross, the second moved along its thinnest axis: all together they scatter
// across the sheets, but each sheet about its own centre has the one cross's frame, doubled.
void test_pca_frame_two_sheets_of_tilted_crosses(void **) {
  const Rotation r;
  const Vec3 centre{-1, 4, 0.5};
  std::vector<Vec3> p = tilted_cross(centre);
  for (const Vec3 &q : tilted_cross(centre + r({0, 0, 10}))) p.push_back(q);
  std::vector<uint32_t> nb;
  bool far_sheet[13];
  for (uint32_t j = 1; j < p.size(); ++j) {
    nb.push_back(j);
    far_sheet[j - 1] = j >= 7;
  }
  const moa::PcaFrame f =
      moa::pca_frame_two_sheets(p, 0, nb.data(), unsigned(nb.size()), far_sheet);
  const double spreads[3] = {4.0, 16.0, 36.0};
  for (int a = 0; a < 3; ++a) {
    assert_true(std::fabs(f.spread[a] - spreads[a]) < 1e-9);
    expect_axis(f.axis[a], r.col[2 - a]);
  }
  // All in one scatter, the offset dominates: the thinnest axis is no longer the normal.
  const moa::PcaFrame all = moa::pca_frame(p, 0, nb.data(), unsigned(nb.size()));
  assert_true(std::fabs(moa::dot(all.axis[2], r.col[2])) > 0.99);
}

// A tilted grid on the quadric h = 0.3 u^2 + 0.2 u v - 0.1 v^2. The neighbourhood of the grid's
// centre is symmetric through it, so its frame's normal is the quadric's axis, and in that frame
// the points lie exactly on a quadric: the fit must leave the centre where it is. Elsewhere the
// frame tilts and a quadric in it only comes close: every point stays within 0.005 of the
// grid's spacing (0.0017 measured).
void test_points_on_a_quadric_stay(void **) {
  const Rotation r;
  std::vector<Vec3> p;
  std::size_t centre = 0;
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j) {
      const double u = 0.05 * i, v = 0.05 * j;
      const double h = 0.3 * u * u + 0.2 * u * v - 0.1 * v * v;
      if (i == 0 && j == 0) centre = p.size();
      p.push_back(Vec3{1, 2, 3} + r({u, v, h}));
    }
  const moa::KdIndex index(p);
  const std::vector<Vec3> s = moa::smoothed_points(index, 40, false, [](double) {});
  assert_int_equal(s.size(), p.size());
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) worst = std::max(worst, moa::norm(s[i] - p[i]));
  assert_true(moa::norm(s[centre] - p[centre]) < 1e-12);
  assert_true(worst < 0.005 * 0.05);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pca_frame_of_a_tilted_cross),
      cmocka_unit_test(test_pca_frame_two_sheets_of_tilted_crosses),
      cmocka_unit_test(test_points_on_a_quadric_stay),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
