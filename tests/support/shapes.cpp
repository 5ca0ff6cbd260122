// Point-set generators. Irregular surfaces are sampled in two steps: many random candidates on
// the surface, then greedy blue-noise thinning, which bounds the spacing from below (no clumps)
// and, with enough candidates, from above (no holes) — a well-sampled input by construction.
#include "support/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace moa::test {

namespace {

constexpr double k_pi = 3.14159265358979323846;

void push(Points &p, double x, double y, double z) {
  p.push_back(x);
  p.push_back(y);
  p.push_back(z);
}

// Surface of the lattice box with n[a] cells along axis a between lo[a] and hi[a].
Points box_lattice(const std::size_t (&n)[3], const double (&lo)[3], const double (&hi)[3]) {
  Points p;
  auto coord = [&](int a, std::size_t i) {
    return i == n[a] ? hi[a] : lo[a] + (hi[a] - lo[a]) * double(i) / double(n[a]);
  };
  for (std::size_t k = 0; k <= n[2]; ++k)
    for (std::size_t j = 0; j <= n[1]; ++j)
      for (std::size_t i = 0; i <= n[0]; ++i) {
        const bool surface = i == 0 || i == n[0] || j == 0 || j == n[1] || k == 0 || k == n[2];
        if (surface) push(p, coord(0, i), coord(1, j), coord(2, k));
      }
  return p;
}

// Blue-noise samples of the square [0,side]^2 (z = 0) with its border sampled first.
Points blue_noise_square(double side, double spacing, Rng &rng) {
  Points candidates;
  const double step = spacing / 16;
  const std::size_t per_edge = static_cast<std::size_t>(std::ceil(side / step));
  for (int edge = 0; edge < 4; ++edge)
    for (std::size_t i = 0; i < per_edge; ++i) {
      const double s = side * double(i) / double(per_edge);
      const double xy[4][2] = {{s, 0}, {side, s}, {side - s, side}, {0, side - s}};
      push(candidates, xy[edge][0], xy[edge][1], 0);
    }
  const std::size_t inner = static_cast<std::size_t>(40 * side * side / (spacing * spacing));
  for (std::size_t i = 0; i < inner; ++i) push(candidates, rng.uniform(0, side), rng.uniform(0, side), 0);
  return thin_points(candidates, spacing);
}

// The blended row of tori used by genus_surface: f = softmin_k(d_k) - r, d_k the distance to
// the k-th core circle. The soft minimum rounds the creases where the tubes meet.
struct ToriRow {
  int count;
  double R = 1.0, r = 0.35, gap = 2.1, blend = 0.12;
  double centre(int k) const { return (k - 0.5 * (count - 1)) * gap; }
  double value(const double *p, double *grad) const {
    double d[3], g[3][3], dmin = HUGE_VAL;
    for (int k = 0; k < count; ++k) {
      const double qx = p[0] - centre(k), qy = p[1], qz = p[2];
      const double rho = std::sqrt(qx * qx + qy * qy), t = rho - R;
      d[k] = std::sqrt(t * t + qz * qz);
      g[k][0] = t * qx / (rho * d[k]);
      g[k][1] = t * qy / (rho * d[k]);
      g[k][2] = qz / d[k];
      dmin = std::min(dmin, d[k]);
    }
    double sum = 0, w[3];
    for (int k = 0; k < count; ++k) sum += w[k] = std::exp(-(d[k] - dmin) / blend);
    for (int a = 0; a < 3; ++a) {
      grad[a] = 0;
      for (int k = 0; k < count; ++k) grad[a] += w[k] / sum * g[k][a];
    }
    return dmin - blend * std::log(sum) - r;
  }
};

}  // namespace

double Rng::uniform() { return double(engine_() >> 11) * 0x1.0p-53; }

double Rng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  for (;;) {
    const double u = 2 * uniform() - 1, v = 2 * uniform() - 1, s = u * u + v * v;
    if (s <= 0 || s >= 1) continue;
    const double f = std::sqrt(-2 * std::log(s) / s);
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }
}

std::uint64_t Rng::below(std::uint64_t n) {
  const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n: the biased low values
  for (;;) {
    const std::uint64_t x = engine_();
    if (x >= threshold) return x % n;
  }
}

Points fibonacci_sphere(std::size_t n, double radius) {
  Points p;
  const double golden = k_pi * (3 - std::sqrt(5.0));
  for (std::size_t i = 0; i < n; ++i) {
    const double z = 1 - (2 * double(i) + 1) / double(n), s = std::sqrt(1 - z * z);
    const double phi = golden * double(i);
    push(p, radius * s * std::cos(phi), radius * s * std::sin(phi), radius * z);
  }
  return p;
}

Points sphere_random(std::size_t n, double radius, std::uint64_t seed) {
  return ellipsoid_random(n, radius, radius, radius, seed);
}

Points ellipsoid_random(std::size_t n, double a, double b, double c, std::uint64_t seed) {
  Rng rng(seed);
  Points p;
  // Map the uniform sphere linearly; the area grows by abc * |(x/a, y/b, z/c)| there, so keep
  // each point with that weight over its maximum (rejection).
  const double max_weight = 1 / std::min({a, b, c});
  while (p.size() < 3 * n) {
    const double x = rng.normal(), y = rng.normal(), z = rng.normal();
    const double len = std::sqrt(x * x + y * y + z * z);
    if (len < 1e-9) continue;
    const double ux = x / len, uy = y / len, uz = z / len;
    const double weight = std::sqrt(ux * ux / (a * a) + uy * uy / (b * b) + uz * uz / (c * c));
    if (rng.uniform() * max_weight < weight) push(p, a * ux, b * uy, c * uz);
  }
  return p;
}

Points torus_random(std::size_t n, double R, double r, std::uint64_t seed) {
  Rng rng(seed);
  Points p;
  while (p.size() < 3 * n) {
    const double u = rng.uniform(0, 2 * k_pi), v = rng.uniform(0, 2 * k_pi);
    // The area element is proportional to R + r cos v.
    if (rng.uniform() * (R + r) >= R + r * std::cos(v)) continue;
    push(p, (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
  }
  return p;
}

Points torus_grid(std::size_t nu, std::size_t nv, double R, double r) {
  Points p;
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) {
      const double u = 2 * k_pi * double(i) / double(nu), v = 2 * k_pi * double(j) / double(nv);
      push(p, (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  return p;
}

std::vector<std::uint32_t> torus_grid_triangles(std::size_t nu, std::size_t nv) {
  std::vector<std::uint32_t> t;
  auto at = [&](std::size_t i, std::size_t j) { return std::uint32_t((j % nv) * nu + i % nu); };
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) {
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      t.insert(t.end(), {a, b, c, a, c, d});
    }
  return t;
}

Points genus_surface(int genus, double spacing, std::uint64_t seed) {
  const ToriRow row{std::clamp(genus, 1, 3)};
  Rng rng(seed);
  const double area = row.count * 4 * k_pi * k_pi * row.R * row.r;
  const std::size_t count = static_cast<std::size_t>(30 * area / (spacing * spacing));
  Points candidates;
  for (std::size_t i = 0; i < count; ++i) {
    // Start on one of the plain tori (uniform by area), then project onto the blended surface.
    const int k = static_cast<int>(rng.below(std::uint64_t(row.count)));
    double u, v;
    do {
      u = rng.uniform(0, 2 * k_pi);
      v = rng.uniform(0, 2 * k_pi);
    } while (rng.uniform() * (row.R + row.r) >= row.R + row.r * std::cos(v));
    const double rr = row.R + row.r * std::cos(v);
    double p[3] = {row.centre(k) + rr * std::cos(u), rr * std::sin(u), row.r * std::sin(v)};
    bool converged = false;
    for (int step = 0; step < 30 && !converged; ++step) {
      double g[3];
      const double f = row.value(p, g), g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
      if (g2 < 1e-12) break;
      for (int a = 0; a < 3; ++a) p[a] -= f * g[a] / g2;
      converged = std::fabs(f) < 1e-13;
    }
    if (converged) push(candidates, p[0], p[1], p[2]);
  }
  return thin_points(candidates, spacing);
}

Points box_grid(double lx, double ly, double lz, double spacing) {
  auto cells = [&](double l) { return std::max<std::size_t>(1, std::size_t(std::lround(l / spacing))); };
  const std::size_t n[3] = {cells(lx), cells(ly), cells(lz)};
  const double lo[3] = {0, 0, 0}, hi[3] = {lx, ly, lz};
  return box_lattice(n, lo, hi);
}

Points cube_grid(std::size_t n) {
  const std::size_t cells[3] = {n, n, n};
  const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
  return box_lattice(cells, lo, hi);
}

Points flat_grid(std::size_t nx, std::size_t ny, double spacing) {
  Points p;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) push(p, double(i) * spacing, double(j) * spacing, 0);
  return p;
}

Points hemisphere(std::size_t n, double radius) {
  Points p = fibonacci_sphere(2 * n, radius);
  p.resize(3 * n);  // the first n points are exactly those with z > 0
  return p;
}

Points saddle(double spacing, std::uint64_t seed) {
  Rng rng(seed);
  Points candidates;
  auto lift = [&](double x, double y) { push(candidates, x, y, x * x - y * y); };
  // The border first, densely, so the thinning keeps a regular border; then the inside.
  const std::size_t per_edge = static_cast<std::size_t>(std::ceil(2 / (spacing / 16)));
  for (int edge = 0; edge < 4; ++edge)
    for (std::size_t i = 0; i < per_edge; ++i) {
      const double s = -1 + 2 * double(i) / double(per_edge);
      const double xy[4][2] = {{s, -1}, {1, s}, {-s, 1}, {-1, -s}};
      lift(xy[edge][0], xy[edge][1]);
    }
  const std::size_t inner = static_cast<std::size_t>(40 * 8 / (spacing * spacing));
  for (std::size_t i = 0; i < inner; ++i) lift(rng.uniform(-1, 1), rng.uniform(-1, 1));
  return thin_points(candidates, spacing);  // in 3-D, so steep parts are not under-sampled
}

namespace {

// Appends the corners of the box [lo, hi] (corner i has x, y, z at the high end where bits 0,
// 1, 2 of i are set) to v, and its twelve triangles, their corners offset by `first`, to t.
void add_box(const double (&lo)[3], const double (&hi)[3], std::uint32_t first,
             std::vector<double> &v, std::vector<std::uint32_t> &t) {
  for (int i = 0; i < 8; ++i)
    v.insert(v.end(), {(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
  for (std::uint32_t c : {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                          2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5})
    t.push_back(first + c);
}

}  // namespace

Points plate_samples(double side, double thickness, std::size_t n, std::uint64_t seed) {
  std::vector<double> v;
  std::vector<std::uint32_t> t;
  add_box({0, 0, 0}, {side, side, thickness}, 0, v, t);
  return sample_mesh(v, t, n, seed);
}

Points hollow_box_samples(double half, double wall, std::size_t n, std::uint64_t seed) {
  std::vector<double> v;
  std::vector<std::uint32_t> t;
  const double in = half - wall;
  add_box({-half, -half, -half}, {half, half, half}, 0, v, t);
  add_box({-in, -in, -in}, {in, in, in}, 8, v, t);
  return sample_mesh(v, t, n, seed);
}

Points pipe_samples(double thickness, double length, std::size_t n, std::uint64_t seed) {
  const std::uint32_t m = 96;
  std::vector<double> v;
  for (std::uint32_t i = 0; i < m; ++i) {  // per step: outer and inner, at both ends
    const double a = 2 * k_pi * double(i) / double(m), c = std::cos(a), s = std::sin(a);
    for (double r : {1.0, 1.0 - thickness})
      for (double z : {0.0, length}) v.insert(v.end(), {r * c, r * s, z});
  }
  std::vector<std::uint32_t> t;
  auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    t.insert(t.end(), {a, b, c, a, c, d});
  };
  for (std::uint32_t i = 0; i < m; ++i) {
    const std::uint32_t p = 4 * i, q = 4 * ((i + 1) % m);  // outer 0 / L, inner 0 / L
    quad(p, q, q + 1, p + 1);          // outer wall
    quad(p + 2, p + 3, q + 3, q + 2);  // inner wall
    quad(p, p + 2, q + 2, q);          // end at 0
    quad(p + 1, q + 1, q + 3, p + 3);  // end at length
  }
  return sample_mesh(v, t, n, seed);
}

Points drilled_plate_samples(double bore, std::size_t n, std::uint64_t seed) {
  constexpr double kThickness = 0.1;
  const double centres[5][2] = {{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.5}, {0.2, 0.8}, {0.8, 0.8}};
  // Each draw picks a part by its area; the top and bottom count whole and refuse the points
  // that fall in a bore, which leaves every part its share of the surface.
  const double faces = 2.0, rim = 4 * kThickness, walls = 5 * 2 * k_pi * bore * kThickness;
  Rng rng(seed);
  Points p;
  while (p.size() < 3 * n) {
    const double part = rng.uniform(0, faces + rim + walls);
    if (part < faces) {
      const double x = rng.uniform(), y = rng.uniform();
      bool in_bore = false;
      for (const auto &c : centres) in_bore |= std::hypot(x - c[0], y - c[1]) < bore;
      if (!in_bore) p.insert(p.end(), {x, y, part < faces / 2 ? 0.0 : kThickness});
    } else if (part < faces + rim) {
      const double t = rng.uniform(), z = rng.uniform(0, kThickness);
      const std::uint64_t side = rng.below(4);  // y = 0, y = 1, x = 0, x = 1
      const double at = side % 2 == 0 ? 0.0 : 1.0;
      if (side < 2)
        p.insert(p.end(), {t, at, z});
      else
        p.insert(p.end(), {at, t, z});
    } else {
      const auto &c = centres[rng.below(5)];
      const double a = rng.uniform(0, 2 * k_pi), z = rng.uniform(0, kThickness);
      p.insert(p.end(), {c[0] + bore * std::cos(a), c[1] + bore * std::sin(a), z});
    }
  }
  return p;
}

Points dumbbell_samples(double neck, std::size_t n, std::uint64_t seed) {
  constexpr double kBall = 0.6, kCentre = 1.0, kBlend = 0.05;
  // The radius of the surface of revolution at x: the larger of ball and neck, blended.
  auto radius = [&](double x) {
    const double d = std::fabs(x) - kCentre;
    const double ball = std::sqrt(std::max(0.0, kBall * kBall - d * d));
    if (std::fabs(x) > kCentre) return ball;
    const double h = std::clamp(0.5 + 0.5 * (ball - neck) / kBlend, 0.0, 1.0);
    return neck + (ball - neck) * h + kBlend * h * (1 - h);
  };
  // Rings along x, closer together towards the poles, where the profile turns steeply.
  const std::uint32_t rings = 600, m = 96;
  std::vector<double> v;
  const double end = kCentre + kBall;
  for (std::uint32_t j = 1; j < rings; ++j) {
    const double x = -end * std::cos(k_pi * double(j) / double(rings)), r = radius(x);
    for (std::uint32_t i = 0; i < m; ++i) {
      const double a = 2 * k_pi * double(i) / double(m);
      v.insert(v.end(), {x, r * std::cos(a), r * std::sin(a)});
    }
  }
  const std::uint32_t first_pole = std::uint32_t(v.size() / 3), second_pole = first_pole + 1;
  v.insert(v.end(), {-end, 0.0, 0.0, end, 0.0, 0.0});
  std::vector<std::uint32_t> t;
  auto at = [&](std::uint32_t j, std::uint32_t i) { return (j - 1) * m + i % m; };
  for (std::uint32_t i = 0; i < m; ++i) {
    t.insert(t.end(), {first_pole, at(1, i + 1), at(1, i)});
    t.insert(t.end(), {second_pole, at(rings - 1, i), at(rings - 1, i + 1)});
    for (std::uint32_t j = 1; j + 1 < rings; ++j)
      t.insert(t.end(), {at(j, i), at(j, i + 1), at(j + 1, i + 1), at(j, i), at(j + 1, i + 1),
                         at(j + 1, i)});
  }
  return sample_mesh(v, t, n, seed);
}

Points parallel_sheets(double side, double spacing, double gap, std::uint64_t seed) {
  Rng rng(seed);
  Points p = blue_noise_square(side, spacing, rng);
  Points upper = blue_noise_square(side, spacing, rng);
  for (std::size_t i = 2; i < upper.size(); i += 3) upper[i] = gap;
  p.insert(p.end(), upper.begin(), upper.end());
  return p;
}

void add_noise(Points &p, double fraction_of_diagonal, std::uint64_t seed) {
  Rng rng(seed);
  const double sigma = fraction_of_diagonal * bbox_diagonal(p);
  for (double &v : p) v += sigma * rng.normal();
}

void add_noise_beyond(Points &p, double x, double sigma, std::uint64_t seed) {
  Rng rng(seed);
  for (std::size_t i = 0; i < p.size(); i += 3)
    if (p[i] > x)
      for (int k = 0; k < 3; ++k) p[i + k] += sigma * rng.normal();
}

double median_nearest_distance(const Points &p) {
  const std::size_t n = p.size() / 3;
  if (n < 2) return 0;
  // Points in order of x; each looks at its neighbours in that order until the gap in x alone
  // exceeds the nearest distance found (with room for rounding, so the result is the exact
  // minimum over all other points).
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return p[3 * a] < p[3 * b]; });
  std::vector<double> nearest(n, HUGE_VAL);
  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t i = order[r];
    auto look = [&](std::size_t j) {
      const double dx = p[3 * i] - p[3 * j], dy = p[3 * i + 1] - p[3 * j + 1],
                   dz = p[3 * i + 2] - p[3 * j + 2];
      if (std::fabs(dx) > nearest[i] * (1 + 1e-12)) return false;
      nearest[i] = std::min(nearest[i], std::sqrt(dx * dx + dy * dy + dz * dz));
      return true;
    };
    for (std::size_t s = r + 1; s < n && look(order[s]); ++s) {
    }
    for (std::size_t s = r; s > 0 && look(order[s - 1]); --s) {
    }
  }
  std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(n / 2), nearest.end());
  return nearest[n / 2];
}

double angle_at(const Points &p, std::uint32_t c, std::uint32_t a, std::uint32_t b) {
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = p[3 * a + k] - p[3 * c + k];
    v[k] = p[3 * b + k] - p[3 * c + k];
  }
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
               z = u[0] * v[1] - u[1] * v[0];
  return std::atan2(std::sqrt(x * x + y * y + z * z), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
}

std::size_t faces_below(const Points &p, const std::vector<std::uint32_t> &triangles,
                        double degrees) {
  const double limit = degrees * 3.14159265358979323846 / 180.0;
  std::size_t below = 0;
  for (std::size_t f = 0; f + 2 < triangles.size(); f += 3) {
    const std::uint32_t a = triangles[f], b = triangles[f + 1], c = triangles[f + 2];
    if (std::min({angle_at(p, a, b, c), angle_at(p, b, c, a), angle_at(p, c, a, b)}) < limit)
      ++below;
  }
  return below;
}

Points density_gradient(const Points &p, double ratio, std::uint64_t seed) {
  Rng rng(seed);
  double lo = p[0], hi = p[0];
  for (std::size_t i = 0; i < p.size(); i += 3) {
    lo = std::min(lo, p[i]);
    hi = std::max(hi, p[i]);
  }
  Points kept;
  for (std::size_t i = 0; i + 2 < p.size(); i += 3) {
    const double t = (p[i] - lo) / (hi - lo);
    if (rng.uniform() * ratio < 1 + (ratio - 1) * t * t) push(kept, p[i], p[i + 1], p[i + 2]);
  }
  return kept;
}

void shuffle(Points &p, std::uint64_t seed) {
  Rng rng(seed);
  for (std::size_t i = p.size() / 3; i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(rng.below(i));
    for (int a = 0; a < 3; ++a) std::swap(p[3 * (i - 1) + a], p[3 * j + a]);
  }
}

double bbox_diagonal(const Points &p) {
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < p.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], p[i]);
    hi[i % 3] = std::max(hi[i % 3], p[i]);
  }
  if (p.empty()) return 0;
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

Points sample_mesh(const std::vector<double> &v, const std::vector<std::uint32_t> &t, std::size_t n,
                   std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> cumulative;
  double total = 0;
  for (std::size_t f = 0; f + 2 < t.size(); f += 3) {
    const double *a = &v[3 * t[f]], *b = &v[3 * t[f + 1]], *c = &v[3 * t[f + 2]];
    const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double g[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double x = e[1] * g[2] - e[2] * g[1], y = e[2] * g[0] - e[0] * g[2], z = e[0] * g[1] - e[1] * g[0];
    total += 0.5 * std::sqrt(x * x + y * y + z * z);
    cumulative.push_back(total);
  }
  Points p;
  if (cumulative.empty()) return p;
  for (std::size_t i = 0; i < n; ++i) {
    const double pick = rng.uniform() * total;
    const std::size_t f = std::min<std::size_t>(
        cumulative.size() - 1, std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
    // Uniform on the triangle: the square root keeps the density flat.
    const double s = std::sqrt(rng.uniform()), w = rng.uniform();
    const double ka = 1 - s, kb = s * (1 - w), kc = s * w;
    const double *a = &v[3 * t[3 * f]], *b = &v[3 * t[3 * f + 1]], *c = &v[3 * t[3 * f + 2]];
    push(p, ka * a[0] + kb * b[0] + kc * c[0], ka * a[1] + kb * b[1] + kc * c[1], ka * a[2] + kb * b[2] + kc * c[2]);
  }
  return p;
}

Points contour_stack(const std::vector<double> &v, const std::vector<std::uint32_t> &t,
                     const double axis[3], std::size_t slices, double per_gap, std::uint64_t seed) {
  Rng rng(seed);
  const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  auto height = [&](std::uint32_t i) {
    return (v[3 * i] * axis[0] + v[3 * i + 1] * axis[1] + v[3 * i + 2] * axis[2]) / norm;
  };
  double lo = height(0), hi = lo;
  for (std::uint32_t i = 0; 3 * i < v.size(); ++i) {
    lo = std::min(lo, height(i));
    hi = std::max(hi, height(i));
  }
  const double gap = (hi - lo) / double(slices), step = gap / per_gap;
  Points p;
  for (std::size_t s = 0; s < slices; ++s) {
    const double level = lo + (double(s) + 0.5) * gap;
    for (std::size_t f = 0; f + 2 < t.size(); f += 3) {
      // The cut through this triangle: where its edges cross the plane.
      double ends[2][3];
      int found = 0;
      for (int e = 0; e < 3 && found < 2; ++e) {
        const std::uint32_t a = t[f + e], b = t[f + (e + 1) % 3];
        const double ha = height(a) - level, hb = height(b) - level;
        if ((ha < 0) == (hb < 0)) continue;
        const double w = ha / (ha - hb);
        for (int k = 0; k < 3; ++k) ends[found][k] = v[3 * a + k] + w * (v[3 * b + k] - v[3 * a + k]);
        ++found;
      }
      if (found < 2) continue;
      const double dx = ends[1][0] - ends[0][0], dy = ends[1][1] - ends[0][1], dz = ends[1][2] - ends[0][2];
      // On average length / step points, at random along the cut.
      const double expected = std::sqrt(dx * dx + dy * dy + dz * dz) / step;
      std::size_t count = std::size_t(expected);
      if (rng.uniform() < expected - double(count)) ++count;
      for (std::size_t c = 0; c < count; ++c) {
        const double w = rng.uniform();
        push(p, ends[0][0] + w * dx, ends[0][1] + w * dy, ends[0][2] + w * dz);
      }
    }
  }
  return p;
}

Points torus_contour_stack(double per_gap) {
  const double axis[3] = {1, 0.3, 0.2};
  return contour_stack(torus_grid(120, 48, 1.0, 0.4), torus_grid_triangles(120, 48), axis, 30,
                       per_gap, 1);
}

Points marching_cubes_vertices(double (*f)(double x, double y, double z), const int n[3]) {
  auto coordinate = [&](int axis, int i) { return -1.0 + 2.0 * double(i) / double(n[axis] - 1); };
  Points p;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const double at[3] = {coordinate(0, i), coordinate(1, j), coordinate(2, k)};
        const double here = f(at[0], at[1], at[2]);
        const int cell[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis) {  // the edge from here along `axis`
          if (cell[axis] + 1 >= n[axis]) continue;
          double next_at[3] = {at[0], at[1], at[2]};
          next_at[axis] = coordinate(axis, cell[axis] + 1);
          const double next = f(next_at[0], next_at[1], next_at[2]);
          if ((here < 0) == (next < 0)) continue;
          const double t = here / (here - next);
          for (int c = 0; c < 3; ++c) p.push_back(at[c] + (next_at[c] - at[c]) * t);
        }
      }
  return p;
}

namespace {

// Circles round the axis (1, 0.3, 0.2) at the middles of `slices` even bands of heights -1 to 1,
// of radius radius(height), each sampled evenly from a random start, `per_gap` points per band.
template <class Radius>
Points circle_stack(std::size_t slices, double per_gap, std::uint64_t seed, Radius radius) {
  Rng rng(seed);
  const double pi = 3.14159265358979323846;
  // The axis and two unit directions across it.
  const double len = std::sqrt(1 + 0.09 + 0.04);
  const double a[3] = {1 / len, 0.3 / len, 0.2 / len};
  const double ulen = std::sqrt(a[1] * a[1] + a[0] * a[0]);
  const double u[3] = {a[1] / ulen, -a[0] / ulen, 0};  // a x (0, 0, 1), normalised
  const double v[3] = {a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2],
                       a[0] * u[1] - a[1] * u[0]};  // a x u
  const double gap = 2.0 / double(slices), step = gap / per_gap;
  Points p;
  for (std::size_t s = 0; s < slices; ++s) {
    const double h = -1 + (double(s) + 0.5) * gap, r = radius(h);
    // Evenly along the circle from a random start, as a segmentation's contours come.
    const std::size_t count = std::max<std::size_t>(3, std::size_t(std::lround(2 * pi * r / step)));
    const double start = rng.uniform();
    for (std::size_t c = 0; c < count; ++c) {
      const double t = 2 * pi * (start + double(c)) / double(count);
      const double cu = r * std::cos(t), sv = r * std::sin(t);
      push(p, h * a[0] + cu * u[0] + sv * v[0], h * a[1] + cu * u[1] + sv * v[1],
           h * a[2] + cu * u[2] + sv * v[2]);
    }
  }
  return p;
}

}  // namespace

Points sphere_contour_stack(std::size_t slices, double per_gap, std::uint64_t seed) {
  return circle_stack(slices, per_gap, seed, [](double h) { return std::sqrt(1 - h * h); });
}

Points cylinder_contour_stack(std::size_t slices, double per_gap, std::uint64_t seed) {
  return circle_stack(slices, per_gap, seed, [](double) { return 1.0; });
}

Points scanned_box(double hx, double hy, double hz, int views, int resolution, double elevation) {
  const double half[3] = {hx, hy, hz};
  const double reach = 4 * std::sqrt(hx * hx + hy * hy + hz * hz);
  // The rays of a view fan out over a little more than the box's bounding sphere (whose
  // radius is a quarter of the distance to it).
  const double fan = 0.3;
  Points p;
  for (int v = 0; v < views; ++v) {
    const double azimuth = 2 * k_pi * v / views + 0.3;
    const double el = v % 2 ? elevation : -elevation;
    const double back[3] = {std::cos(el) * std::cos(azimuth), std::sin(el),
                            std::cos(el) * std::sin(azimuth)};
    const double eye[3] = {reach * back[0], reach * back[1], reach * back[2]};
    // right = forward x up, up' = right x forward, with forward = -back and up = +y.
    double right[3] = {back[2], 0, -back[0]};
    const double rn = std::sqrt(right[0] * right[0] + right[2] * right[2]);
    right[0] /= rn;
    right[2] /= rn;
    const double up[3] = {right[2] * back[1], right[0] * back[2] - right[2] * back[0],
                          -right[0] * back[1]};
    for (int i = 0; i < resolution; ++i)
      for (int j = 0; j < resolution; ++j) {
        const double x = (2 * (i + 0.5) / resolution - 1) * fan;
        const double y = (2 * (j + 0.5) / resolution - 1) * fan;
        double d[3];
        for (int a = 0; a < 3; ++a) d[a] = -back[a] + x * right[a] + y * up[a];
        // Slab test: the ray enters the box at the largest of the per-axis entry distances.
        double enter = -HUGE_VAL, leave = HUGE_VAL;
        for (int a = 0; a < 3; ++a) {
          if (d[a] == 0) {
            if (std::fabs(eye[a]) > half[a]) enter = HUGE_VAL;
            continue;
          }
          const double t1 = (-half[a] - eye[a]) / d[a], t2 = (half[a] - eye[a]) / d[a];
          enter = std::max(enter, std::min(t1, t2));
          leave = std::min(leave, std::max(t1, t2));
        }
        if (!(enter <= leave) || enter <= 0) continue;
        push(p, eye[0] + enter * d[0], eye[1] + enter * d[1], eye[2] + enter * d[2]);
      }
  }
  return p;
}

Points thin_points(const Points &candidates, double min_distance) {
  // Hash grid with cells of min_distance: a conflicting point lies in one of the 27 cells around.
  auto cell = [&](double x) { return static_cast<std::int64_t>(std::floor(x / min_distance)); };
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (std::uint64_t(x) * 73856093u) ^ (std::uint64_t(y) * 19349663u) ^ (std::uint64_t(z) * 83492791u);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  Points kept;
  const double d2 = min_distance * min_distance;
  for (std::size_t i = 0; i + 2 < candidates.size(); i += 3) {
    const double *c = &candidates[i];
    const std::int64_t cx = cell(c[0]), cy = cell(c[1]), cz = cell(c[2]);
    bool free = true;
    for (std::int64_t dx = -1; dx <= 1 && free; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && free; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && free; ++dz) {
          const auto it = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (std::uint32_t k : it->second) {
            const double *q = &kept[3 * std::size_t(k)];
            const double ex = q[0] - c[0], ey = q[1] - c[1], ez = q[2] - c[2];
            if (ex * ex + ey * ey + ez * ez < d2) {
              free = false;
              break;
            }
          }
        }
    if (!free) continue;
    grid[key(cx, cy, cz)].push_back(std::uint32_t(kept.size() / 3));
    push(kept, c[0], c[1], c[2]);
  }
  return kept;
}

}  // namespace moa::test
