/*
 * host_register.c - what a host body costs (issue 22, docs/benchmarks.md "Host bodies").
 *
 * 1. Registering a host matrix of about 10^6 entries against its factorization. A block
 *    [0,1]^2 of N x N cells, plane strain, E = 1, nu = 0.3, its left side restrained (no
 *    equation), a traction on its right side, no contact: one host body, whose stiffness comes
 *    from tests/host_assembly.c (not from the library), in the host's natural numbering. The
 *    input forms, each with N chosen for about 10^6 entries:
 *      coordinates FULL, element entries: every element's 8 x 8 (Q1) entries, duplicates
 *        summed by the library (what a host that never assembles passes);
 *      coordinates TRIANGLE, assembled: the upper triangle of the summed matrix (a host with
 *        an assembled matrix: skyline, CSR), each nonzero once;
 *      coordinates FULL, assembled: both triangles of the summed matrix;
 *      elements Q1 / Q8: mc_add_element_matrices with each element's full matrix (Smith and
 *        Griffiths' storkm; Q8: 16 x 16 per element).
 *    Measured: the wall time of the mc_add_stiffness / mc_add_element_matrices call (the
 *    registration), and of mc_solve's phases: MC_INFO_TIME_ASSEMBLY (the entries summed into
 *    compressed columns, the rigid-mode check), MC_INFO_TIME_FACTORIZATION. Goal: registration at
 *    most a tenth of the factorization.
 * 2. The contact solve with host bodies against the same scene with mesh bodies: the Hertz scene
 *    (examples/scenes/hertz_scene.h, P1, h2 = 1.37 h1, mortar, the library's automatic interface
 *    solver and threads), both bodies mesh bodies, or both host bodies (coordinates: the element
 *    entries' upper triangles; elements: mc_add_element_matrices) given every node. Measured: the
 *    wall time of mc_solve (registration excluded), after one untimed solve of the same scene in
 *    this process; the three alternate, in turn first. Goal: the same time.
 * Medians of --repeat runs (default 7 for part 1, 3 for part 2); the forms (part 1) and the bodies
 * (part 2) take turns, each in turn first, so that a change of load on the machine hits all alike.
 *
 * usage: host_register [--repeat n] [--quick] [--part 1|2] [h1 ...]
 *        (--quick: small sizes, a check that the program runs; h1 default 0.01 0.004 0.0025)
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "hertz_scene.h"
#include "host_assembly.h"
#include "mortarcontact.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPEAT 15

static void check(mc_status st, mc_model *m, const char *what) {
  if (st == MC_OK) return;
  fprintf(stderr, "host_register: %s failed: %s: %s\n", what, mc_status_string(st), mc_errmsg(m));
  exit(1);
}

/* ---- part 1: a block of N x N cells ----------------------------------------------------------- */

typedef struct block {
  int npc, n;       /* cells per side */
  mc_int n_nodes, n_cells, n_eq;
  double *xy;
  mc_int *cells;    /* npc per cell */
  mc_int *eq;       /* 2 per node: 0-based equation or -1 */
  double *ke;       /* (2 npc)^2 per cell */
  double *f;        /* n_eq */
} block;

/* Q1 or Q8 cells on the lattice of corners (and middles for Q8, no centres). */
static void block_build(block *b, int npc, int n) {
  const int order = npc == 8 ? 2 : 1, nI = order * n + 1;
  mc_int *id = malloc(sizeof(mc_int) * (size_t)nI * (size_t)nI);
  memset(b, 0, sizeof *b);
  b->npc = npc, b->n = n;
  for (int J = 0; J < nI; ++J)
    for (int I = 0; I < nI; ++I) id[J * nI + I] = (order == 2 && I % 2 == 1 && J % 2 == 1) ? -1 : b->n_nodes++;
  b->xy = malloc(sizeof(double) * 2 * (size_t)b->n_nodes);
  b->eq = malloc(sizeof(mc_int) * 2 * (size_t)b->n_nodes);
  for (int J = 0; J < nI; ++J)
    for (int I = 0; I < nI; ++I) {
      const mc_int k = id[J * nI + I];
      if (k < 0) continue;
      b->xy[2 * k] = (double)I / (nI - 1), b->xy[2 * k + 1] = (double)J / (nI - 1);
    }
  for (mc_int k = 0; k < b->n_nodes; ++k) /* the left side restrained */
    for (int c = 0; c < 2; ++c) b->eq[2 * k + c] = b->xy[2 * k] == 0 ? -1 : b->n_eq++;
  b->n_cells = (mc_int)n * n;
  b->cells = malloc(sizeof(mc_int) * (size_t)npc * (size_t)b->n_cells);
  mc_int *c = b->cells;
#define ID(I, J) id[(J) * nI + (I)]
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i, c += npc) {
      const int I = order * i, J = order * j, o = order;
      c[0] = ID(I, J), c[1] = ID(I + o, J), c[2] = ID(I + o, J + o), c[3] = ID(I, J + o);
      if (npc == 8) c[4] = ID(I + 1, J), c[5] = ID(I + 2, J + 1), c[6] = ID(I + 1, J + 2), c[7] = ID(I, J + 1);
    }
#undef ID
  const int nd = 2 * npc;
  double D[9], xy[16];
  ha_law_plane_strain(1, 0.3, D);
  b->ke = malloc(sizeof(double) * (size_t)(nd * nd) * (size_t)b->n_cells);
  for (mc_int e = 0; e < b->n_cells; ++e) {
    for (int a = 0; a < npc; ++a) {
      const mc_int k = b->cells[(size_t)e * npc + a];
      xy[2 * a] = b->xy[2 * k], xy[2 * a + 1] = b->xy[2 * k + 1];
    }
    if (ha_element_stiffness(npc, xy, 0, 1, D, b->ke + (size_t)e * nd * nd)) {
      fprintf(stderr, "host_register: bad cell\n");
      exit(1);
    }
  }
  /* a traction (0.01, 0.005) on the right side */
  b->f = calloc((size_t)b->n_eq, sizeof(double));
  for (int j = 0; j < n; ++j) {
    const int I = nI - 1, J = order * j;
    const mc_int nodes[3] = {id[J * nI + I], id[(J + order) * nI + I], order == 2 ? id[(J + 1) * nI + I] : -1};
    const int ne = order == 2 ? 3 : 2;
    double exy[6], fe[6];
    const double t[2] = {0.01, 0.005};
    for (int a = 0; a < ne; ++a) exy[2 * a] = b->xy[2 * nodes[a]], exy[2 * a + 1] = b->xy[2 * nodes[a] + 1];
    ha_edge_load(ne, exy, t, 0, 1, fe);
    for (int a = 0; a < ne; ++a)
      for (int cc = 0; cc < 2; ++cc) b->f[b->eq[2 * nodes[a] + cc]] += fe[2 * a + cc];
  }
  free(id);
}

static void block_free(block *b) {
  free(b->xy), free(b->cells), free(b->eq), free(b->ke), free(b->f);
  memset(b, 0, sizeof *b);
}

/* The element entries in host numbers (0-based), every one (duplicates kept). */
static void element_entries(const block *b, ha_coo *a) {
  const int nd = 2 * b->npc;
  memset(a, 0, sizeof *a);
  for (mc_int e = 0; e < b->n_cells; ++e) {
    mc_int num[16];
    for (int l = 0; l < nd; ++l) num[l] = b->eq[2 * b->cells[(size_t)e * b->npc + l / 2] + l % 2];
    const double *k = b->ke + (size_t)e * nd * nd;
    for (int p = 0; p < nd; ++p)
      for (int q = 0; q < nd; ++q)
        if (num[p] >= 0 && num[q] >= 0) ha_coo_add(a, num[p], num[q], k[nd * p + q]);
  }
}

static const ha_coo *sort_source;
static int by_row_col(const void *x, const void *y) {
  const size_t i = *(const size_t *)x, j = *(const size_t *)y;
  const mc_int ri = sort_source->row[i], rj = sort_source->row[j], ci = sort_source->col[i], cj = sort_source->col[j];
  return ri != rj ? (ri > rj) - (ri < rj) : (ci > cj) - (ci < cj);
}

/* The summed matrix: each nonzero once, both triangles (upper_only: row <= col only). */
static void assembled_entries(const ha_coo *all, int upper_only, ha_coo *out) {
  size_t *order = malloc(sizeof(size_t) * all->n);
  for (size_t k = 0; k < all->n; ++k) order[k] = k;
  sort_source = all;
  qsort(order, all->n, sizeof(size_t), by_row_col);
  memset(out, 0, sizeof *out);
  for (size_t p = 0; p < all->n;) {
    const mc_int r = all->row[order[p]], c = all->col[order[p]];
    double v = 0;
    for (; p < all->n && all->row[order[p]] == r && all->col[order[p]] == c; ++p) v += all->val[order[p]];
    if (!upper_only || r <= c) ha_coo_add(out, r, c, v);
  }
  free(order);
}

enum { FORM_FULL_ELEMENT_ENTRIES, FORM_TRIANGLE_ASSEMBLED, FORM_FULL_ASSEMBLED, FORM_ELEMENTS };

typedef struct register_row {
  const char *name;
  int npc, n, form;
  /* the input, built once */
  block b;
  ha_coo input;
  mc_int *eltptr, *eltvar;
  int storage;
  long entries, equations;
  double t_register[MAX_REPEAT], t_assembly[MAX_REPEAT], t_factor[MAX_REPEAT];
} register_row;

static void prepare_registration(register_row *row) {
  block *b = &row->b;
  block_build(b, row->npc, row->n);
  ha_coo all;
  memset(&row->input, 0, sizeof row->input);
  element_entries(b, &all);
  const int nd = 2 * b->npc;
  row->storage = MC_MATRIX_FULL;
  switch (row->form) {
    case FORM_FULL_ELEMENT_ENTRIES: row->input = all, memset(&all, 0, sizeof all); break;
    case FORM_TRIANGLE_ASSEMBLED: assembled_entries(&all, 1, &row->input), row->storage = MC_MATRIX_TRIANGLE; break;
    case FORM_FULL_ASSEMBLED: assembled_entries(&all, 0, &row->input); break;
    default: /* elements: the restrained freedoms stay in, numbered below the base (skipped) */
      row->eltptr = malloc(sizeof(mc_int) * ((size_t)b->n_cells + 1));
      row->eltvar = malloc(sizeof(mc_int) * (size_t)nd * (size_t)b->n_cells);
      for (mc_int e = 0; e < b->n_cells; ++e) {
        row->eltptr[e] = (mc_int)(e * nd);
        for (int l = 0; l < nd; ++l) row->eltvar[(size_t)e * nd + l] = b->eq[2 * b->cells[(size_t)e * b->npc + l / 2] + l % 2];
      }
      row->eltptr[b->n_cells] = (mc_int)(b->n_cells * nd);
  }
  ha_coo_free(&all);
  row->entries = row->form == FORM_ELEMENTS ? (long)b->n_cells * nd * nd : (long)row->input.n;
  row->equations = b->n_eq;
}

static void measure_registration(register_row *row, int r) {
  const block *b = &row->b;
  mc_model *m = NULL;
  check(mc_create(&m), m, "mc_create");
  check(mc_set_host_body(m, 1, b->n_nodes, b->xy, b->eq, b->n_eq), m, "mc_set_host_body");
  const double t0 = bench_wall();
  if (row->form == FORM_ELEMENTS) /* a_elt: the element matrices, symmetric (by rows = by columns) */
    check(mc_add_element_matrices(m, 1, b->n_cells, row->eltptr, row->eltvar, b->ke), m, "mc_add_element_matrices");
  else
    check(mc_add_stiffness(m, 1, (mc_int)row->input.n, row->input.row, row->input.col, row->input.val, row->storage), m,
          "mc_add_stiffness");
  row->t_register[r] = bench_wall() - t0;
  check(mc_set_load_vector(m, 1, b->n_eq, b->f), m, "mc_set_load_vector");
  check(mc_solve(m), m, "mc_solve");
  check(mc_get_info_real(m, MC_INFO_TIME_ASSEMBLY, &row->t_assembly[r]), m, "info");
  check(mc_get_info_real(m, MC_INFO_TIME_FACTORIZATION, &row->t_factor[r]), m, "info");
  mc_destroy(m);
}

static void part1(int repeat, int quick) {
  /* N for about 10^6 entries: element entries 64 per Q1 cell; assembled, per node about 36
     (full) or 19 (upper triangle); Q8 elements 256 per cell */
  enum { ROWS = 5 };
  static register_row rows[ROWS] = {
      {.name = "coordinates FULL, element entries (Q1)", .npc = 4, .n = 125, .form = FORM_FULL_ELEMENT_ENTRIES},
      {.name = "coordinates TRIANGLE, assembled (Q1)", .npc = 4, .n = 229, .form = FORM_TRIANGLE_ASSEMBLED},
      {.name = "coordinates FULL, assembled (Q1)", .npc = 4, .n = 166, .form = FORM_FULL_ASSEMBLED},
      {.name = "elements (Q1, 8 x 8)", .npc = 4, .n = 125, .form = FORM_ELEMENTS},
      {.name = "elements (Q8, 16 x 16)", .npc = 8, .n = 63, .form = FORM_ELEMENTS},
  };
  for (int k = 0; k < ROWS; ++k) {
    if (quick) rows[k].n = rows[k].npc == 8 ? 8 : 16;
    prepare_registration(&rows[k]);
  }
  measure_registration(&rows[0], 0); /* untimed: the first solve of a process maps fresh memory */
  for (int r = 0; r < repeat; ++r) /* the forms in turn, each in turn first */
    for (int i = 0; i < ROWS; ++i) measure_registration(&rows[(i + r) % ROWS], r);
  printf("Registering a host matrix against its factorization (one host body, plane strain, no contact; medians of %d)\n\n",
         repeat);
  printf("| input | cells | equations | entries | register s | assembly s | factorization s | register / factorization | "
         "(register + assembly) / factorization |\n|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < ROWS; ++k) {
    register_row *w = &rows[k];
    const double reg = bench_median(w->t_register, repeat), as = bench_median(w->t_assembly, repeat),
                 fac = bench_median(w->t_factor, repeat);
    printf("| %s | %d x %d | %ld | %ld | %.4f | %.4f | %.4f | %.3f | %.3f |\n", w->name, w->n, w->n, w->equations, w->entries,
           reg, as, fac, reg / fac, (reg + as) / fac);
    free(w->eltptr), free(w->eltvar);
    ha_coo_free(&w->input);
    block_free(&w->b);
  }
  fflush(stdout);
}

/* ---- part 2: the Hertz scene, mesh bodies against host bodies ------------------------------------ */

enum { AS_MESH = 0, AS_HOST_COORDINATES = 1, AS_HOST_ELEMENTS = 2 };
static const char *kAsName[3] = {"mesh bodies", "host bodies (coordinates)", "host bodies (elements)"};

typedef struct hertz_host {
  hertz_scene s;
  mc_int n_eq[2];
  mc_int *eq[2];     /* 2 per node */
  double *f[2];
  ha_coo upper[2];   /* the element entries' upper triangles, host numbers */
  mc_int *eltptr[2], *eltvar[2];
  double *ke[2];     /* 36 per cell (P1) */
} hertz_host;

static void hertz_host_build(hertz_host *h, double h1) {
  memset(h, 0, sizeof *h);
  if (hertz_scene_build(&h->s, h1, 1.37 * h1, 0)) {
    fprintf(stderr, "host_register: bad h1 %g\n", h1);
    exit(1);
  }
  double D[9];
  ha_law_plane_strain(1, 0.3, D);
  for (int b = 0; b < 2; ++b) {
    const hertz_mesh *hm = &h->s.body[b];
    char *fix = calloc((size_t)hm->n_nodes, 1);
    if (b == 0)
      for (int i = 0; i < h->s.n_axis_nodes; ++i) fix[h->s.axis_nodes[i]] |= MC_X;
    else
      for (int i = 0; i < h->s.n_bottom_nodes; ++i) fix[h->s.bottom_nodes[i]] |= MC_XY;
    h->eq[b] = malloc(sizeof(mc_int) * 2 * (size_t)hm->n_nodes);
    for (int i = 0; i < hm->n_nodes; ++i)
      for (int c = 0; c < 2; ++c) h->eq[b][2 * i + c] = (fix[i] & (c == 0 ? MC_X : MC_Y)) ? -1 : h->n_eq[b]++;
    free(fix);
    h->ke[b] = malloc(sizeof(double) * 36 * (size_t)hm->n_cells);
    h->eltptr[b] = malloc(sizeof(mc_int) * ((size_t)hm->n_cells + 1));
    h->eltvar[b] = malloc(sizeof(mc_int) * 6 * (size_t)hm->n_cells);
    for (int e = 0; e < hm->n_cells; ++e) {
      double xy[6];
      mc_int num[6];
      for (int a = 0; a < 3; ++a) {
        const int k = hm->cells[3 * e + a];
        xy[2 * a] = hm->xy[2 * k], xy[2 * a + 1] = hm->xy[2 * k + 1];
        num[2 * a] = h->eq[b][2 * k], num[2 * a + 1] = h->eq[b][2 * k + 1];
      }
      double *k = h->ke[b] + 36 * (size_t)e;
      ha_element_stiffness(3, xy, 0, 1, D, k);
      h->eltptr[b][e] = 6 * e;
      for (int l = 0; l < 6; ++l) h->eltvar[b][6 * e + l] = num[l];
      for (int p = 0; p < 6; ++p)
        for (int q = 0; q < 6; ++q)
          if (num[p] >= 0 && num[q] >= 0 && num[p] <= num[q]) ha_coo_add(&h->upper[b], num[p], num[q], k[6 * p + q]);
    }
    h->eltptr[b][hm->n_cells] = 6 * hm->n_cells;
    h->f[b] = calloc((size_t)h->n_eq[b], sizeof(double));
  }
  const double t[2] = {0, -0.005}; /* P = 0.01 on the flat top of width 2 */
  for (int e = 0; e < h->s.n_top_edges; ++e) {
    const int *v = h->s.top_edges + 2 * e;
    double xy[4], fe[4];
    for (int a = 0; a < 2; ++a) xy[2 * a] = h->s.body[0].xy[2 * v[a]], xy[2 * a + 1] = h->s.body[0].xy[2 * v[a] + 1];
    ha_edge_load(2, xy, t, 0, 1, fe);
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c)
        if (h->eq[0][2 * v[a] + c] >= 0) h->f[0][h->eq[0][2 * v[a] + c]] += fe[2 * a + c];
  }
}

static void hertz_host_free(hertz_host *h) {
  for (int b = 0; b < 2; ++b) {
    free(h->eq[b]), free(h->f[b]), free(h->eltptr[b]), free(h->eltvar[b]), free(h->ke[b]);
    ha_coo_free(&h->upper[b]);
  }
  hertz_scene_free(&h->s);
}

typedef struct solve_time {
  double wall, assembly, total;
  long dofs;
  double p0;
} solve_time;

static solve_time hertz_solve(const hertz_host *h, int as) {
  mc_model *m = NULL;
  check(mc_create(&m), m, "mc_create");
  for (int b = 0; b < 2; ++b) {
    const hertz_mesh *hm = &h->s.body[b];
    if (as == AS_MESH) {
      check(mc_set_mesh(m, b + 1, hm->n_nodes, hm->xy, hm->n_cells, 3, hm->cells), m, "mc_set_mesh");
      check(mc_set_material(m, b + 1, 1, 0.3), m, "mc_set_material");
    } else {
      check(mc_set_host_body(m, b + 1, hm->n_nodes, hm->xy, h->eq[b], h->n_eq[b]), m, "mc_set_host_body");
      if (as == AS_HOST_COORDINATES)
        check(mc_add_stiffness(m, b + 1, (mc_int)h->upper[b].n, h->upper[b].row, h->upper[b].col, h->upper[b].val,
                               MC_MATRIX_TRIANGLE),
              m, "mc_add_stiffness");
      else
        check(mc_add_element_matrices(m, b + 1, hm->n_cells, h->eltptr[b], h->eltvar[b], h->ke[b]), m,
              "mc_add_element_matrices");
      check(mc_set_load_vector(m, b + 1, h->n_eq[b], h->f[b]), m, "mc_set_load_vector");
    }
    check(mc_set_contact(m, b + 1, h->s.n_contact_edges[b], h->s.contact_edges[b]), m, "mc_set_contact");
  }
  if (as == AS_MESH) {
    check(mc_fix(m, 1, h->s.n_axis_nodes, h->s.axis_nodes, MC_X, NULL), m, "mc_fix");
    check(mc_fix(m, 2, h->s.n_bottom_nodes, h->s.bottom_nodes, MC_XY, NULL), m, "mc_fix");
    double *t = malloc(sizeof(double) * 2 * (size_t)h->s.n_top_edges);
    for (int e = 0; e < h->s.n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -0.005;
    check(mc_add_traction(m, 1, h->s.n_top_edges, h->s.top_edges, t), m, "mc_add_traction");
    free(t);
  }
  /* the same work for both: a host body has no cells to estimate on, so the mesh bodies' error
     estimate (MC_OPTION_ERROR_ESTIMATE, on by default) is off here */
  check(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0), m, "mc_set_option_int");
  solve_time r;
  const double t0 = bench_wall();
  check(mc_solve(m), m, "mc_solve");
  r.wall = bench_wall() - t0;
  int64_t dofs = 0;
  mc_get_info_int(m, MC_INFO_DOFS, &dofs);
  r.dofs = (long)dofs;
  mc_get_info_real(m, MC_INFO_TIME_ASSEMBLY, &r.assembly);
  mc_get_info_real(m, MC_INFO_TIME_TOTAL, &r.total);
  mc_int n = 0;
  mc_get_contact_count(m, &n);
  double *p = malloc(sizeof(double) * ((size_t)n + 1));
  mc_get_contact_pressure(m, p);
  r.p0 = 0;
  for (mc_int j = 0; j < n; ++j) r.p0 = fmax(r.p0, p[j]);
  free(p);
  mc_destroy(m);
  return r;
}

static void part2(int repeat, int n_sizes, const double *sizes) {
  printf("\nThe contact solve: the Hertz scene (P1, mortar) with both bodies mesh bodies or host bodies (wall s of "
         "mc_solve, medians of %d)\n\n",
         repeat);
  printf("| h1 | DOFs | %s s | %s s | %s s | coordinates / mesh | elements / mesh | assembly s (mesh / coordinates / "
         "elements) | p0 host - mesh |\n|---|---|---|---|---|---|---|---|---|\n",
         kAsName[0], kAsName[1], kAsName[2]);
  for (int k = 0; k < n_sizes; ++k) {
    hertz_host h;
    hertz_host_build(&h, sizes[k]);
    hertz_solve(&h, AS_MESH); /* untimed: the first solve of a process maps fresh memory */
    double wall[3][MAX_REPEAT], assembly[3][MAX_REPEAT], p0[3] = {0, 0, 0};
    long dofs = 0;
    for (int r = 0; r < repeat; ++r)
      for (int i = 0; i < 3; ++i) {
        const int as = (i + r) % 3; /* each in turn first */
        const solve_time t = hertz_solve(&h, as);
        wall[as][r] = t.wall, assembly[as][r] = t.assembly, p0[as] = t.p0, dofs = t.dofs;
      }
    double w[3], a[3];
    for (int as = 0; as < 3; ++as) w[as] = bench_median(wall[as], repeat), a[as] = bench_median(assembly[as], repeat);
    printf("| %g | %ld | %.3f | %.3f | %.3f | %.2f | %.2f | %.3f / %.3f / %.3f | %.1e |\n", sizes[k], dofs, w[0], w[1], w[2],
           w[1] / w[0], w[2] / w[0], a[0], a[1], a[2], fmax(fabs(p0[1] - p0[0]), fabs(p0[2] - p0[0])) / p0[0]);
    fflush(stdout);
    hertz_host_free(&h);
  }
}

int main(int argc, char **argv) {
  int repeat = 0, quick = 0, part = 0, n_sizes = 0;
  double sizes[16];
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--quick")) quick = 1;
    else if (!strcmp(argv[i], "--part") && i + 1 < argc) part = atoi(argv[++i]);
    else if (n_sizes < 16 && atof(argv[i]) > 0) sizes[n_sizes++] = atof(argv[i]);
    else {
      fprintf(stderr, "usage: host_register [--repeat n] [--quick] [--part 1|2] [h1 ...]\n");
      return 2;
    }
  }
  if (repeat > MAX_REPEAT) repeat = MAX_REPEAT;
  if (n_sizes == 0) {
    const double fine[3] = {0.01, 0.004, 0.0025}, coarse[1] = {0.05};
    n_sizes = quick ? 1 : 3;
    memcpy(sizes, quick ? coarse : fine, sizeof(double) * (size_t)n_sizes);
  }
  if (part != 2) part1(repeat > 0 ? repeat : quick ? 1 : 7, quick);
  if (part != 1) part2(repeat > 0 ? repeat : quick ? 1 : 3, n_sizes, sizes);
  return 0;
}
