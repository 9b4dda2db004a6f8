/*
 * long_interface.c - the cost of a long contact interface (docs/benchmarks.md, "Long contact
 * interfaces"; docs/robustness.md, "Known limitations"), on either interface solver.
 *
 * Two strips 0.4 high, one on the other: body 1 of nx x 4 squares (P1, 2 triangles each) on
 * body 2 of round(1.37 nx) x 4 (non-matching meshes), their whole length nx/10 in contact; a
 * uniform pressure p = 0.01 on body 1's top, body 2 held vertically on its bottom and both held
 * horizontally at one left corner node: a uniform stress sigma_yy = -p in both, so every contact
 * pressure is exactly p (a patch test: the "pressure error" column checks the answer).
 * The interface has nx + 1 body-1 nodes, a fraction of the unknowns that does not shrink with
 * the mesh: the case where condensing onto the interface (MC_INTERFACE_CONDENSED: a dense
 * operator S of order q, from a dense trailing block of each factor) costs most, and the one
 * the sparse path (MC_INTERFACE_SPARSE: the two bodies and the active rows factorized together)
 * is for.
 *
 * Every solve runs in a child process of its own (fork; the child builds the meshes and the
 * model, solves, and sends its results and its peak resident memory, VmHWM, back through a
 * pipe), so that each contact solve and each plain solve reports its own peak memory. For each
 * nx: one plain solve (the same meshes and load with body 1 held vertically on its bottom
 * instead of by contact), then one contact solve per interface solver asked for (--solver).
 *
 * Table 1, one row per nx and solver: the solver asked for and the one that ran
 * (MC_INFO_INTERFACE_SOLVER), the factors' nonzeros, active-set iterations and numeric
 * factorizations, the sparse path's conjugate-gradient steps, the contact solve's time and its
 * parts (MC_INFO_TIME_ANALYSIS, MC_INFO_TIME_FACTORIZATION, and from the log: contact geometry,
 * interface operator, active-set solve, refinement; "-" where the log had no such message), the plain solve's time, peak memory of both and the ratios, and the
 * accuracy: pressure error / p, MC_INFO_COMPLEMENTARITY (of the problem the solver solved) and
 * MC_INFO_GAP_RESIDUAL (of the returned displacements). Times are wall seconds of mc_solve
 * (median of --repeat solves in the same child; the first solve of a process also maps its
 * memory fresh). Peak memory is the child's VmHWM in MiB (it includes the meshes and the
 * process's own ~10 MiB).
 * Table 2 (--solver both or all), one row per nx: the paths side by side, time and peak memory,
 * each against the plain solve, and condensed/sparse.
 *
 * The condensed path is skipped above --condensed-max (its time grows like q^3 and its memory
 * like q^2: about 3.3 GiB at nx = 4000, tens of GiB at 16000); skipped cells print as "—".
 * A solve whose path is chosen by the library (auto) cannot be skipped beforehand: each child
 * runs under an address-space limit (--mem-limit, default 85 % of MemAvailable at the start),
 * so that a path that needs more memory fails cleanly instead of waking the OOM killer, and
 * under a time limit (--timeout). A failed, killed or timed-out solve prints as such in its row.
 *
 * usage: long_interface [--solver auto|condensed|sparse|both|all] [--condensed-max nx]
 *                       [--repeat n] [--threads n] [--mem-limit GiB] [--timeout s] [--log]
 *                       [--cells KIND] [--multiplier linear|quadratic] [nx ...]
 *   --solver         MC_OPTION_INTERFACE_SOLVER of the contact solves: auto (default: the option
 *                    not set, the library's choice), condensed, sparse, both (condensed and
 *                    sparse, each forced), all (auto, condensed and sparse), friction (sparse
 *                    without and with --friction's law, default coulomb:0.3)
 *   --friction       coulomb:MU or tresca:G, the pair's friction in --solver friction's solves
 *   --condensed-max  largest nx solved with the condensed path forced (default 4000)
 *   --repeat         solves per child, timed, median printed (default 1, max 15)
 *   --threads        MC_OPTION_THREADS of every solve (default: not set, automatic)
 *   --mem-limit      address-space limit of each child in GiB (RLIMIT_AS; default 85 % of
 *                    MemAvailable at the start; 0: none; at least 1: below that OpenBLAS's
 *                    start in the child can fail and spin)
 *   --timeout        wall-time limit of each child in seconds (default 1800; 0: none)
 *   --log            every contact solve's log messages on stderr
 *   --cells          P1 (default, the meshes above), Q1, T6, Q8, Q9: both strips of that kind
 *                    (sc_mesh_cells; a quadratic strip has 2 nx + 1 contact nodes)
 *   --multiplier     MC_OPTION_MULTIPLIER of the contact solves (a quadratic body 1's)
 *   nx ...           default 250 500 1000 2000 4000 8000 16000
 */
#define _POSIX_C_SOURCE 200809L
#include "cell_kind_name.h"
#include "mortarcontact.h"
#include "scenes.h"
#include "bench_timing.h"
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_REPEAT 15
#define MAX_SIZES 64
#define DASH "\xe2\x80\x94" /* the em dash of skipped cells */

enum { KIND_PLAIN = -1 }; /* otherwise a value of MC_OPTION_INTERFACE_SOLVER, plus: */
enum { KIND_FRICTION = 0x100 }; /* with --friction's law on the pair */
static int friction_law = MC_FRICTION_NONE; /* --friction coulomb:MU or tresca:G */
static double friction_value = 0;

/* The seconds at the end of the log messages of the contact parts ("..., 0.123 s"); -1: no such
   message in this solve's log. */
typedef struct parts {
  double geometry, interface, active_set, refinement;
  long cg_steps; /* the sparse path's conjugate-gradient steps ("..., 9 conjugate-gradient steps, ..."); -1: none */
} parts;

static int echo_log; /* --log */
/* --cells KIND: body 1's and body 2's cells (default P1: the meshes above); a quadratic kind
   meshes both strips with sc_mesh_cells (the same cells, nodes at the middles too).
   --multiplier: MC_OPTION_MULTIPLIER (used by a quadratic body 1). */
static int cells_npc = 3, multiplier = MC_MULTIPLIER_LINEAR;

static double trailing_seconds(const char *message) {
  const char *comma = strrchr(message, ',');
  return comma ? atof(comma + 1) : 0;
}

static void note_parts(void *user, mc_log_level level, const char *message) {
  (void)level;
  parts *p = user;
  if (echo_log) fprintf(stderr, "    %s\n", message);
  if (strncmp(message, "contact geometry", 16) == 0) p->geometry = trailing_seconds(message);
  if (strncmp(message, "interface operator", 18) == 0) p->interface = trailing_seconds(message);
  if (strncmp(message, "active-set solve", 16) == 0) {
    p->active_set = trailing_seconds(message);
    const char *cg = strstr(message, " conjugate-gradient steps");
    if (cg) {
      while (cg > message && cg[-1] >= '0' && cg[-1] <= '9') --cg;
      p->cg_steps = atol(cg);
    }
  }
  if (strncmp(message, "refinement", 10) == 0) p->refinement = trailing_seconds(message);
  /* with friction: the stick/slip iteration's time, and its linear solves' Krylov steps */
  if (strncmp(message, "friction solve", 14) == 0) p->active_set = trailing_seconds(message);
  if (strncmp(message, "sparse friction solve", 21) == 0) {
    const char *steps = strstr(message, " Krylov steps");
    if (steps) {
      while (steps > message && steps[-1] >= '0' && steps[-1] <= '9') --steps;
      p->cg_steps = atol(steps);
    }
  }
}

static const double kPressure = 0.01;

/* What a child sends back. ok: 1 solved; 0 failed (message). */
typedef struct outcome {
  int ok, solver_ran;
  long dofs, nnz, contact_nodes, iterations, factorizations;
  double t_solve, t_analysis, t_factor, complementarity, gap_residual, pressure_error, peak_mib;
  parts log;
  char message[240];
} outcome;

/* 1. The model: both strips, the supports, the pressure; contact or body 1 held on its bottom. */
static mc_model *strips(const sc_mesh mesh[2], int kind, int threads, parts *log, char *message, size_t size) {
  mc_model *m = NULL;
  mc_status st = mc_create(&m);
  for (int b = 0; b < 2 && !st; ++b) {
    st = sc_set_mesh(m, b + 1, &mesh[b], 0);
    if (!st) st = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  const mc_int corner1 = mesh[0].side_nodes[SC_LEFT][0], corner2 = mesh[1].side_nodes[SC_LEFT][0];
  if (!st) st = sc_fix_side(m, 2, &mesh[1], SC_BOTTOM, MC_Y, 0);
  if (!st) st = mc_fix(m, 2, 1, &corner2, MC_X, NULL);
  if (!st) st = mc_fix(m, 1, 1, &corner1, MC_X, NULL);
  double *p = malloc(sizeof(double) * mesh[0].n_side_edges[SC_TOP]);
  for (mc_int e = 0; e < mesh[0].n_side_edges[SC_TOP]; ++e) p[e] = kPressure;
  if (!st) st = mc_add_pressure(m, 1, mesh[0].n_side_edges[SC_TOP], mesh[0].side_edges[SC_TOP], p);
  free(p);
  if (kind != KIND_PLAIN) {
    if (!st) st = mc_set_contact(m, 1, mesh[0].n_side_edges[SC_BOTTOM], mesh[0].side_edges[SC_BOTTOM]);
    if (!st) st = mc_set_contact(m, 2, mesh[1].n_side_edges[SC_TOP], mesh[1].side_edges[SC_TOP]);
    /* auto: the option is left at the library's default, as a host that does not set it */
    const int path = kind & ~KIND_FRICTION;
    if (!st && path != MC_INTERFACE_AUTO) st = mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path);
    if (!st && (kind & KIND_FRICTION)) st = mc_set_friction(m, 1, friction_law, friction_value);
    if (!st) st = mc_set_option_int(m, MC_OPTION_MULTIPLIER, multiplier);
  } else if (!st) {
    st = sc_fix_side(m, 1, &mesh[0], SC_BOTTOM, MC_Y, 0);
  }
  if (!st && threads >= 0) st = mc_set_option_int(m, MC_OPTION_THREADS, threads);
  if (!st && log) st = mc_set_log_callback(m, note_parts, log);
  if (st) {
    snprintf(message, size, "model: %s", m ? mc_errmsg(m) : "mc_create failed");
    mc_destroy(m);
    return NULL;
  }
  return m;
}

static double peak_rss_mib(void) {
  FILE *f = fopen("/proc/self/status", "r");
  char line[256];
  long kib = -1;
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, "VmHWM:", 6) == 0) kib = atol(line + 6);
  if (f) fclose(f);
  return kib / 1024.0;
}

/* 2. In the child: the meshes, `repeat` solves (median time), the last one's results. */
static void solve_here(int nx, int kind, int repeat, int threads, outcome *r) {
  memset(r, 0, sizeof *r);
  const int nx2 = (int)lround(1.37 * nx);
  const double length = 0.1 * nx;
  sc_mesh mesh[2];
  const int failed = cells_npc == 3 ? sc_mesh_rect(&mesh[0], 3, nx, 4, 0, 0, length, 0.4, 0, 1) ||
                                          sc_mesh_rect(&mesh[1], 3, nx2, 4, 0, -0.4, length, 0.4, 0, 2)
                                    : sc_mesh_cells(&mesh[0], cells_npc, nx, 4, 0, 0, length, 0.4, 0) ||
                                          sc_mesh_cells(&mesh[1], cells_npc, nx2, 4, 0, -0.4, length, 0.4, 0);
  if (failed) {
    snprintf(r->message, sizeof r->message, "cannot mesh nx = %d", nx);
    return;
  }
  double times[MAX_REPEAT];
  for (int k = 0; k < repeat; ++k) {
    parts log = {-1, -1, -1, -1, -1};
    mc_model *m = strips(mesh, kind, threads, kind == KIND_PLAIN ? NULL : &log, r->message, sizeof r->message);
    if (!m) return;
    if (echo_log && kind != KIND_PLAIN) fprintf(stderr, "  nx %d, solve %d of %d:\n", nx, k + 1, repeat);
    const double start = bench_wall();
    if (mc_solve(m)) {
      snprintf(r->message, sizeof r->message, "mc_solve: %s", mc_errmsg(m));
      mc_destroy(m);
      return;
    }
    times[k] = bench_wall() - start;
    if (k == repeat - 1) {
      int64_t v = 0;
      mc_get_info_int(m, MC_INFO_DOFS, &v), r->dofs = (long)v;
      mc_get_info_int(m, MC_INFO_FACTOR_NNZ, &v), r->nnz = (long)v;
      mc_get_info_int(m, MC_INFO_ITERATIONS, &v), r->iterations = (long)v;
      mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v), r->factorizations = (long)v;
      v = 0;
      mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &v), r->solver_ran = (int)v;
      mc_get_info_real(m, MC_INFO_TIME_ANALYSIS, &r->t_analysis);
      mc_get_info_real(m, MC_INFO_TIME_FACTORIZATION, &r->t_factor);
      mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &r->complementarity);
      mc_get_info_real(m, MC_INFO_GAP_RESIDUAL, &r->gap_residual);
      r->log = log;
      /* 3. The answer against the exact one: every contact pressure p. */
      if (kind != KIND_PLAIN) {
        mc_int n = 0;
        mc_get_contact_count(m, &n);
        double *pressure = malloc(sizeof(double) * (n > 0 ? n : 1)), worst = n > 0 ? 0 : INFINITY;
        mc_get_contact_pressure(m, pressure);
        for (mc_int j = 0; j < n; ++j) worst = fmax(worst, fabs(pressure[j] - kPressure) / kPressure);
        free(pressure);
        r->contact_nodes = n, r->pressure_error = worst;
      }
    }
    mc_destroy(m);
  }
  r->t_solve = bench_median(times, repeat);
  r->peak_mib = peak_rss_mib();
  r->ok = 1;
  sc_mesh_free(&mesh[0]);
  sc_mesh_free(&mesh[1]);
}

/* 4. One solve in a child process of its own, under the memory and time limits. */
static outcome run_child(int nx, int kind, int repeat, int threads, double mem_limit_gib, int timeout) {
  outcome r;
  memset(&r, 0, sizeof r);
  int fd[2];
  if (pipe(fd) != 0) {
    snprintf(r.message, sizeof r.message, "pipe: %s", strerror(errno));
    return r;
  }
  fflush(stdout), fflush(stderr);
  const double start = bench_wall();
  pid_t pid = fork();
  if (pid < 0) {
    snprintf(r.message, sizeof r.message, "fork: %s", strerror(errno));
    close(fd[0]), close(fd[1]);
    return r;
  }
  if (pid == 0) {
    close(fd[0]);
    if (mem_limit_gib > 0) {
      struct rlimit limit;
      limit.rlim_cur = limit.rlim_max = (rlim_t)(mem_limit_gib * 1073741824.0);
      setrlimit(RLIMIT_AS, &limit);
    }
    if (timeout > 0) alarm((unsigned)timeout);
    solve_here(nx, kind, repeat, threads, &r);
    ssize_t written = write(fd[1], &r, sizeof r);
    _exit(written == (ssize_t)sizeof r ? 0 : 1);
  }
  close(fd[1]);
  ssize_t got = 0, n;
  while (got < (ssize_t)sizeof r && (n = read(fd[0], (char *)&r + got, sizeof r - got)) > 0) got += n;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (got != (ssize_t)sizeof r) {
    memset(&r, 0, sizeof r);
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
      snprintf(r.message, sizeof r.message, "timed out after %d s (--timeout)", timeout);
    else if (WIFSIGNALED(status))
      snprintf(r.message, sizeof r.message, "killed by signal %d after %.0f s%s", WTERMSIG(status), bench_wall() - start,
               WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "");
    else
      snprintf(r.message, sizeof r.message, "the child process failed (exit status %d)",
               WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  return r;
}

static const char *solver_name(int kind) {
  if (kind & KIND_FRICTION) {
    switch (kind & ~KIND_FRICTION) {
      case MC_INTERFACE_AUTO: return "auto + friction";
      case MC_INTERFACE_CONDENSED: return "condensed + friction";
      case MC_INTERFACE_SPARSE: return "sparse + friction";
      default: return "?";
    }
  }
  switch (kind) {
    case KIND_PLAIN: return "plain";
    case MC_INTERFACE_AUTO: return "auto";
    case MC_INTERFACE_CONDENSED: return "condensed";
    case MC_INTERFACE_SPARSE: return "sparse";
    default: return "?";
  }
}

/* MC_INFO_INTERFACE_SOLVER as read: 1 condensed, 2 sparse; 0 "not set" (no contact, or a
   library that does not set it yet). */
static const char *ran_name(int ran) {
  return ran == MC_INTERFACE_CONDENSED ? "condensed" : ran == MC_INTERFACE_SPARSE ? "sparse" : "0 (not set)";
}

/* A part's time, "-" when the log had no such message. */
static void part(char *cell, double seconds) {
  if (seconds < 0) strcpy(cell, "-");
  else snprintf(cell, 96, "%.3f", seconds);
}

/* Table 1's columns. */
#define NCOL 25
static const char *const kColumns[NCOL] = {
    "nx", "contact nodes", "DOFs", "solver", "ran", "nnz(L) contact", "nnz(L) plain", "it", "factorizations",
    "CG steps", "contact solve s", "analysis s", "factor s", "geometry s", "interface operator s", "active-set s", "refinement s", "plain solve s",
    "contact/plain", "peak MiB contact", "peak MiB plain", "memory contact/plain", "pressure error / p",
    "MC_INFO_COMPLEMENTARITY", "MC_INFO_GAP_RESIDUAL"};

static void print_row(char cell[NCOL][96]) {
  for (int c = 0; c < NCOL; ++c) printf("| %s ", cell[c]);
  printf("|\n");
  fflush(stdout);
}

/* MemAvailable (or MemTotal on kernels without it) in GiB, at the start of the run. */
static double mem_available_gib(void) {
  FILE *f = fopen("/proc/meminfo", "r");
  char line[256];
  long total = 0, available = 0;
  while (f && fgets(line, sizeof line, f)) {
    if (strncmp(line, "MemTotal:", 9) == 0) total = atol(line + 9);
    if (strncmp(line, "MemAvailable:", 13) == 0) available = atol(line + 13);
  }
  if (f) fclose(f);
  return (available > 0 ? available : total) / 1048576.0;
}

static int usage(const char *argv0) {
  fprintf(stderr,
          "usage: %s [--solver auto|condensed|sparse|both|all|friction] [--friction coulomb:MU|tresca:G]\n"
          "       [--condensed-max nx] [--repeat n] [--threads n]\n"
          "       [--mem-limit GiB] [--timeout s] [--log] [--cells P1|Q1|T6|Q8|Q9] [--multiplier linear|quadratic]\n"
          "       [nx ...]\n",
          argv0);
  return 2;
}

int main(int argc, char **argv) {
  static const int defaults[] = {250, 500, 1000, 2000, 4000, 8000, 16000};
  int sizes[MAX_SIZES], n_sizes = 0, repeat = 1, threads = -1, condensed_max = 4000, timeout = 1800;
  double mem_limit = 0.85 * mem_available_gib();
  const char *solver = "auto";
  for (int i = 1; i < argc; ++i) {
    const int more = i + 1 < argc;
    if (!strcmp(argv[i], "--solver") && more) solver = argv[++i];
    else if (!strcmp(argv[i], "--condensed-max") && more) condensed_max = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--repeat") && more) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--threads") && more) threads = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--mem-limit") && more) mem_limit = atof(argv[++i]);
    else if (!strcmp(argv[i], "--timeout") && more) timeout = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--log")) echo_log = 1;
    else if (!strcmp(argv[i], "--friction") && more) {
      const char *f = argv[++i], *colon = strchr(f, ':');
      if (!colon) return usage(argv[0]);
      if (!strncmp(f, "coulomb:", 8)) friction_law = MC_FRICTION_COULOMB;
      else if (!strncmp(f, "tresca:", 7)) friction_law = MC_FRICTION_TRESCA;
      else return usage(argv[0]);
      friction_value = atof(colon + 1);
    }
    else if (!strcmp(argv[i], "--cells") && more) {
      const char *k = argv[++i];
      cells_npc = 0;
      for (int npc = 3; npc <= 9; ++npc)
        if (!strcmp(k, cell_kind_name(npc))) cells_npc = npc;
      if (!cells_npc) return usage(argv[0]);
    } else if (!strcmp(argv[i], "--multiplier") && more) {
      const char *k = argv[++i];
      if (!strcmp(k, "linear")) multiplier = MC_MULTIPLIER_LINEAR;
      else if (!strcmp(k, "quadratic")) multiplier = MC_MULTIPLIER_QUADRATIC;
      else return usage(argv[0]);
    }
    else if (argv[i][0] != '-' && atoi(argv[i]) >= 1 && n_sizes < MAX_SIZES) sizes[n_sizes++] = atoi(argv[i]);
    else {
      fprintf(stderr, "bad argument %s\n", argv[i]);
      return usage(argv[0]);
    }
  }
  if (n_sizes == 0)
    for (size_t k = 0; k < sizeof defaults / sizeof *defaults; ++k) sizes[n_sizes++] = defaults[k];
  int kinds[3], n_kinds = 0;
  if (!strcmp(solver, "auto")) kinds[n_kinds++] = MC_INTERFACE_AUTO;
  else if (!strcmp(solver, "condensed")) kinds[n_kinds++] = MC_INTERFACE_CONDENSED;
  else if (!strcmp(solver, "sparse")) kinds[n_kinds++] = MC_INTERFACE_SPARSE;
  else if (!strcmp(solver, "both")) kinds[n_kinds++] = MC_INTERFACE_CONDENSED, kinds[n_kinds++] = MC_INTERFACE_SPARSE;
  else if (!strcmp(solver, "friction")) {
    if (friction_law == MC_FRICTION_NONE) friction_law = MC_FRICTION_COULOMB, friction_value = 0.3;
    kinds[n_kinds++] = MC_INTERFACE_SPARSE, kinds[n_kinds++] = MC_INTERFACE_SPARSE | KIND_FRICTION;
  } else if (!strcmp(solver, "all"))
    kinds[n_kinds++] = MC_INTERFACE_AUTO, kinds[n_kinds++] = MC_INTERFACE_CONDENSED, kinds[n_kinds++] = MC_INTERFACE_SPARSE;
  else {
    fprintf(stderr, "bad --solver %s\n", solver);
    return usage(argv[0]);
  }
  if (mem_limit > 0 && mem_limit < 1) {
    fprintf(stderr, "--mem-limit: 0 (none) or at least 1 GiB\n");
    return usage(argv[0]);
  }
  if (repeat < 1 || repeat > MAX_REPEAT) {
    fprintf(stderr, "need 1 <= --repeat <= %d\n", MAX_REPEAT);
    return usage(argv[0]);
  }
  const int side_by_side = n_kinds > 1;
  /* results kept for table 2: [size][0] plain, [size][1 + k] kinds[k]; skipped: ok = -1 */
  outcome(*kept)[4] = side_by_side ? calloc((size_t)n_sizes, sizeof *kept) : NULL;

  char threads_text[32] = "not set";
  if (threads >= 0) snprintf(threads_text, sizeof threads_text, "%d", threads);
  printf("Strips, %s%s, nx x 4 on round(1.37 nx) x 4; --solver %s; condensed path forced only up to nx = %d; "
         "median of %d solve%s per child; MC_OPTION_THREADS %s; OPENBLAS_NUM_THREADS=%s; %ld cores; "
         "per child: memory limit %.1f GiB, timeout %d s\n\n",
         cell_kind_name(cells_npc), cells_npc > 4 && multiplier == MC_MULTIPLIER_QUADRATIC ? " (quadratic multipliers)" : "",
         solver, condensed_max, repeat, repeat == 1 ? "" : "s", threads_text,
         getenv("OPENBLAS_NUM_THREADS") ? getenv("OPENBLAS_NUM_THREADS") : "unset", sysconf(_SC_NPROCESSORS_ONLN),
         mem_limit, timeout);
  for (int c = 0; c < NCOL; ++c) printf("| %s ", kColumns[c]);
  printf("|\n");
  for (int c = 0; c < NCOL; ++c) printf("|---");
  printf("|\n");
  fflush(stdout);
  int failed = 0;
  for (int s = 0; s < n_sizes; ++s) {
    const int nx = sizes[s];
    outcome plain = run_child(nx, KIND_PLAIN, repeat, threads, mem_limit, timeout);
    if (!plain.ok) {
      fprintf(stderr, "nx %d, plain: %s\n", nx, plain.message);
      failed = 1;
    }
    if (kept) kept[s][0] = plain;
    for (int k = 0; k < n_kinds; ++k) {
      const int kind = kinds[k];
      /* the row's cells; "—" where a skipped path has nothing to show */
      char cell[NCOL][96];
      for (int c = 0; c < NCOL; ++c) strcpy(cell[c], DASH);
      snprintf(cell[0], 96, "%d", nx);
      snprintf(cell[3], 96, "%s", solver_name(kind));
      if (plain.ok) {
        snprintf(cell[6], 96, "%ld", plain.nnz);
        snprintf(cell[17], 96, "%.4f", plain.t_solve);
        snprintf(cell[20], 96, "%.0f", plain.peak_mib);
      } else {
        strcpy(cell[17], "failed"), strcpy(cell[20], "failed");
      }
      if (kind == MC_INTERFACE_CONDENSED && nx > condensed_max) {
        snprintf(cell[1], 96, "%d", nx + 1); /* body 1's bottom nodes */
        snprintf(cell[4], 96, DASH " (skipped: nx > %d)", condensed_max);
        if (kept) kept[s][1 + k].ok = -1;
        print_row(cell);
        continue;
      }
      outcome r = run_child(nx, kind, repeat, threads, mem_limit, timeout);
      if (kept) kept[s][1 + k] = r;
      if (!r.ok) {
        fprintf(stderr, "nx %d, %s: %s\n", nx, solver_name(kind), r.message);
        snprintf(cell[4], 96, "FAILED: %.80s", r.message);
        print_row(cell);
        failed = 1;
        continue;
      }
      snprintf(cell[1], 96, "%ld", r.contact_nodes);
      snprintf(cell[2], 96, "%ld", r.dofs);
      snprintf(cell[4], 96, "%s", ran_name(r.solver_ran));
      snprintf(cell[5], 96, "%ld", r.nnz);
      snprintf(cell[7], 96, "%ld", r.iterations);
      snprintf(cell[8], 96, "%ld", r.factorizations);
      if (r.log.cg_steps >= 0) snprintf(cell[9], 96, "%ld", r.log.cg_steps);
      else strcpy(cell[9], "-");
      snprintf(cell[10], 96, "%.3f", r.t_solve);
      snprintf(cell[11], 96, "%.3f", r.t_analysis);
      snprintf(cell[12], 96, "%.3f", r.t_factor);
      part(cell[13], r.log.geometry), part(cell[14], r.log.interface);
      part(cell[15], r.log.active_set), part(cell[16], r.log.refinement);
      if (plain.ok) {
        const double x = r.t_solve / plain.t_solve;
        snprintf(cell[18], 96, x < 10 ? "%.2f" : "%.0f", x);
        snprintf(cell[21], 96, "%.2f", r.peak_mib / plain.peak_mib);
      }
      snprintf(cell[19], 96, "%.0f", r.peak_mib);
      snprintf(cell[22], 96, "%.1e", r.pressure_error);
      snprintf(cell[23], 96, "%.1e", r.complementarity);
      snprintf(cell[24], 96, "%.1e", r.gap_residual);
      print_row(cell);
    }
  }

  if (kept) {
    /* Table 2: the paths side by side. */
    printf("\n| nx | contact nodes | DOFs | plain s");
    for (int k = 0; k < n_kinds; ++k) printf(" | %s s", solver_name(kinds[k]));
    for (int k = 0; k < n_kinds; ++k) printf(" | %s/plain", solver_name(kinds[k]));
    printf(" | %s | plain peak MiB", friction_law != MC_FRICTION_NONE ? "friction/frictionless" : "condensed/sparse");
    for (int k = 0; k < n_kinds; ++k) printf(" | %s peak MiB", solver_name(kinds[k]));
    for (int k = 0; k < n_kinds; ++k) printf(" | %s/plain memory", solver_name(kinds[k]));
    printf(" | ran (%s", solver_name(kinds[0]));
    for (int k = 1; k < n_kinds; ++k) printf(", %s", solver_name(kinds[k]));
    printf(") |\n|");
    for (int c = 0; c < 7 + 4 * n_kinds; ++c) printf("---|");
    printf("\n");
    for (int s = 0; s < n_sizes; ++s) {
      const outcome *plain = &kept[s][0], *row = kept[s] + 1;
      long nodes = 0, dofs = plain->dofs;
      int c = -1, sp = -1;
      for (int k = 0; k < n_kinds; ++k) {
        if (row[k].ok == 1 && !nodes) nodes = row[k].contact_nodes, dofs = row[k].dofs;
        if (kinds[k] == MC_INTERFACE_CONDENSED) c = k;
        if (kinds[k] == (MC_INTERFACE_SPARSE | KIND_FRICTION)) c = k; /* (--solver friction: friction/frictionless) */
        if (kinds[k] == MC_INTERFACE_SPARSE) sp = k;
      }
      printf("| %d | %ld | %ld | %s", sizes[s], nodes, dofs, plain->ok == 1 ? "" : "failed");
      if (plain->ok == 1) printf("%.4f", plain->t_solve);
#define CELL(cond, ...)                    \
  do {                                     \
    if (row[k].ok == -1) printf(" | " DASH); \
    else if (!(cond)) printf(" | failed"); \
    else printf(__VA_ARGS__);              \
  } while (0)
      for (int k = 0; k < n_kinds; ++k) CELL(row[k].ok == 1, " | %.3f", row[k].t_solve);
      for (int k = 0; k < n_kinds; ++k) {
        const double x = plain->ok == 1 && row[k].ok == 1 ? row[k].t_solve / plain->t_solve : 0;
        CELL(x > 0, x < 10 ? " | %.2f" : " | %.0f", x);
      }
      if (c >= 0 && sp >= 0 && row[c].ok == 1 && row[sp].ok == 1) printf(" | %.2f", row[c].t_solve / row[sp].t_solve);
      else printf(" | " DASH);
      if (plain->ok == 1) printf(" | %.0f", plain->peak_mib);
      else printf(" | failed");
      for (int k = 0; k < n_kinds; ++k) CELL(row[k].ok == 1, " | %.0f", row[k].peak_mib);
      for (int k = 0; k < n_kinds; ++k) {
        const double x = plain->ok == 1 && row[k].ok == 1 ? row[k].peak_mib / plain->peak_mib : 0;
        CELL(x > 0, " | %.2f", x);
      }
#undef CELL
      printf(" | ");
      for (int k = 0; k < n_kinds; ++k)
        printf("%s%s", k ? ", " : "", row[k].ok == -1 ? DASH : row[k].ok == 1 ? ran_name(row[k].solver_ran) : "failed");
      printf(" |\n");
    }
    free(kept);
  }
  return failed;
}
