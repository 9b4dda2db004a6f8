/*
 * chain.c - the cost of a chain of N bodies (issue 32; docs/benchmarks.md, "Assemblies: a chain
 * of N bodies"). The goal: a chain of N bodies costs about N / 2 times the two-body solve, on
 * both interface paths.
 *
 * The scene: N unit squares stacked, body 1 on top, body N at the bottom, each a structured P1
 * mesh of a fixed size (--cells n: odd-numbered bodies n x n squares, even-numbered ones
 * round(0.955 n) x round(1.05 n), so that every interface is non-matching and every body has
 * about 2 (n + 1)^2 unknowns: n = 158 gives 5.06e4 per body, 1.0e5 for N = 2). Pairs: body k's
 * bottom (non-mortar) on body k + 1's top (mortar). A uniform pressure p = 0.01 on body 1's
 * top; body N on rollers at its bottom; every body's bottom-left corner held in x (frictionless
 * contact holds no horizontal motion); bodies 1 .. N - 1 held vertically by contact alone. Every
 * body is then in the uniform stress sigma_yy = -p and every contact pressure is p (a patch
 * test: the program checks it to 1e-8 and says so in the "pressure error" column).
 * The reference: the same N meshes without contact, each on rollers at its bottom, held at its
 * corner and loaded by p on its top (N independent elasticity problems; "plain").
 *
 * Every solve is a fresh model (mc_create, the scene, mc_solve timed by the wall clock, the
 * results read, mc_destroy): the first solve, analysis and factorization included. --repeat
 * rounds (default 3), each solving every N on every path once; the medians printed, the time infos too (MC_INFO_TIME_*),
 * and from the log the contact parts (contact geometry, interface operator, active-set solve).
 * MC_OPTION_THREADS is 1 (serial) unless --threads says otherwise, so that the ratios measure the
 * work, not how it is spread on a shared machine.
 *
 * usage: chain [--cells n] [--repeat r] [--threads t] [--solvers plain,condensed,sparse,auto] [N ...]
 *   N ... default 2 4 8 16
 *   CHAIN_LOG=1: every contact solve's log messages on stderr
 * Exit status 1 if a contact pressure is off p by more than 1e-8 (relative).
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "mortarcontact.h"
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPEAT 15
#define MAX_N 64

enum { PLAIN = 0, CONDENSED = 1, SPARSE = 2, AUTO = 3, N_KINDS = 4 };
static const char *const kind_name[N_KINDS] = {"plain", "condensed", "sparse", "auto"};
static const double kPressure = 0.01;

typedef struct parts {
  double geometry, interface, active_set;
  long cg_steps; /* the sparse path's ("..., 9 conjugate-gradient steps, ...") */
} parts;

static double trailing_seconds(const char *message) {
  const char *comma = strrchr(message, ',');
  return comma ? atof(comma + 1) : 0;
}

static void note_parts(void *user, mc_log_level level, const char *message) {
  (void)level;
  parts *p = user;
  if (getenv("CHAIN_LOG")) fprintf(stderr, "  log: %s\n", message); /* bench/interface_choice.py reads the choice */
  if (strncmp(message, "contact geometry", 16) == 0) p->geometry += trailing_seconds(message);
  if (strncmp(message, "interface operator", 18) == 0) p->interface += trailing_seconds(message);
  if (strncmp(message, "active-set solve", 16) == 0) {
    p->active_set += trailing_seconds(message);
    const char *cg = strstr(message, " conjugate-gradient steps");
    if (cg) {
      while (cg > message && cg[-1] >= '0' && cg[-1] <= '9') --cg;
      p->cg_steps += atol(cg);
    }
  }
}

/* One solve's measurements. */
typedef struct sample {
  double wall, cpu, assembly, analysis, factorization, solve, contact, geometry, interface, active_set;
  double pressure_error;
  long dofs, rows, iterations, factorizations, ran, nnz, cg_steps;
} sample;

#define CALL(call)                                                             \
  do {                                                                         \
    if ((call) != MC_OK) {                                                     \
      fprintf(stderr, "chain: %s failed: %s\n", #call, mc_errmsg(m));          \
      exit(1);                                                                 \
    }                                                                          \
  } while (0)

/* The process's CPU time: on a shared machine less disturbed by the others' load than the wall
   clock (the solves are serial; BLAS threads, if any, add theirs). */
static double cpu_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void press_top(mc_model *m, int body, const sc_mesh *mesh) {
  CALL(sc_traction_side(m, body, mesh, SC_TOP, 0, -kPressure, 0));
}

static sample solve_chain(const sc_mesh *mesh, int n, int kind, int threads) {
  sample s;
  memset(&s, 0, sizeof s);
  parts log = {0, 0, 0, 0};
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(1);
  CALL(mc_set_body_count(m, n));
  if (threads >= 0) CALL(mc_set_option_int(m, MC_OPTION_THREADS, threads));
  for (int k = 0; k < n; ++k) {
    CALL(sc_set_mesh(m, k + 1, &mesh[k], 0));
    CALL(mc_set_material(m, k + 1, 1.0, 0.3));
    const mc_int corner = mesh[k].side_nodes[SC_BOTTOM][0];
    CALL(mc_fix(m, k + 1, 1, &corner, MC_X, NULL));
    if (kind == PLAIN || k == n - 1) CALL(sc_fix_side(m, k + 1, &mesh[k], SC_BOTTOM, MC_Y, 0));
    if (kind == PLAIN || k == 0) press_top(m, k + 1, &mesh[k]);
  }
  if (kind != PLAIN) {
    for (int k = 0; k + 1 < n; ++k) {
      int pair;
      CALL(mc_add_contact_pair(m, k + 1, k + 2, &pair));
      CALL(mc_set_pair_surface(m, pair, k + 1, mesh[k].n_side_edges[SC_BOTTOM], mesh[k].side_edges[SC_BOTTOM]));
      CALL(mc_set_pair_surface(m, pair, k + 2, mesh[k + 1].n_side_edges[SC_TOP], mesh[k + 1].side_edges[SC_TOP]));
    }
    if (kind != AUTO) CALL(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, kind == CONDENSED ? MC_INTERFACE_CONDENSED : MC_INTERFACE_SPARSE));
    CALL(mc_set_log_callback(m, note_parts, &log));
  }
  const double t0 = bench_wall(), c0 = cpu_seconds();
  CALL(mc_solve(m));
  s.wall = bench_wall() - t0, s.cpu = cpu_seconds() - c0;
  int64_t v;
  CALL(mc_get_info_int(m, MC_INFO_DOFS, &v));
  s.dofs = (long)v;
  CALL(mc_get_info_int(m, MC_INFO_CONTACT_NODES, &v));
  s.rows = (long)v;
  CALL(mc_get_info_int(m, MC_INFO_ITERATIONS, &v));
  s.iterations = (long)v;
  CALL(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  s.factorizations = (long)v;
  CALL(mc_get_info_int(m, MC_INFO_FACTOR_NNZ, &v));
  s.nnz = (long)v;
  CALL(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &v));
  s.ran = (long)v;
  CALL(mc_get_info_real(m, MC_INFO_TIME_ASSEMBLY, &s.assembly));
  CALL(mc_get_info_real(m, MC_INFO_TIME_ANALYSIS, &s.analysis));
  CALL(mc_get_info_real(m, MC_INFO_TIME_FACTORIZATION, &s.factorization));
  CALL(mc_get_info_real(m, MC_INFO_TIME_SOLVE, &s.solve));
  CALL(mc_get_info_real(m, MC_INFO_TIME_CONTACT, &s.contact));
  s.geometry = log.geometry, s.interface = log.interface, s.active_set = log.active_set, s.cg_steps = log.cg_steps;
  /* the patch test: every pair's pressures are p */
  for (int pair = 1; kind != PLAIN && pair < n; ++pair) {
    mc_int q;
    CALL(mc_get_pair_contact_count(m, pair, &q));
    double *p = malloc(sizeof(double) * (size_t)q);
    CALL(mc_get_pair_contact(m, pair, MC_CONTACT_PRESSURE, p));
    for (mc_int j = 0; j < q; ++j) s.pressure_error = fmax(s.pressure_error, fabs(p[j] / kPressure - 1));
    free(p);
  }
  mc_destroy(m);
  return s;
}

/* Medians over the repeats, field by field. */
static sample median_of(sample *runs, int r) {
  sample out = runs[0];
  double v[MAX_REPEAT];
#define MEDIAN(field)                                  \
  do {                                                 \
    for (int k = 0; k < r; ++k) v[k] = runs[k].field;  \
    out.field = bench_median(v, r);                    \
  } while (0)
  MEDIAN(wall);
  MEDIAN(cpu);
  MEDIAN(assembly);
  MEDIAN(analysis);
  MEDIAN(factorization);
  MEDIAN(solve);
  MEDIAN(contact);
  MEDIAN(geometry);
  MEDIAN(interface);
  MEDIAN(active_set);
#undef MEDIAN
  for (int k = 0; k < r; ++k) out.pressure_error = fmax(out.pressure_error, runs[k].pressure_error);
  return out;
}

int main(int argc, char **argv) {
  int failed = 0, cells = 158, repeat = 3, threads = 1, n_sizes = 0, sizes[16], want[N_KINDS] = {1, 1, 1, 1};
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--cells") && i + 1 < argc) cells = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--solvers") && i + 1 < argc) {
      const char *list = argv[++i];
      for (int k = 0; k < N_KINDS; ++k) want[k] = strstr(list, kind_name[k]) != NULL;
    } else if (argv[i][0] != '-' && n_sizes < 16) sizes[n_sizes++] = atoi(argv[i]);
    else {
      fprintf(stderr, "usage: chain [--cells n] [--repeat r] [--threads t] [--solvers plain,condensed,sparse,auto] [N ...]\n");
      return 2;
    }
  }
  if (!n_sizes) sizes[0] = 2, sizes[1] = 4, sizes[2] = 8, sizes[3] = 16, n_sizes = 4;
  if (cells < 2 || repeat < 1 || repeat > MAX_REPEAT) {
    fprintf(stderr, "chain: --cells at least 2, --repeat 1 to %d\n", MAX_REPEAT);
    return 2;
  }
  for (int i = 0; i < n_sizes; ++i)
    if (sizes[i] < 2 || sizes[i] > MAX_N) {
      fprintf(stderr, "chain: N from 2 to %d\n", MAX_N);
      return 2;
    }
  const int odd_nx = cells, even_nx = (int)lround(0.955 * cells), even_ny = (int)lround(1.05 * cells);
  printf("chain of N unit squares: odd bodies %d x %d P1 squares, even bodies %d x %d; medians of %d; threads %d\n\n",
         odd_nx, odd_nx, even_nx, even_ny, repeat, threads);
  printf("| N | solver (ran) | DOFs | contact rows | iterations | factorizations | factor nonzeros | CG steps | mc_solve s | CPU s | "
         "assembly | analysis | factorization | solve | contact | of which: geometry | interface operator | active-set solve | "
         "pressure error |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  /* Rounds outermost: round r solves every N and every path once, so that the ratios below
     compare solves made at about the same time (a shared machine's load changes by the minute),
     and each ratio's median is over the rounds. */
  static sample runs[16][N_KINDS][MAX_REPEAT];
  sample result[16][N_KINDS];
  memset(result, 0, sizeof result);
  static sc_mesh mesh[16][MAX_N];
  for (int i = 0; i < n_sizes; ++i)
    for (int k = 0; k < sizes[i]; ++k) {
      const int nx = k % 2 ? even_nx : odd_nx, ny = k % 2 ? even_ny : odd_nx;
      if (sc_mesh_rect(&mesh[i][k], 3, nx, ny, 0, sizes[i] - 1 - k, 1, 1, 0, 1)) {
        fprintf(stderr, "chain: mesh of body %d failed\n", k + 1);
        return 1;
      }
    }
  for (int r = 0; r < repeat; ++r)
    for (int i = 0; i < n_sizes; ++i)
      for (int kind = 0; kind < N_KINDS; ++kind)
        if (want[kind]) runs[i][kind][r] = solve_chain(mesh[i], sizes[i], kind, threads);
  for (int i = 0; i < n_sizes; ++i) {
    const int n = sizes[i];
    for (int kind = 0; kind < N_KINDS; ++kind) {
      if (!want[kind]) continue;
      sample s = result[i][kind] = median_of(runs[i][kind], repeat);
      char ran[32];
      snprintf(ran, sizeof ran, "%s%s%s", kind_name[kind], kind == AUTO ? ": " : "",
               kind == AUTO ? (s.ran == MC_INTERFACE_CONDENSED ? "condensed" : "sparse") : "");
      if (kind == PLAIN)
        printf("| %d | plain | %ld | - | - | - | %.3g | - | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | - | - | - | - | - |\n", n,
               s.dofs, (double)s.nnz, s.wall, s.cpu, s.assembly, s.analysis, s.factorization, s.solve);
      else
        printf("| %d | %s | %ld | %ld | %ld | %ld | %.3g | %ld | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | "
               "%.1e |\n",
               n, ran, s.dofs, s.rows, s.iterations, s.factorizations, (double)s.nnz, s.cg_steps, s.wall, s.cpu, s.assembly, s.analysis,
               s.factorization, s.solve, s.contact, s.geometry, s.interface, s.active_set, s.pressure_error);
      if (kind != PLAIN && s.pressure_error > 1e-8) {
        fprintf(stderr, "chain: N %d %s: pressure error %g\n", n, ran, s.pressure_error);
        failed = 1;
      }
    }
  }
  /* ratios within each round, then their medians: contact / plain at the same N, and each path
     at N against itself at the first N */
  printf("\nRatios of wall times within each round, medians over the %d rounds:\n\n", repeat);
  printf("| N | condensed / plain | sparse / plain | auto / plain | N / %d | plain(N) / plain(%d) | condensed(N) / condensed(%d) | "
         "sparse(N) / sparse(%d) | auto(N) / auto(%d) |\n", sizes[0], sizes[0], sizes[0], sizes[0], sizes[0]);
  printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 0; i < n_sizes; ++i) {
    double ratio[7][MAX_REPEAT];
    for (int r = 0; r < repeat; ++r) {
      for (int kind = 1; kind < N_KINDS; ++kind) ratio[kind - 1][r] = runs[i][kind][r].wall / runs[i][PLAIN][r].wall;
      for (int kind = 0; kind < N_KINDS; ++kind) ratio[3 + kind][r] = runs[i][kind][r].wall / runs[0][kind][r].wall;
    }
    printf("| %d | %.2f | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f | %.2f |\n", sizes[i], bench_median(ratio[0], repeat),
           bench_median(ratio[1], repeat), bench_median(ratio[2], repeat), (double)sizes[i] / sizes[0], bench_median(ratio[3], repeat),
           bench_median(ratio[4], repeat), bench_median(ratio[5], repeat), bench_median(ratio[6], repeat));
  }
  for (int i = 0; i < n_sizes; ++i)
    for (int k = 0; k < sizes[i]; ++k) sc_mesh_free(&mesh[i][k]);
  /* side by side: each path against the plain solve, and against its own N = first size */
  printf("\n| N | DOFs (contact) | plain s | condensed s | sparse s | auto s (ran) | condensed / plain | sparse / plain | auto / plain | "
         "N / %d | plain / plain(%d) | condensed / condensed(%d) | sparse / sparse(%d) | auto / auto(%d) |\n",
         sizes[0], sizes[0], sizes[0], sizes[0], sizes[0]);
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 0; i < n_sizes; ++i) {
    const sample *s = result[i], *f = result[0];
#define RATIO(a, b) ((b) > 0 ? (a) / (b) : NAN)
    printf("| %d | %ld | %.3f | %.3f | %.3f | %.3f (%s) | %.2f | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f | %.2f |\n", sizes[i],
           s[CONDENSED].dofs ? s[CONDENSED].dofs : s[SPARSE].dofs ? s[SPARSE].dofs : s[PLAIN].dofs, s[PLAIN].wall, s[CONDENSED].wall, s[SPARSE].wall, s[AUTO].wall,
           s[AUTO].ran == MC_INTERFACE_CONDENSED ? "condensed" : s[AUTO].ran == MC_INTERFACE_SPARSE ? "sparse" : "-",
           RATIO(s[CONDENSED].wall, s[PLAIN].wall), RATIO(s[SPARSE].wall, s[PLAIN].wall), RATIO(s[AUTO].wall, s[PLAIN].wall),
           (double)sizes[i] / sizes[0], RATIO(s[PLAIN].wall, f[PLAIN].wall), RATIO(s[CONDENSED].wall, f[CONDENSED].wall),
           RATIO(s[SPARSE].wall, f[SPARSE].wall), RATIO(s[AUTO].wall, f[AUTO].wall));
#undef RATIO
  }
  /* the same from the CPU times, and the factors' nonzeros (no noise at all) */
  printf("\n| N | plain CPU s | condensed CPU s | sparse CPU s | auto CPU s | condensed / plain | sparse / plain | N / %d | "
         "plain / plain(%d) | condensed / condensed(%d) | sparse / sparse(%d) | auto / auto(%d) | factor nonzeros: plain, condensed, "
         "sparse / their N = %d |\n",
         sizes[0], sizes[0], sizes[0], sizes[0], sizes[0], sizes[0]);
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 0; i < n_sizes; ++i) {
    const sample *s = result[i], *f = result[0];
#define RATIO(a, b) ((b) > 0 ? (double)(a) / (double)(b) : NAN)
    printf("| %d | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f | %.2f | %.2f, %.2f, %.2f |\n", sizes[i],
           s[PLAIN].cpu, s[CONDENSED].cpu, s[SPARSE].cpu, s[AUTO].cpu, RATIO(s[CONDENSED].cpu, s[PLAIN].cpu),
           RATIO(s[SPARSE].cpu, s[PLAIN].cpu), (double)sizes[i] / sizes[0], RATIO(s[PLAIN].cpu, f[PLAIN].cpu),
           RATIO(s[CONDENSED].cpu, f[CONDENSED].cpu), RATIO(s[SPARSE].cpu, f[SPARSE].cpu), RATIO(s[AUTO].cpu, f[AUTO].cpu),
           RATIO(s[PLAIN].nnz, f[PLAIN].nnz), RATIO(s[CONDENSED].nnz, f[CONDENSED].nnz), RATIO(s[SPARSE].nnz, f[SPARSE].nnz));
#undef RATIO
  }
  return failed;
}
