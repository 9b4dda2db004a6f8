/*
 * error_estimate_cost.c - what MC_INFO_ERROR_ESTIMATE costs beside the solve (docs/benchmarks.md,
 * "Error estimate"): the Hertz scene (examples/scenes/hertz_scene.h, h2 = 1.37 h1, MC_METHOD_MORTAR)
 * solved with MC_OPTION_ERROR_ESTIMATE 1 and 0 alternately, --repeat times each; printed: the
 * medians of MC_INFO_TIME_TOTAL with and without, and of the estimate's own phase time (from the
 * log message "error estimate: ..., T s"). Every solve has MC_OPTION_EAGER_RESULTS = 1, so that
 * the estimate (and the stresses) are computed inside mc_solve as before results on demand, and
 * MC_INFO_TIME_TOTAL holds them (bench/resolve_cost.c measures the default, on demand).
 *
 * usage: error_estimate_cost [--repeat n] KIND:h1[,h1...] ...   (KIND: P1, Q1, T6, Q8, Q9)
 */
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void phase(void *user, mc_log_level level, const char *message) {
  (void)level;
  const char *at = strstr(message, "error estimate: ");
  if (!at) return;
  const char *comma = strrchr(message, ',');
  if (comma) *(double *)user = atof(comma + 1);
}

static int compare(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int n) {
  qsort(v, (size_t)n, sizeof *v, compare);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* One solve; returns MC_INFO_TIME_TOTAL, sets *estimate_time and *dofs. */
static double solve(const hertz_scene *s, int on, double *estimate_time, long *dofs, double *estimate) {
  mc_model *m = NULL;
  mc_create(&m);
  *estimate_time = 0;
  mc_set_log_callback(m, phase, estimate_time);
  for (int b = 0; b < 2; ++b) {
    mc_set_mesh(m, b + 1, s->body[b].n_nodes, s->body[b].xy, s->body[b].n_cells, s->body[b].nodes_per_cell, s->body[b].cells);
    mc_set_material(m, b + 1, 1, 0.3);
  }
  mc_fix(m, 1, s->n_axis_nodes, s->axis_nodes, MC_X, NULL);
  mc_fix(m, 2, s->n_bottom_nodes, s->bottom_nodes, MC_XY, NULL);
  double *t = malloc(sizeof(double) * 2 * (size_t)s->n_top_edges);
  for (int e = 0; e < s->n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -0.005; /* 0.01 over the top's length 2 */
  mc_add_traction(m, 1, s->n_top_edges, s->top_edges, t);
  free(t);
  mc_set_contact(m, 1, s->n_contact_edges[0], s->contact_edges[0]);
  mc_set_contact(m, 2, s->n_contact_edges[1], s->contact_edges[1]);
  mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, on);
  mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 1);
  double total = -1;
  if (mc_solve(m) == MC_OK) {
    int64_t v;
    mc_get_info_real(m, MC_INFO_TIME_TOTAL, &total);
    mc_get_info_int(m, MC_INFO_DOFS, &v), *dofs = (long)v;
    mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, estimate);
  } else {
    fprintf(stderr, "solve: %s\n", mc_errmsg(m));
  }
  mc_destroy(m);
  return total;
}

int main(int argc, char **argv) {
  int repeat = 3;
  printf("| cells | h1 | DOFs | estimate | solve with the estimate, s | without, s | the estimate's phase, s | "
         "its share of the solve |\n|---|---|---|---|---|---|---|---|\n");
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = atoi(argv[++i]);
      if (repeat < 1 || repeat > 15) repeat = 3;
      continue;
    }
    const char *colon = strchr(argv[i], ':');
    if (!colon) continue;
    const int npc = !strncmp(argv[i], "P1", 2) ? 3 : !strncmp(argv[i], "Q1", 2) ? 4 : !strncmp(argv[i], "T6", 2) ? 6
                    : !strncmp(argv[i], "Q8", 2) ? 8 : 9;
    for (const char *h = colon + 1; h && *h; h = strchr(h, ',') ? strchr(h, ',') + 1 : NULL) {
      const double h1 = atof(h);
      hertz_scene s;
      if (hertz_scene_build_cells(&s, h1, 1.37 * h1, npc)) continue;
      double with[15], without[15], phase_time[15], estimate = 0;
      long dofs = 0;
      for (int r = 0; r < repeat; ++r) { /* alternating, so that both see the machine alike */
        double t_phase, unused;
        with[r] = solve(&s, 1, &phase_time[r], &dofs, &estimate);
        without[r] = solve(&s, 0, &t_phase, &dofs, &unused);
      }
      const double tw = median(with, repeat), to = median(without, repeat), tp = median(phase_time, repeat);
      printf("| %s | %g | %ld | %.4f | %.3f | %.3f | %.3f | %.1f %% |\n", argv[i][0] == 'P' ? "P1" : argv[i][0] == 'T' ? "T6"
             : npc == 4 ? "Q1" : npc == 8 ? "Q8" : "Q9", h1, dofs, estimate, tw, to, tp, 100 * tp / tw);
      fflush(stdout);
      hertz_scene_free(&s);
    }
  }
  return 0;
}
