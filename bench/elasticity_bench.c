/*
 * elasticity_bench.c - the plain elasticity solve, the baseline every contact solve is timed
 * against (docs/benchmarks.md).
 *
 * A block [0,1]^2 clamped on its left side, P1 on N x N squares (2 triangles each), plane
 * strain, a uniform traction on its right side. For each size (one child process each, so
 * that the peak RSS is that size's own) prints: DOFs, times of assembly, analysis,
 * factorization and solve, nnz(L), peak RSS, and the ratio assembly / factorization.
 *
 * usage: elasticity_bench [N ...]   (default: 70 100 158 224 316 500 707 1000)
 */
#include "mortarcontact.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static long peak_rss_kib(void) {
  FILE *f = fopen("/proc/self/status", "r");
  char line[256];
  long kib = -1;
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, "VmHWM:", 6) == 0) kib = atol(line + 6);
  if (f) fclose(f);
  return kib;
}

static int run(int n) {
  const int nodes = (n + 1) * (n + 1), cells = 2 * n * n;
  double *xy = malloc(sizeof(double) * 2 * nodes);
  mc_int *tri = malloc(sizeof(mc_int) * 3 * cells), *left = malloc(sizeof(mc_int) * (n + 1));
  mc_int *right = malloc(sizeof(mc_int) * 2 * n);
  double *traction = malloc(sizeof(double) * 2 * n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) xy[2 * (j * (n + 1) + i)] = (double)i / n, xy[2 * (j * (n + 1) + i) + 1] = (double)j / n;
  for (int j = 0, c = 0; j < n; ++j)
    for (int i = 0; i < n; ++i, c += 2) {
      mc_int a = j * (n + 1) + i, b = a + 1, d = a + n + 1, e = d + 1;
      mc_int t[6] = {a, b, e, a, e, d};
      memcpy(tri + 3 * c, t, sizeof t);
    }
  for (int j = 0; j <= n; ++j) left[j] = j * (n + 1);
  for (int j = 0; j < n; ++j) right[2 * j] = j * (n + 1) + n, right[2 * j + 1] = (j + 1) * (n + 1) + n;
  for (int j = 0; j < n; ++j) traction[2 * j] = 0.1, traction[2 * j + 1] = -0.05;
  mc_model *m;
  if (mc_create(&m) || mc_set_mesh(m, 1, nodes, xy, cells, 3, tri) || mc_set_material(m, 1, 1.0, 0.3) ||
      mc_fix(m, 1, n + 1, left, MC_XY, NULL) || mc_add_traction(m, 1, n, right, traction) || mc_solve(m)) {
    fprintf(stderr, "N = %d: %s\n", n, mc_errmsg(m));
    return 1;
  }
  int64_t dofs, nnz;
  double ta, tn, tf, ts, tt;
  mc_get_info_int(m, MC_INFO_DOFS, &dofs);
  mc_get_info_int(m, MC_INFO_FACTOR_NNZ, &nnz);
  mc_get_info_real(m, MC_INFO_TIME_ASSEMBLY, &ta);
  mc_get_info_real(m, MC_INFO_TIME_ANALYSIS, &tn);
  mc_get_info_real(m, MC_INFO_TIME_FACTORIZATION, &tf);
  mc_get_info_real(m, MC_INFO_TIME_SOLVE, &ts);
  mc_get_info_real(m, MC_INFO_TIME_TOTAL, &tt);
  double factor_mib = nnz * 12.0 / 1048576.0; /* value + row index per entry */
  printf("| %5d | %9lld | %8.3f | %8.3f | %8.3f | %7.3f | %8.3f | %11lld | %8.0f | %9.0f | %5.2f |\n", n, (long long)dofs,
         ta, tn, tf, ts, tt, (long long)nnz, factor_mib, peak_rss_kib() / 1024.0, ta / tf);
  fflush(stdout);
  mc_destroy(m);
  free(xy), free(tri), free(left), free(right), free(traction);
  return 0;
}

int main(int argc, char **argv) {
  int defaults[] = {70, 100, 158, 224, 316, 500, 707, 1000};
  int count = argc > 1 ? argc - 1 : (int)(sizeof defaults / sizeof defaults[0]);
  printf("| N | DOFs | assembly s | analysis s | factor s | solve s | total s | nnz(L) | L MiB | peak RSS MiB | assembly/factor |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  fflush(stdout);
  for (int k = 0; k < count; ++k) {
    int n = argc > 1 ? atoi(argv[k + 1]) : defaults[k];
    pid_t child = fork();
    if (child == 0) _exit(run(n));
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
  }
  return 0;
}
