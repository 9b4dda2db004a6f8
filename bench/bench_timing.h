/*
 * bench_timing.h - the wall clock and the median of repeated runs, shared by the benchmarks
 * (header-only, C99).
 */
#ifndef MC_BENCH_TIMING_H
#define MC_BENCH_TIMING_H

#include <stdlib.h>
#include <time.h>

static inline double bench_wall(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static inline int bench_compare_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The median of v[0..n) (sorts v). */
static inline double bench_median(double *v, int n) {
  qsort(v, n, sizeof *v, bench_compare_double);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#endif /* MC_BENCH_TIMING_H */
