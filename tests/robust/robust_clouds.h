/* Clouds the C robustness tests share. */
#ifndef MOA_TESTS_ROBUST_CLOUDS_H
#define MOA_TESTS_ROBUST_CLOUDS_H

#include <math.h>
#include <stddef.h>

/* n points of a unit sphere centred on the origin, on a Fibonacci lattice (poles on the y axis,
 * the golden angle between consecutive points): about sqrt(4 pi / n) apart. */
static inline void fibonacci_sphere(double *xyz, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * ((double)i + 0.5) / (double)n, r = sqrt(1.0 - y * y);
    const double t = 2.39996322972865332 * (double)i;
    xyz[3 * i] = r * cos(t);
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = r * sin(t);
  }
}

#endif
