/*
 * contact_half_width.h - the contact half-width estimator of the Hertz benchmarks
 * (bench/hertz_sweep.c, bench/hertz_quadratic.c; bench/getfem_hertz.py re-implements it, so that
 * both codes are measured alike): per side, p^2 extrapolated linearly in x^2 to zero through the
 * last two loaded nodes (above 1e-10 of the largest pressure), clamped between the last loaded
 * node and the next; the mean of both sides. NAN when a side has fewer than two loaded nodes off
 * the centre. Header-only (static): C99 and libm.
 */
#ifndef MC_BENCH_CONTACT_HALF_WIDTH_H
#define MC_BENCH_CONTACT_HALF_WIDTH_H

#include <math.h>
#include <stdlib.h>

static double contact_half_width(int n, const double *x_in, const double *p_in) {
  int *order = malloc(sizeof(int) * n);
  double *x = malloc(sizeof(double) * n), *p = malloc(sizeof(double) * n), pmax = 0;
  for (int i = 0; i < n; ++i) order[i] = i;
  for (int i = 1; i < n; ++i) /* insertion sort by x: the arc nodes come almost sorted */
    for (int k = i; k > 0 && x_in[order[k - 1]] > x_in[order[k]]; --k) {
      int t = order[k];
      order[k] = order[k - 1], order[k - 1] = t;
    }
  for (int i = 0; i < n; ++i) x[i] = x_in[order[i]], p[i] = p_in[order[i]], pmax = fmax(pmax, p[i]);
  int c = 0;
  for (int i = 1; i < n; ++i)
    if (fabs(x[i]) < fabs(x[c])) c = i;
  double sum = 0;
  for (int step = 1; step >= -1; step -= 2) {
    int k = c;
    while (k + step >= 0 && k + step < n && p[k + step] > 1e-10 * pmax) k += step;
    if (k == c || k + step < 0 || k + step >= n) {
      sum = NAN;
      break;
    }
    double x0 = fabs(x[k - step]), x1 = fabs(x[k]), xn = fabs(x[k + step]);
    double q0 = p[k - step] * p[k - step], q1 = p[k] * p[k];
    double z2 = q0 > q1 ? x1 * x1 + q1 * (x1 * x1 - x0 * x0) / (q0 - q1) : xn * xn;
    sum += fmin(fmax(sqrt(fmax(z2, 0.0)), x1), xn);
  }
  free(order), free(x), free(p);
  return 0.5 * sum;
}

#endif /* MC_BENCH_CONTACT_HALF_WIDTH_H */
