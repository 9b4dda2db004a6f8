/*
 * test_host_body.c - host bodies (issue 22): a body given by the host's own stiffness, load
 * vector and equation numbering instead of a mesh of the library's cells.
 *
 * The host's matrices come from tests/host_assembly.c, an assembler written independently of
 * lib/ with the library's quadrature rules, so a host body and the equivalent mesh body must give
 * the same answer to round-off:
 * - the two-block contact patch (test_quadratic's flat patch) and the Hertz scene (curved), for
 *   P1, Q1, T6, Q8 and Q9 cells, with body 1, body 2 or both given as host bodies: coordinate
 *   input (MC_MATRIX_FULL, MC_MATRIX_TRIANGLE lower and upper) and element input, index base 0
 *   and 1, restrained freedoms absent from the input or given with numbers below the base
 *   (skipped), host equation numberings that permute the natural one, only the contact nodes
 *   given for a supported body, the three methods, both interface solvers, floating host bodies
 *   (held vertically by contact alone), plane strain with a thickness, axisymmetric (the host's
 *   matrix carries 2 pi r), loads by mc_set_load_vector or mc_add_nodal_force, two threads,
 *   quadratic mesh bodies' contact edges by mc_set_contact_curved, a re-solve with a new load
 *   vector (no factorization): displacements, pressures and contact loads equal to 1e-10 of
 *   their largest, K u = f + r on the free equations with the test's own K,
 *   mc_get_equation_solution equal to mc_get_displacement;
 * - a layered orthotropic section the library has no cell for (laws per band of cells and
 *   sub-layers inside quadrilaterals) against a mesh body: the patch test, exact to 1e-10;
 * - bad input, each refused naming the argument and index, the model usable after it; the calls
 *   a host body refuses.
 */
#include "cell_kind_name.h"
#include "check_helpers.h"
#include "hertz_scene.h"
#include "host_assembly.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const int kKinds[5] = {3, 4, 6, 8, 9};
static double max_abs_of(const double *v, size_t n) {
  double s = 0;
  for (size_t i = 0; i < n; ++i) s = fmax(s, fabs(v[i]));
  return s;
}

/* ---- a scene as data: both bodies, their supports, loads and contact surfaces -------------------- */

typedef struct body_def {
  int npc;
  mc_int n_nodes, n_cells;
  double *xy;
  mc_int *cells;
  mc_int n_contact;
  mc_int *contact;     /* 2 corners per edge, the body on their left */
  mc_int n_load;
  mc_int *load_edges;  /* 2 corners per edge: a uniform traction on each */
  double traction[2];
  char *fix;           /* per node: MC_X | MC_Y held at zero */
  double young, nu;
} body_def;

typedef struct scene_def {
  const char *name;
  body_def b[2];
  int axisymmetric;
  double thickness;
} scene_def;

static void body_copy_mesh(body_def *b, int npc, mc_int n_nodes, const double *xy, mc_int n_cells, const mc_int *cells) {
  memset(b, 0, sizeof *b);
  b->npc = npc, b->n_nodes = n_nodes, b->n_cells = n_cells;
  b->xy = malloc(sizeof(double) * 2 * (size_t)n_nodes);
  memcpy(b->xy, xy, sizeof(double) * 2 * (size_t)n_nodes);
  b->cells = malloc(sizeof(mc_int) * (size_t)npc * (size_t)n_cells);
  memcpy(b->cells, cells, sizeof(mc_int) * (size_t)npc * (size_t)n_cells);
  b->fix = calloc((size_t)n_nodes, 1);
}

static mc_int *copy_ids(const void *ids, size_t n, int is_int) {
  mc_int *out = malloc(sizeof(mc_int) * (n ? n : 1));
  for (size_t k = 0; k < n; ++k) out[k] = is_int ? (mc_int)((const int *)ids)[k] : ((const mc_int *)ids)[k];
  return out;
}

static void body_free(body_def *b) {
  free(b->xy), free(b->cells), free(b->contact), free(b->load_edges), free(b->fix);
  memset(b, 0, sizeof *b);
}
static void scene_free(scene_def *s) { body_free(&s->b[0]), body_free(&s->b[1]); }

/* The contact patch of test_quadratic: body 1 = [0,1] x [0,0.5] (5 x 3 squares, criss-cross
   triangles), body 2 = [0,1] x [-0.5,0] (7 x 3, not matching), E = 1 and 3, nu = 0.3, pressure
   0.2 on body 1's top, rollers on both left sides and under body 2: body 1 is held vertically by
   contact alone. Axisymmetric: the same meshes as meridians (the left sides on the axis). */
static void flat_patch_scene(scene_def *s, int npc1, int npc2, int axisymmetric) {
  const int npc[2] = {npc1, npc2}, nx[2] = {5, 7}, cross[2] = {1, 0};
  const double y0[2] = {0, -0.5}, young[2] = {1, 3};
  memset(s, 0, sizeof *s);
  s->name = axisymmetric ? "axisymmetric flat patch" : "flat patch";
  s->axisymmetric = axisymmetric, s->thickness = 1;
  for (int k = 0; k < 2; ++k) {
    sc_mesh mesh;
    ck_assert_int_eq(sc_mesh_cells(&mesh, npc[k], nx[k], 3, 0, y0[k], 1, 0.5, cross[k]), 0);
    body_def *b = &s->b[k];
    body_copy_mesh(b, npc[k], mesh.n_nodes, mesh.xy, mesh.n_cells, mesh.cells);
    b->young = young[k], b->nu = 0.3;
    const int side = k == 0 ? SC_BOTTOM : SC_TOP;
    b->n_contact = mesh.n_side_edges[side];
    b->contact = copy_ids(mesh.side_edges[side], 2 * (size_t)b->n_contact, 0);
    for (mc_int i = 0; i < mesh.n_side_nodes[SC_LEFT]; ++i) b->fix[mesh.side_nodes[SC_LEFT][i]] |= MC_X;
    if (k == 1)
      for (mc_int i = 0; i < mesh.n_side_nodes[SC_BOTTOM]; ++i) b->fix[mesh.side_nodes[SC_BOTTOM][i]] |= MC_Y;
    if (k == 0) {
      b->n_load = mesh.n_side_edges[SC_TOP];
      b->load_edges = copy_ids(mesh.side_edges[SC_TOP], 2 * (size_t)b->n_load, 0);
      b->traction[0] = 0, b->traction[1] = -0.2;
    }
    sc_mesh_free(&mesh);
  }
}

/* The shared Hertz scene (hertz_scene.h): the half-disc (body 1, u_x = 0 on its axis, held
   vertically by contact alone) pressed with 0.01 on its flat top onto the clamped block;
   axisymmetric: the sphere on a flat (the x >= 0 halves, u_r = 0 on the axis of both bodies). */
static void hertz_scene_def(scene_def *s, int npc, double h, int axisymmetric) {
  hertz_scene hs;
  ck_assert_int_eq(axisymmetric ? hertz_scene_axisymmetric_cells(&hs, h, h * 1.37, npc)
                                : hertz_scene_build_cells(&hs, h, h * 1.37, npc),
                   0);
  memset(s, 0, sizeof *s);
  s->name = axisymmetric ? "sphere on a flat" : "Hertz";
  s->axisymmetric = axisymmetric, s->thickness = 1;
  for (int k = 0; k < 2; ++k) {
    const hertz_mesh *hm = &hs.body[k];
    mc_int *cells = copy_ids(hm->cells, (size_t)npc * (size_t)hm->n_cells, 1);
    body_copy_mesh(&s->b[k], npc, hm->n_nodes, hm->xy, hm->n_cells, cells);
    free(cells);
    s->b[k].young = 1, s->b[k].nu = 0.3;
    s->b[k].n_contact = hs.n_contact_edges[k];
    s->b[k].contact = copy_ids(hs.contact_edges[k], 2 * (size_t)hs.n_contact_edges[k], 1);
  }
  for (int i = 0; i < hs.n_axis_nodes; ++i) s->b[0].fix[hs.axis_nodes[i]] |= MC_X;
  for (int i = 0; i < hs.n_bottom_nodes; ++i) s->b[1].fix[hs.bottom_nodes[i]] |= MC_XY;
  if (axisymmetric)
    for (int k = 0; k < 2; ++k)
      for (mc_int i = 0; i < s->b[k].n_nodes; ++i)
        if (s->b[k].xy[2 * i] == 0) s->b[k].fix[i] |= MC_X;
  s->b[0].n_load = hs.n_top_edges;
  s->b[0].load_edges = copy_ids(hs.top_edges, 2 * (size_t)hs.n_top_edges, 1);
  s->b[0].traction[0] = 0, s->b[0].traction[1] = axisymmetric ? -0.0025 / (3.14159265358979323846) : -0.005;
  hertz_scene_free(&hs);
}

/* The edge's nodes: its two corners, and its middle for quadratic cells. Returns 2 or 3. */
static int edge_nodes(const body_def *b, const mc_int *edge, mc_int *nodes) {
  nodes[0] = edge[0], nodes[1] = edge[1];
  if (b->npc <= 4) return 2;
  nodes[2] = ha_edge_middle(b->npc, b->n_cells, b->cells, edge[0], edge[1]);
  ck_assert_int_ge(nodes[2], 0);
  return 3;
}

/* The consistent nodal load (2 per node) of the body's tractions times scale. */
static double *consistent_load(const scene_def *s, int k, double scale) {
  const body_def *b = &s->b[k];
  double *F = calloc(2 * (size_t)b->n_nodes, sizeof(double));
  const double t[2] = {scale * b->traction[0], scale * b->traction[1]};
  for (mc_int e = 0; e < b->n_load; ++e) {
    mc_int nodes[3];
    double xy[6], f[6];
    const int n = edge_nodes(b, b->load_edges + 2 * e, nodes);
    for (int a = 0; a < n; ++a) xy[2 * a] = b->xy[2 * nodes[a]], xy[2 * a + 1] = b->xy[2 * nodes[a] + 1];
    ha_edge_load(n, xy, t, s->axisymmetric, s->thickness, f);
    for (int a = 0; a < n; ++a) F[2 * nodes[a]] += f[2 * a], F[2 * nodes[a] + 1] += f[2 * a + 1];
  }
  return F;
}

/* Element matrices of every cell of an isotropic body ((2 npc)^2 each, row-major). */
static double *element_matrices(const scene_def *s, int k) {
  const body_def *b = &s->b[k];
  const int nd = 2 * b->npc;
  double D[16], xy[18];
  if (s->axisymmetric) ha_law_axisymmetric(b->young, b->nu, D);
  else ha_law_plane_strain(b->young, b->nu, D);
  double *ke = malloc(sizeof(double) * (size_t)(nd * nd) * (size_t)b->n_cells);
  for (mc_int c = 0; c < b->n_cells; ++c) {
    for (int a = 0; a < b->npc; ++a) {
      const mc_int i = b->cells[(size_t)c * b->npc + a];
      xy[2 * a] = b->xy[2 * i], xy[2 * a + 1] = b->xy[2 * i + 1];
    }
    ck_assert_int_eq(ha_element_stiffness(b->npc, xy, s->axisymmetric, s->thickness, D, ke + (size_t)c * nd * nd), 0);
  }
  return ke;
}

/* ---- a body as a mesh body ---------------------------------------------------------------------- */

/* Replaces the loads of mesh body k by its tractions times scale. */
static void set_mesh_loads(mc_model *m, const scene_def *s, int k, int base, double scale) {
  const body_def *b = &s->b[k];
  OK(mc_clear_loads(m, k + 1));
  if (b->n_load == 0) return;
  mc_int *edges = sc_ids(b->load_edges, 2 * b->n_load, base);
  double *t = malloc(sizeof(double) * 2 * (size_t)b->n_load);
  for (mc_int e = 0; e < b->n_load; ++e) t[2 * e] = scale * b->traction[0], t[2 * e + 1] = scale * b->traction[1];
  OK(mc_add_traction(m, k + 1, b->n_load, edges, t));
  free(edges), free(t);
}

/* Body k as a mesh body; curved: its contact edges (quadratic cells) given with their middles
   through mc_set_contact_curved instead of by their corners. */
static void set_mesh_body_as(mc_model *m, const scene_def *s, int k, int base, double load_scale, int curved) {
  const body_def *b = &s->b[k];
  mc_int *cells = sc_ids(b->cells, b->n_cells * b->npc, base);
  OK(mc_set_mesh(m, k + 1, b->n_nodes, b->xy, b->n_cells, b->npc, cells));
  free(cells);
  OK(mc_set_material(m, k + 1, b->young, b->nu));
  for (int mask = 1; mask <= 3; ++mask) {
    mc_int *ids = malloc(sizeof(mc_int) * (size_t)b->n_nodes), n = 0;
    for (mc_int i = 0; i < b->n_nodes; ++i)
      if (b->fix[i] == mask) ids[n++] = i + base;
    if (n > 0) OK(mc_fix(m, k + 1, n, ids, mask, NULL));
    free(ids);
  }
  set_mesh_loads(m, s, k, base, load_scale);
  if (curved && b->npc > 4) {
    mc_int *edges = malloc(sizeof(mc_int) * 3 * (size_t)b->n_contact);
    for (mc_int e = 0; e < b->n_contact; ++e) {
      mc_int nodes[3] = {-1, -1, -1};
      edge_nodes(b, b->contact + 2 * e, nodes);
      for (int a = 0; a < 3; ++a) edges[3 * e + a] = nodes[a] + base;
    }
    OK(mc_set_contact_curved(m, k + 1, b->n_contact, edges));
    free(edges);
    return;
  }
  mc_int *edges = sc_ids(b->contact, 2 * b->n_contact, base);
  OK(mc_set_contact(m, k + 1, b->n_contact, edges));
  free(edges);
}

static void set_mesh_body(mc_model *m, const scene_def *s, int k, int base, double load_scale) {
  set_mesh_body_as(m, s, k, base, load_scale, 0);
}

/* ---- a body as a host body ---------------------------------------------------------------------- */

enum { IN_FULL = 0, IN_LOWER = 1, IN_UPPER = 2, IN_ELEMENTS = 3 };
static const char *kInputName[4] = {"coordinates full", "coordinates lower", "coordinates upper", "elements"};
enum { NUM_NATURAL = 0, NUM_REVERSE = 1, NUM_INTERLEAVED = 2, NUM_SHUFFLED = 3 };
static const char *kNumberingName[4] = {"natural", "reversed", "interleaved", "shuffled"};

typedef struct variant {
  int base;        /* index base */
  int input;       /* IN_* */
  int given;       /* restrained freedoms: 1 given (numbers below the base, their entries passed), 0 absent */
  int numbering;   /* NUM_*: the host's order of its equations */
  int subset;      /* 1: only the contact surface's nodes given (a body held by its supports) */
  int nodal_force; /* 1: the load by mc_add_nodal_force instead of mc_set_load_vector */
  int extra;       /* equations appended that no node names (internal freedoms), with no stiffness */
} variant;

/* What the host knows of a body it registered. */
typedef struct host_body {
  mc_int n_eq;
  mc_int *eq;        /* per mesh freedom (2 per node): its equation, 0-based, or -1 */
  mc_int n_given;
  mc_int *given;     /* the mesh nodes given, in the host's node order */
  ha_coo K;          /* the stiffness on the equations (0-based), duplicates kept */
  double *f;         /* the load vector (n_eq) */
} host_body;

static void host_body_free(host_body *h) {
  free(h->eq), free(h->given), free(h->f);
  ha_coo_free(&h->K);
  memset(h, 0, sizeof *h);
}

/* The host's number of freedom l of a node: its equation plus the base, or for a restrained
   freedom a number below the base (varied: any such number means "none"). */
static mc_int host_number(const host_body *h, mc_int node, int comp, int base) {
  const mc_int e = h->eq[2 * node + comp];
  return e >= 0 ? e + base : base - 1 - (node + comp) % 3;
}

static void number_equations(host_body *h, const body_def *b, int numbering, unsigned seed) {
  h->eq = malloc(sizeof(mc_int) * 2 * (size_t)b->n_nodes);
  mc_int n = 0;
  for (mc_int i = 0; i < b->n_nodes; ++i)
    for (int c = 0; c < 2; ++c) h->eq[2 * i + c] = (b->fix[i] & (c == 0 ? MC_X : MC_Y)) ? -1 : n++;
  h->n_eq = n;
  mc_int *perm = malloc(sizeof(mc_int) * (size_t)n);
  for (mc_int k = 0; k < n; ++k) {
    switch (numbering) {
      case NUM_REVERSE: perm[k] = n - 1 - k; break;
      case NUM_INTERLEAVED: perm[k] = k % 2 == 0 ? k / 2 : (n + 1) / 2 + k / 2; break;
      default: perm[k] = k;
    }
  }
  if (numbering == NUM_SHUFFLED) {
    unsigned state = seed;
    for (mc_int k = n - 1; k > 0; --k) {
      const mc_int j = (mc_int)(sc_random(&state) * (k + 1)), t = perm[k];
      perm[k] = perm[j], perm[j] = t;
    }
  }
  for (mc_int l = 0; l < 2 * b->n_nodes; ++l)
    if (h->eq[l] >= 0) h->eq[l] = perm[h->eq[l]];
  free(perm);
}

/* Registers body k of the scene as a host body with the element matrices ke and the nodal load
   F (2 per node); fills h. */
static void set_host_body(mc_model *m, const scene_def *s, int k, const double *ke, const double *F, const variant *v,
                          host_body *h, unsigned seed) {
  const body_def *b = &s->b[k];
  const int base = v->base, body = k + 1, npc = b->npc, nd = 2 * npc;
  memset(h, 0, sizeof *h);
  number_equations(h, b, v->numbering, seed);
  h->n_eq += v->extra;
  /* the nodes given: all of them, or only those of the contact surface */
  mc_int *new_id = malloc(sizeof(mc_int) * (size_t)b->n_nodes);
  for (mc_int i = 0; i < b->n_nodes; ++i) new_id[i] = v->subset ? -1 : i;
  if (v->subset) {
    for (mc_int e = 0; e < b->n_contact; ++e) {
      mc_int nodes[3];
      const int n = edge_nodes(b, b->contact + 2 * e, nodes);
      for (int a = 0; a < n; ++a) new_id[nodes[a]] = 0;
    }
  }
  h->given = malloc(sizeof(mc_int) * (size_t)b->n_nodes);
  for (mc_int i = 0; i < b->n_nodes; ++i)
    if (new_id[i] >= 0) new_id[i] = h->n_given, h->given[h->n_given++] = i;
  double *xy = malloc(sizeof(double) * 2 * (size_t)h->n_given);
  mc_int *equations = malloc(sizeof(mc_int) * 2 * (size_t)h->n_given);
  for (mc_int j = 0; j < h->n_given; ++j) {
    const mc_int i = h->given[j];
    xy[2 * j] = b->xy[2 * i], xy[2 * j + 1] = b->xy[2 * i + 1];
    equations[2 * j] = host_number(h, i, 0, base), equations[2 * j + 1] = host_number(h, i, 1, base);
  }
  SUCCEEDS(mc_set_host_body(m, body, h->n_given, xy, equations, h->n_eq));
  free(xy), free(equations);

  /* the stiffness, in two calls (the first and the second half of the cells): repeated calls add */
  const mc_int halves[3] = {0, b->n_cells / 2, b->n_cells};
  mc_int *num = malloc(sizeof(mc_int) * (size_t)nd);
  for (int half = 0; half < 2; ++half) {
    ha_coo call;
    memset(&call, 0, sizeof call);
    mc_int *eltptr = malloc(sizeof(mc_int) * (size_t)(halves[half + 1] - halves[half] + 1));
    mc_int *eltvar = malloc(sizeof(mc_int) * (size_t)nd * (size_t)(halves[half + 1] - halves[half] + 1));
    double *a_elt = malloc(sizeof(double) * (size_t)(nd * nd) * (size_t)(halves[half + 1] - halves[half] + 1));
    size_t n_var = 0, n_val = 0;
    for (mc_int c = halves[half]; c < halves[half + 1]; ++c) {
      const mc_int *v_ = b->cells + (size_t)c * npc;
      const double *kc = ke + (size_t)c * nd * nd;
      for (int l = 0; l < nd; ++l) num[l] = host_number(h, v_[l / 2], l % 2, base);
      for (int p = 0; p < nd; ++p)
        for (int q = 0; q < nd; ++q)
          if (num[p] >= base && num[q] >= base) ha_coo_add(&h->K, num[p] - base, num[q] - base, kc[nd * p + q]);
      if (v->input == IN_ELEMENTS) {
        int keep[18], n_keep = 0;
        for (int l = 0; l < nd; ++l)
          if (v->given || num[l] >= base) keep[n_keep++] = l;
        eltptr[c - halves[half]] = (mc_int)n_var + base;
        for (int a = 0; a < n_keep; ++a) eltvar[n_var++] = num[keep[a]];
        for (int qa = 0; qa < n_keep; ++qa) /* column by column */
          for (int pa = 0; pa < n_keep; ++pa) a_elt[n_val++] = kc[nd * keep[pa] + keep[qa]];
      } else {
        for (int p = 0; p < nd; ++p)
          for (int q = 0; q < nd; ++q) {
            const int free_pq = num[p] >= base && num[q] >= base;
            if (!free_pq && !v->given) continue;
            if (v->input == IN_LOWER && num[p] < num[q]) continue;
            if (v->input == IN_UPPER && num[p] > num[q]) continue;
            ha_coo_add(&call, num[p], num[q], kc[nd * p + q]);
          }
      }
    }
    if (v->input == IN_ELEMENTS) {
      eltptr[halves[half + 1] - halves[half]] = (mc_int)n_var + base;
      SUCCEEDS(mc_add_element_matrices(m, body, halves[half + 1] - halves[half], eltptr, eltvar, a_elt));
    } else {
      SUCCEEDS(mc_add_stiffness(m, body, (mc_int)call.n, call.row, call.col, call.val,
                                v->input == IN_FULL ? MC_MATRIX_FULL : MC_MATRIX_TRIANGLE));
    }
    free(eltptr), free(eltvar), free(a_elt);
    ha_coo_free(&call);
  }
  free(num);

  /* the load */
  h->f = calloc((size_t)h->n_eq, sizeof(double));
  for (mc_int l = 0; l < 2 * b->n_nodes; ++l)
    if (h->eq[l] >= 0) h->f[h->eq[l]] += F[l];
  if (v->nodal_force) { /* every loaded node is given */
    mc_int *ids = malloc(sizeof(mc_int) * (size_t)h->n_given);
    double *force = malloc(sizeof(double) * 2 * (size_t)h->n_given);
    for (mc_int j = 0; j < h->n_given; ++j) {
      ids[j] = j + base;
      force[2 * j] = F[2 * h->given[j]], force[2 * j + 1] = F[2 * h->given[j] + 1];
    }
    SUCCEEDS(mc_add_nodal_force(m, body, h->n_given, ids, force));
    free(ids), free(force);
  } else {
    SUCCEEDS(mc_set_load_vector(m, body, h->n_eq, h->f));
  }

  /* the contact surface, in the host's node ids: 2-node edges, or 3-node curved ones */
  const int quadratic = npc > 4, per = quadratic ? 3 : 2;
  mc_int *edges = malloc(sizeof(mc_int) * (size_t)per * (size_t)b->n_contact);
  for (mc_int e = 0; e < b->n_contact; ++e) {
    mc_int nodes[3];
    const int n = edge_nodes(b, b->contact + 2 * e, nodes);
    for (int a = 0; a < n; ++a) edges[per * e + a] = new_id[nodes[a]] + base;
  }
  if (quadratic) SUCCEEDS(mc_set_contact_curved(m, body, b->n_contact, edges));
  else SUCCEEDS(mc_set_contact(m, body, b->n_contact, edges));
  free(edges), free(new_id);
}

/* ---- results, compared ---------------------------------------------------------------------------- */

typedef struct results {
  double *u[2];        /* displacements, 2 per mesh node */
  double *r[2];        /* contact loads, 2 per mesh node (0 at restrained freedoms) */
  mc_int n;            /* contact positions */
  mc_int *nodes;       /* their mesh node ids (0-based) */
  double *p;
  double residual;     /* host bodies: max |K u - f - r| / max(|f|, |r|) on the free equations */
  double disp_vs_eq;   /* host bodies: max |mc_get_displacement - mc_get_equation_solution| / max |u| */
  long factorizations;
} results;

static void results_free(results *r) {
  for (int k = 0; k < 2; ++k) free(r->u[k]), free(r->r[k]);
  free(r->nodes), free(r->p);
  memset(r, 0, sizeof *r);
}

/* Reads the results of a solved model; host[k] is NULL for a mesh body. */
static results read_results(mc_model *m, const scene_def *s, host_body *const host[2], int base) {
  results res;
  memset(&res, 0, sizeof res);
  for (int k = 0; k < 2; ++k) {
    const body_def *b = &s->b[k];
    const size_t nf = 2 * (size_t)b->n_nodes;
    res.u[k] = calloc(nf, sizeof(double)), res.r[k] = calloc(nf, sizeof(double));
    if (!host[k]) {
      OK(mc_get_displacement(m, k + 1, res.u[k]));
      OK(mc_get_contact_load(m, k + 1, res.r[k]));
      double *ueq = malloc(sizeof(double) * nf);
      OK(mc_get_equation_solution(m, k + 1, ueq)); /* 2 per node for a mesh body */
      for (size_t l = 0; l < nf; ++l) ck_assert_msg(ueq[l] == res.u[k][l], "mesh body %d: equation solution differs", k + 1);
      free(ueq);
      for (mc_int i = 0; i < b->n_nodes; ++i) /* only the free freedoms are compared */
        for (int c = 0; c < 2; ++c)
          if (b->fix[i] & (c == 0 ? MC_X : MC_Y)) res.r[k][2 * i + c] = 0;
      continue;
    }
    const host_body *h = host[k];
    double *ueq = malloc(sizeof(double) * (size_t)h->n_eq), *req = malloc(sizeof(double) * (size_t)h->n_eq);
    double *ku = malloc(sizeof(double) * (size_t)h->n_eq), *ug = malloc(sizeof(double) * 2 * (size_t)h->n_given);
    OK(mc_get_equation_solution(m, k + 1, ueq));
    OK(mc_get_contact_load(m, k + 1, req));
    OK(mc_get_displacement(m, k + 1, ug));
    for (size_t l = 0; l < nf; ++l)
      if (h->eq[l] >= 0) res.u[k][l] = ueq[h->eq[l]], res.r[k][l] = req[h->eq[l]];
    const double uscale = fmax(max_abs_of(ueq, (size_t)h->n_eq), 1e-300);
    for (mc_int j = 0; j < h->n_given; ++j)
      for (int c = 0; c < 2; ++c)
        res.disp_vs_eq = fmax(res.disp_vs_eq, fabs(ug[2 * j + c] - res.u[k][2 * h->given[j] + c]) / uscale);
    ha_coo_multiply(&h->K, ueq, ku, h->n_eq);
    double worst = 0, scale = fmax(fmax(max_abs_of(h->f, (size_t)h->n_eq), max_abs_of(req, (size_t)h->n_eq)), 1e-300);
    for (mc_int e = 0; e < h->n_eq; ++e) worst = fmax(worst, fabs(ku[e] - h->f[e] - req[e]));
    res.residual = fmax(res.residual, worst / scale);
    free(ueq), free(req), free(ku), free(ug);
  }
  OK(mc_get_contact_count(m, &res.n));
  res.nodes = malloc(sizeof(mc_int) * (size_t)(res.n + 1));
  res.p = malloc(sizeof(double) * (size_t)(res.n + 1));
  OK(mc_get_contact_nodes(m, res.nodes));
  OK(mc_get_contact_pressure(m, res.p));
  for (mc_int j = 0; j < res.n; ++j) {
    res.nodes[j] -= base;
    if (host[0]) res.nodes[j] = host[0]->given[res.nodes[j]];
  }
  int64_t f = 0;
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &f));
  res.factorizations = (long)f;
  return res;
}

typedef struct differences {
  double u, p, r;
} differences;

static differences compare(const scene_def *s, const results *a, const results *b) {
  differences d = {0, 0, 0};
  double us = 1e-300, rs = 1e-300;
  for (int k = 0; k < 2; ++k) {
    const size_t nf = 2 * (size_t)s->b[k].n_nodes;
    us = fmax(us, max_abs_of(a->u[k], nf)), rs = fmax(rs, max_abs_of(a->r[k], nf));
  }
  for (int k = 0; k < 2; ++k)
    for (size_t l = 0; l < 2 * (size_t)s->b[k].n_nodes; ++l) {
      d.u = fmax(d.u, fabs(a->u[k][l] - b->u[k][l]) / us);
      d.r = fmax(d.r, fabs(a->r[k][l] - b->r[k][l]) / rs);
    }
  ck_assert_int_eq(a->n, b->n);
  const double ps = fmax(max_abs_of(a->p, (size_t)a->n), 1e-300);
  for (mc_int j = 0; j < a->n; ++j) {
    ck_assert_int_eq(a->nodes[j], b->nodes[j]);
    d.p = fmax(d.p, fabs(a->p[j] - b->p[j]) / ps);
  }
  return d;
}

/* ---- one comparison: the scene with mesh bodies, then with host bodies ----------------------------- */

typedef struct run_options {
  int host_mask; /* 1: body 1 a host body, 2: body 2, 3: both */
  int method, solver;
  int resolve;   /* also re-solve both with the load times 1.7 */
  int threads;   /* MC_OPTION_THREADS of the host model (0: not set) */
  int curved;    /* the host model's quadratic mesh bodies: contact by mc_set_contact_curved */
  int multiplier; /* MC_OPTION_MULTIPLIER of both models */
  variant v[2];  /* per body */
} run_options;

typedef struct worst_of {
  double u, p, r, residual, disp_vs_eq;
  int runs;
} worst_of;

static void set_options(mc_model *m, const run_options *o) {
  OK(mc_set_option_int(m, MC_OPTION_METHOD, o->method));
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, o->solver));
  OK(mc_set_option_int(m, MC_OPTION_MULTIPLIER, o->multiplier));
}

static void note(worst_of *w, differences d, const results *h) {
  w->u = fmax(w->u, d.u), w->p = fmax(w->p, d.p), w->r = fmax(w->r, d.r);
  w->residual = fmax(w->residual, h->residual), w->disp_vs_eq = fmax(w->disp_vs_eq, h->disp_vs_eq);
  ++w->runs;
}

static const char *kMethodName[3] = {"mortar", "dual mortar", "node-to-segment"};

static void run_comparison(const scene_def *s, const run_options *o, worst_of *worst) {
  const int base = o->v[0].base; /* one index base per model: both bodies share it */
  /* the reference: mesh bodies */
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  if (s->axisymmetric) OK(mc_set_plane(m, MC_AXISYMMETRIC, 1));
  else OK(mc_set_plane(m, MC_PLANE_STRAIN, s->thickness));
  for (int k = 0; k < 2; ++k) set_mesh_body(m, s, k, 0, 1.0);
  set_options(m, o);
  SUCCEEDS(mc_solve(m));
  host_body *none[2] = {NULL, NULL};
  results ref = read_results(m, s, none, 0);

  /* the same through host bodies */
  mc_model *mh = NULL;
  ck_assert_int_eq(mc_create(&mh), MC_OK);
  {
    mc_model *m = mh; /* for the macros */
    OK(mc_set_index_base(m, base));
    if (s->axisymmetric) OK(mc_set_plane(m, MC_AXISYMMETRIC, 1));
    else OK(mc_set_plane(m, MC_PLANE_STRAIN, s->thickness));
  }
  host_body hb[2];
  host_body *host[2] = {NULL, NULL};
  double *F[2] = {NULL, NULL};
  for (int k = 0; k < 2; ++k) {
    if (!(o->host_mask & (1 << k))) {
      set_mesh_body_as(mh, s, k, base, 1.0, o->curved);
      continue;
    }
    double *ke = element_matrices(s, k);
    F[k] = consistent_load(s, k, 1.0);
    set_host_body(mh, s, k, ke, F[k], &o->v[k], &hb[k], 1234u + (unsigned)k);
    host[k] = &hb[k];
    free(ke);
  }
  {
    mc_model *m = mh;
    set_options(m, o);
    if (o->threads) OK(mc_set_option_int(m, MC_OPTION_THREADS, o->threads));
    SUCCEEDS(mc_solve(m));
    if (o->host_mask == 3) /* no cells to draw: refused before any file is opened */
      FAILS(mc_write_vtu(m, "never_written.vtu"), MC_ERROR_STATE, "no mesh body to write");
  }
  results got = read_results(mh, s, host, base);
  differences d = compare(s, &ref, &got);
  note(worst, d, &got);
  char what[2][160];
  for (int k = 0; k < 2; ++k) {
    const variant *v = &o->v[k];
    if (host[k])
      snprintf(what[k], sizeof what[k], "host %s (%s, %s, restrained %s, %s%s%s)", cell_kind_name(s->b[k].npc),
               kInputName[v->input], kNumberingName[v->numbering], v->given ? "given" : "absent",
               v->subset ? "contact nodes only" : "all nodes", v->nodal_force ? ", nodal forces" : "",
               k == 0 ? ", floating" : "");
    else
      snprintf(what[k], sizeof what[k], "mesh %s%s", cell_kind_name(s->b[k].npc),
               o->curved && s->b[k].npc > 4 ? " (mc_set_contact_curved)" : "");
  }
  printf("%s, base %d, %s, %s%s%s; body 1 %s; body 2 %s: host - mesh: u %.1e, p %.1e, contact load %.1e; K u - f - r %.1e; "
         "displacement - equation solution %.1e\n",
         s->name, base, kMethodName[o->method], o->solver == MC_INTERFACE_SPARSE ? "sparse" : "condensed",
         o->threads == 2 ? ", two threads" : "",
         o->multiplier == MC_MULTIPLIER_QUADRATIC && s->b[0].npc > 4 ? ", quadratic multipliers" : "", what[0], what[1],
         d.u, d.p, d.r, got.residual, got.disp_vs_eq);

  if (o->resolve) { /* a new load vector: no factorization, the same answer as the mesh bodies' */
    const double scale = 1.7;
    for (int k = 0; k < 2; ++k) set_mesh_loads(m, s, k, 0, scale);
    SUCCEEDS(mc_solve(m));
    results ref2 = read_results(m, s, none, 0);
    for (int k = 0; k < 2; ++k) {
      mc_model *m = mh;
      if (!host[k]) {
        set_mesh_loads(m, s, k, base, scale);
        continue;
      }
      for (mc_int e = 0; e < hb[k].n_eq; ++e) hb[k].f[e] *= scale;
      if (o->v[k].nodal_force) OK(mc_clear_loads(m, k + 1));
      SUCCEEDS(mc_set_load_vector(m, k + 1, hb[k].n_eq, hb[k].f));
    }
    {
      mc_model *m = mh;
      SUCCEEDS(mc_solve(m));
    }
    results got2 = read_results(mh, s, host, base);
    differences d2 = compare(s, &ref2, &got2);
    note(worst, d2, &got2);
    printf("  re-solve with the load times %.1f: %ld factorizations (mesh bodies: %ld); u %.1e, p %.1e, contact load %.1e; "
           "K u - f - r %.1e\n",
           scale, got2.factorizations, ref2.factorizations, d2.u, d2.p, d2.r, got2.residual);
    ck_assert_msg(got2.factorizations == 0, "the re-solve with a new load vector factorized %ld times", got2.factorizations);
    results_free(&ref2), results_free(&got2);
  }
  results_free(&ref), results_free(&got);
  for (int k = 0; k < 2; ++k)
    if (host[k]) host_body_free(&hb[k]);
  free(F[0]), free(F[1]);
  mc_destroy(m), mc_destroy(mh);
}

static void assert_worst(const char *what, const worst_of *w) {
  printf("%s: %d solves; worst host - mesh: u %.1e, p %.1e, contact load %.1e; K u - f - r %.1e; displacement - "
         "equation solution %.1e\n",
         what, w->runs, w->u, w->p, w->r, w->residual, w->disp_vs_eq);
  ck_assert_msg(w->u <= 1e-10, "%s: displacements differ by %g", what, w->u);
  ck_assert_msg(w->p <= 1e-10, "%s: pressures differ by %g", what, w->p);
  ck_assert_msg(w->r <= 1e-10, "%s: contact loads differ by %g", what, w->r);
  ck_assert_msg(w->residual <= 1e-10, "%s: K u - f - r = %g", what, w->residual);
  ck_assert_msg(w->disp_vs_eq <= 1e-15, "%s: mc_get_displacement and mc_get_equation_solution differ by %g", what,
                w->disp_vs_eq);
}


/* ---- the flat patch: every kind, every input, both bases ----------------------------------------- */

START_TEST(flat_patch_host_equals_mesh) {
  worst_of worst;
  memset(&worst, 0, sizeof worst);
  int n = 0;
  for (int k = 0; k < 5; ++k) {
    scene_def s;
    flat_patch_scene(&s, kKinds[k], kKinds[(k + 1) % 5], 0);
    for (int input = 0; input < 4; ++input)
      for (int base = 0; base < 2; ++base, ++n) {
        run_options o;
        memset(&o, 0, sizeof o);
        o.host_mask = 1 + n % 3;
        o.method = n % 3; /* the three methods in turn */
        o.solver = (n / 3) % 2 ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED;
        o.resolve = n % 4 == 1;
        for (int b = 0; b < 2; ++b) {
          variant *v = &o.v[b];
          v->base = base, v->input = (input + b) % 4, v->given = (input + base + k + b) % 2;
          v->numbering = (n + b) % 4;
          v->subset = b == 1 && n % 5 == 2;           /* body 2 is held by its supports */
          v->nodal_force = !v->subset && n % 7 == 3;
        }
        s.thickness = n % 6 == 5 ? 0.25 : 1;
        o.threads = n % 5 == 4 ? 2 : 0;
        o.curved = base == 1;
        o.multiplier = (n / 2) % 2 ? MC_MULTIPLIER_QUADRATIC : MC_MULTIPLIER_LINEAR;
        run_comparison(&s, &o, &worst);
      }
    scene_free(&s);
  }
  assert_worst("flat patch, plane strain", &worst);
}
END_TEST

START_TEST(axisymmetric_flat_patch_host_equals_mesh) {
  worst_of worst;
  memset(&worst, 0, sizeof worst);
  int n = 0;
  for (int k = 0; k < 5; ++k) {
    scene_def s;
    flat_patch_scene(&s, kKinds[k], kKinds[(k + 2) % 5], 1);
    for (int mask = 1; mask <= 3; mask += 2, ++n) {
      run_options o;
      memset(&o, 0, sizeof o);
      o.host_mask = mask;
      o.method = n % 3; /* the three methods in turn */
      o.solver = n % 2 ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED;
      o.resolve = n % 3 == 0;
      for (int b = 0; b < 2; ++b) {
        variant *v = &o.v[b];
        v->base = (n / 2) % 2, v->input = (n + b) % 4, v->given = (n + b) % 2, v->numbering = (n + 2 * b) % 4;
      }
      run_comparison(&s, &o, &worst);
    }
    scene_free(&s);
  }
  assert_worst("flat patch, axisymmetric", &worst);
}
END_TEST

/* ---- the Hertz scene: curved contact ------------------------------------------------------------ */

START_TEST(hertz_host_equals_mesh) {
  worst_of worst;
  memset(&worst, 0, sizeof worst);
  int n = 0;
  for (int k = 0; k < 5; ++k) {
    scene_def s;
    hertz_scene_def(&s, kKinds[k], 0.1, 0);
    for (int mask = 1; mask <= 3; ++mask, ++n) {
      run_options o;
      memset(&o, 0, sizeof o);
      o.host_mask = mask;
      o.method = n % 3; /* the three methods in turn */
      o.solver = n % 2 ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED;
      for (int b = 0; b < 2; ++b) {
        variant *v = &o.v[b];
        v->base = (n / 2) % 2, v->input = (n + b + k) % 4, v->given = (n + b) % 2, v->numbering = (n + b) % 4;
        v->subset = b == 1 && n % 2 == 0; /* the block is clamped */
      }
      o.threads = n % 4 == 3 ? 2 : 0;
      o.curved = mask != 3;
      o.multiplier = mask == 2 ? MC_MULTIPLIER_LINEAR : MC_MULTIPLIER_QUADRATIC; /* each quadratic kind with both */
      run_comparison(&s, &o, &worst);
    }
    scene_free(&s);
  }
  /* the sphere on a flat, P1 and Q8, both bodies host bodies and body 1 alone */
  for (int k = 0; k < 5; k += 3) {
    scene_def s;
    hertz_scene_def(&s, kKinds[k], 0.1, 1);
    for (int mask = 1; mask <= 3; mask += 2, ++n) {
      run_options o;
      memset(&o, 0, sizeof o);
      o.host_mask = mask, o.method = MC_METHOD_MORTAR, o.solver = n % 2 ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED;
      for (int b = 0; b < 2; ++b) o.v[b].base = n % 2, o.v[b].input = (n + b) % 4, o.v[b].numbering = NUM_SHUFFLED;
      run_comparison(&s, &o, &worst);
    }
    scene_free(&s);
  }
  assert_worst("Hertz and sphere on a flat", &worst);
}
END_TEST

/* ---- a layered orthotropic section the library has no cell for ------------------------------------ */

/* Body 1 = [0,1] x [0,0.5] (6 x 3 cells) of a layered orthotropic material: each band of cells
   (a row) has its own s22, and inside each quadrilateral two sub-layers (eta < 0 and eta > 0)
   have their own s11 and s33; s12 is common (the interfaces between layers must carry the same
   strain eps_xx). Under a uniform pressure p on its top, on rollers at x = 0 and pressed on an
   isotropic mesh body (body 2, [0,1] x [-0.5,0], 7 x 3, on rollers at x = 0 and under it), the
   exact state is sigma = (0, -p, 0) everywhere in body 1: eps_xx = -p s12, eps_yy = -p s22 of
   each band, no shear; the contact pressure is p. */
static void layered_patch(int npc1, int npc2, int method, int solver, double *err_p, double *err_u, double *err_res) {
  const double p = 0.2, s12 = -0.25, s11[2] = {1.0, 0.6}, s33[2] = {2.6, 1.9}, s22[3] = {0.8, 1.3, 0.55};
  scene_def s;
  flat_patch_scene(&s, npc1, npc2, 0);
  /* body 1 with 6 x 3 cells (not 5: every band then has its own cells) */
  body_free(&s.b[0]);
  {
    sc_mesh mesh;
    ck_assert_int_eq(sc_mesh_cells(&mesh, npc1, 6, 3, 0, 0, 1, 0.5, 1), 0);
    body_def *b = &s.b[0];
    body_copy_mesh(b, npc1, mesh.n_nodes, mesh.xy, mesh.n_cells, mesh.cells);
    b->n_contact = mesh.n_side_edges[SC_BOTTOM];
    b->contact = copy_ids(mesh.side_edges[SC_BOTTOM], 2 * (size_t)b->n_contact, 0);
    for (mc_int i = 0; i < mesh.n_side_nodes[SC_LEFT]; ++i) b->fix[mesh.side_nodes[SC_LEFT][i]] |= MC_X;
    b->n_load = mesh.n_side_edges[SC_TOP];
    b->load_edges = copy_ids(mesh.side_edges[SC_TOP], 2 * (size_t)b->n_load, 0);
    b->traction[0] = 0, b->traction[1] = -p;
    sc_mesh_free(&mesh);
  }
  const body_def *b = &s.b[0];
  const int nd = 2 * npc1;
  double *ke = malloc(sizeof(double) * (size_t)(nd * nd) * (size_t)b->n_cells);
  for (mc_int c = 0; c < b->n_cells; ++c) {
    double xy[18], yc = 0;
    for (int a = 0; a < npc1; ++a) {
      const mc_int i = b->cells[(size_t)c * npc1 + a];
      xy[2 * a] = b->xy[2 * i], xy[2 * a + 1] = b->xy[2 * i + 1];
      yc += xy[2 * a + 1] / npc1;
    }
    const int band = yc < 0.5 / 3 ? 0 : yc < 1.0 / 3 ? 1 : 2;
    double D[18];
    ha_law_orthotropic(s11[0], s22[band], s12, s33[0], D);
    ha_law_orthotropic(s11[1], s22[band], s12, s33[1], D + 9);
    double *kc = ke + (size_t)c * nd * nd;
    if (npc1 == 4 || npc1 == 8 || npc1 == 9) { /* two sub-layers inside the cell */
      const double bounds[3] = {-1, 0, 1};
      ck_assert_int_eq(ha_layered_stiffness(npc1, xy, 1, 2, bounds, D, kc), 0);
    } else { /* triangles: alternate the two laws of the band from cell to cell */
      ck_assert_int_eq(ha_element_stiffness(npc1, xy, 0, 1, D + 9 * (c % 2), kc), 0);
    }
  }
  double *F = consistent_load(&s, 0, 1.0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  variant v = {1, (npc1 + method) % 4, npc1 % 2, NUM_SHUFFLED, 0, 0, 0};
  host_body hb;
  OK(mc_set_index_base(m, 1));
  set_host_body(m, &s, 0, ke, F, &v, &hb, 99u);
  set_mesh_body(m, &s, 1, 1, 1.0);
  OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver));
  SUCCEEDS(mc_solve(m));
  host_body *host[2] = {&hb, NULL};
  results r = read_results(m, &s, host, 1);
  /* the exact displacements */
  const double e2 = s.b[1].young, nu = s.b[1].nu, eyy2 = -(1 - nu * nu) * p / e2, exx2 = nu * (1 + nu) * p / e2;
  const double u_interface = eyy2 * 0.5, band_h = 0.5 / 3;
  double du = 0, scale = 0;
  for (int k = 0; k < 2; ++k)
    for (mc_int i = 0; i < s.b[k].n_nodes; ++i) {
      const double x = s.b[k].xy[2 * i], y = s.b[k].xy[2 * i + 1];
      double ux, uy;
      if (k == 1) {
        ux = exx2 * x, uy = eyy2 * (y + 0.5);
      } else {
        ux = -p * s12 * x, uy = u_interface;
        for (int band = 0; band < 3; ++band) uy += -p * s22[band] * fmin(fmax(y - band * band_h, 0), band_h);
      }
      du = fmax(du, fmax(fabs(r.u[k][2 * i] - ux), fabs(r.u[k][2 * i + 1] - uy)));
      scale = fmax(scale, fmax(fabs(ux), fabs(uy)));
    }
  double dp = 0;
  for (mc_int j = 0; j < r.n; ++j) dp = fmax(dp, fabs(r.p[j] - p) / p);
  *err_p = dp, *err_u = du / scale, *err_res = r.residual;
  results_free(&r);
  host_body_free(&hb);
  free(ke), free(F);
  mc_destroy(m);
  scene_free(&s);
}

START_TEST(layered_orthotropic_host_body_patch_test) {
  double worst_p = 0, worst_u = 0, worst_res = 0;
  int n = 0;
  for (int k = 0; k < 5; ++k)
    for (int solver = MC_INTERFACE_CONDENSED; solver <= MC_INTERFACE_SPARSE; ++solver, ++n) {
      /* the mortar methods: node-to-segment does not pass patch tests across non-matching meshes */
      const int method = n % 2 == 1 ? MC_METHOD_DUAL_MORTAR : MC_METHOD_MORTAR;
      double ep, eu, er;
      layered_patch(kKinds[k], kKinds[(k + 3) % 5], method, solver, &ep, &eu, &er);
      printf("layered orthotropic %s host body%s on a mesh %s, %s, %s: pressure %.1e p, displacement %.1e, K u - f - r "
             "%.1e\n",
             cell_kind_name(kKinds[k]), kKinds[k] == 3 || kKinds[k] == 6 ? "" : " (two sub-layers per cell)",
             cell_kind_name(kKinds[(k + 3) % 5]), kMethodName[method], solver == MC_INTERFACE_SPARSE ? "sparse" : "condensed", ep,
             eu, er);
      worst_p = fmax(worst_p, ep), worst_u = fmax(worst_u, eu), worst_res = fmax(worst_res, er);
    }
  ck_assert_msg(worst_p <= 1e-10, "layered patch: pressure off by %g p", worst_p);
  ck_assert_msg(worst_u <= 1e-10, "layered patch: displacement off by %g", worst_u);
  ck_assert_msg(worst_res <= 1e-10, "layered patch: K u - f - r = %g", worst_res);
}
END_TEST

/* ---- bad input ------------------------------------------------------------------------------------- */

/* A small valid scene for the error checks: the flat patch, P1, body 1 a host body (natural
   numbering, base 1), body 2 a mesh body. */
typedef struct small_host {
  scene_def s;
  double *ke, *F;
  host_body hb;
} small_host;

static void small_host_build(mc_model *m, small_host *sh) {
  flat_patch_scene(&sh->s, 3, 4, 0);
  sh->ke = element_matrices(&sh->s, 0);
  sh->F = consistent_load(&sh->s, 0, 1.0);
  OK(mc_set_index_base(m, 1));
  variant v = {1, IN_FULL, 0, NUM_NATURAL, 0, 0, 0};
  set_host_body(m, &sh->s, 0, sh->ke, sh->F, &v, &sh->hb, 1u);
  set_mesh_body(m, &sh->s, 1, 1, 1.0);
}

static void small_host_free(small_host *sh) {
  free(sh->ke), free(sh->F);
  host_body_free(&sh->hb);
  scene_free(&sh->s);
}

/* The reference answer of the small scene (mesh bodies), to show that failed calls added nothing. */
static void small_scene_reference(const scene_def *s, results *ref) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  for (int k = 0; k < 2; ++k) set_mesh_body(m, s, k, 0, 1.0);
  SUCCEEDS(mc_solve(m));
  host_body *none[2] = {NULL, NULL};
  *ref = read_results(m, s, none, 0);
  mc_destroy(m);
}

static void assert_same_as_reference(mc_model *m, small_host *sh, const char *after) {
  results ref;
  small_scene_reference(&sh->s, &ref);
  SUCCEEDS(mc_solve(m));
  host_body *host[2] = {&sh->hb, NULL};
  results got = read_results(m, &sh->s, host, 1);
  differences d = compare(&sh->s, &ref, &got);
  printf("after %s: host - mesh: u %.1e, p %.1e\n", after, d.u, d.p);
  ck_assert_msg(d.u <= 1e-10 && d.p <= 1e-10, "after %s: the answer changed (u %g, p %g)", after, d.u, d.p);
  results_free(&ref), results_free(&got);
}

/* ---- curved contact edges of host bodies, and messages naming the host's elements ----------------- */

/* The log lines of a model, kept for the assertions. */
typedef struct log_lines {
  char text[16384];
} log_lines;

static void keep_log_line(void *user_data, mc_log_level level, const char *message) {
  log_lines *log = user_data;
  const size_t used = strlen(log->text);
  (void)level;
  if (used + 2 >= sizeof log->text) return; /* full: later lines are dropped, never written past the end */
  strncat(log->text, message, sizeof log->text - used - 2);
  strcat(log->text, "\n");
}

/* Body 1's curved contact edges as a legacy program with Smith and Griffiths' 8-node
   quadrilateral hands them over: each side corner, middle, corner (host ids in base). */
static mc_int *corner_middle_corner_edges(const body_def *b, int base) {
  mc_int *edges = malloc(sizeof(mc_int) * 3 * (size_t)b->n_contact);
  for (mc_int e = 0; e < b->n_contact; ++e) {
    mc_int nodes[3];
    ck_assert_int_eq(edge_nodes(b, b->contact + 2 * e, nodes), 3);
    edges[3 * e] = nodes[0] + base, edges[3 * e + 1] = nodes[2] + base, edges[3 * e + 2] = nodes[1] + base;
  }
  return edges;
}

static double max_pressure_error(mc_model *m, double pressure, mc_int *count) {
  OK(mc_get_contact_count(m, count));
  double *p = malloc(sizeof(double) * (size_t)*count), worst = 0;
  OK(mc_get_contact_pressure(m, p));
  for (mc_int j = 0; j < *count; ++j) worst = fmax(worst, fabs(p[j] - pressure));
  free(p);
  return worst;
}

/* The trap of issue 31: a host Q8 body whose contact sides come corner, middle, corner. Every
   side reads so from the nodes' positions and none as (end, end, middle): taken, reordered and
   logged; the patch test's pressure (0.2) comes out as with the library's order. An edge list
   mixing the two orders is refused, naming an edge of each in base 1. */
START_TEST(host_corner_middle_corner_sides) {
  scene_def s;
  flat_patch_scene(&s, 8, 8, 0);
  double *ke = element_matrices(&s, 0), *F = consistent_load(&s, 0, 1.0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  log_lines log = {""};
  OK(mc_set_log_callback(m, keep_log_line, &log));
  OK(mc_set_index_base(m, 1));
  const variant v = {1, IN_ELEMENTS, 0, NUM_NATURAL, 0, 0, 0};
  host_body h;
  set_host_body(m, &s, 0, ke, F, &v, &h, 3u); /* (end, end, middle) */
  set_mesh_body(m, &s, 1, 1, 1.0);
  SUCCEEDS(mc_solve(m));
  mc_int n_right = 0, n_cmc = 0;
  const double right = max_pressure_error(m, 0.2, &n_right);
  ck_assert_msg(strstr(log.text, "corner, middle, corner") == NULL, "no reordering logged for the library's order");

  mc_int *cmc = corner_middle_corner_edges(&s.b[0], 1);
  SUCCEEDS(mc_set_contact_curved(m, 1, s.b[0].n_contact, cmc));
  printf("corner, middle, corner: log \"%s\"\n", log.text);
  ck_assert_msg(strstr(log.text, "were given as (corner, middle, corner)"), "the reordering is logged: %s", log.text);
  SUCCEEDS(mc_solve(m));
  const double reordered = max_pressure_error(m, 0.2, &n_cmc);
  printf("Q8 host body, patch pressure error: (end, end, middle) %.1e, (corner, middle, corner) %.1e; %d and %d "
         "positions\n", right, reordered, (int)n_right, (int)n_cmc);
  ck_assert_int_eq(n_cmc, n_right); /* (before: duplicated nodes in the contact list) */
  ck_assert_msg(right <= 1e-10 && reordered <= 1e-10, "patch pressure off: %g and %g", right, reordered);

  /* the first side in the library's order, the others not: refused, naming edges 2 and 1 */
  mc_int *mixed = corner_middle_corner_edges(&s.b[0], 1);
  mixed[1] = cmc[2], mixed[2] = cmc[1];
  FAILS(mc_set_contact_curved(m, 1, s.b[0].n_contact, mixed), MC_ERROR_CONTACT, "(end, end, middle)");
  printf("mixed orders: %s\n", mc_errmsg(m));
  char needle[160];
  snprintf(needle, sizeof needle, "edge 2 (edges(4:6) = (%d, %d, %d)): node %d is not between its ends %d and %d",
           (int)mixed[3], (int)mixed[4], (int)mixed[5], (int)mixed[5], (int)mixed[3], (int)mixed[4]);
  ck_assert_msg(strstr(mc_errmsg(m), needle), "message \"%s\" lacks \"%s\"", mc_errmsg(m), needle);
  snprintf(needle, sizeof needle, "would be (%d, %d, %d), but edge 1 (edges(1:3)", (int)mixed[3], (int)mixed[5],
           (int)mixed[4]);
  ck_assert_msg(strstr(mc_errmsg(m), needle), "message \"%s\" lacks \"%s\"", mc_errmsg(m), needle);
  SUCCEEDS(mc_solve(m)); /* the refused call changed nothing */
  ck_assert_double_le(max_pressure_error(m, 0.2, &n_cmc), 1e-10);
  free(cmc), free(mixed), free(ke), free(F);
  host_body_free(&h);
  scene_free(&s);
  mc_destroy(m);
}
END_TEST

/* Curved edges of a host body with no cells to check them against: the nodes' positions and
   roles are checked, messages in the model's index base (positions "edges[0..2]" in base 0,
   "edges(1:3)" in base 1). Nodes (0-based): 0 (0, 0), 1 (1, 0), 2 (2, 0), 3 (3, 0), 4 (4, 0) on
   a line, 5 (1, 0.2), 6 (1, 0.8), 7 (1, -0.2). */
START_TEST(host_curved_edges_checked) {
  const int base = _i;
  static const double xy[16] = {0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 1, 0.2, 1, 0.8, 1, -0.2};
  mc_int equations[16];
  for (int k = 0; k < 16; ++k) equations[k] = k + base;
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  if (base) OK(mc_set_index_base(m, 1));
  char needle[200];

  /* an equation number above the system: its position in the base ("equations[3]" or "(4)") */
  equations[3] = 16 + base;
  FAILS(mc_set_host_body(m, 1, 8, xy, equations, 16), MC_ERROR_ARGUMENT, AT("equations", 3, base));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), base ? "equations(4) = 17" : "equations[3] = 16"));
  printf("base %d, equation above the system: %s\n", base, mc_errmsg(m));
  equations[3] = 3 + base;
  SUCCEEDS(mc_set_host_body(m, 1, 8, xy, equations, 16));

#define IDS3(a, b, c) {(a) + base, (b) + base, (c) + base}
  /* the library's order; a middle off the chord as on a curved side (0.1 chord lengths) */
  const mc_int good[3] = IDS3(0, 2, 1), arc[3] = IDS3(0, 2, 5);
  SUCCEEDS(mc_set_contact_curved(m, 1, 1, good));
  SUCCEEDS(mc_set_contact_curved(m, 1, 1, arc));
  /* a middle beyond its ends: 3 at 1.5 of the chord 0 -> 2. (Read as corner, middle, corner, 2
     would lie at 0.67 of 0 -> 3, off the midpoint: not taken for the edge (0, 3) with middle 2.) */
  const mc_int beyond[3] = IDS3(0, 2, 3);
  FAILS(mc_set_contact_curved(m, 1, 1, beyond), MC_ERROR_CONTACT, "(end, end, middle)");
  printf("base %d, middle beyond its ends: %s\n", base, mc_errmsg(m));
  snprintf(needle, sizeof needle, "edge %d (%s = (%d, %d, %d)): node %d is not between its ends %d and %d", base,
           AT_RANGE("edges", 0, 2, base), base, 2 + base, 3 + base, 3 + base, base, 2 + base);
  ck_assert_msg(strstr(mc_errmsg(m), needle), "message \"%s\" lacks \"%s\"", mc_errmsg(m), needle);
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "projects at 1.5 of the chord"));
  /* a middle far off to one side: 6 over the chord 0 -> 2 at its midpoint, 0.4 chord lengths off
     it (a 90-degree arc's middle is 0.21 off, a 120-degree arc's 0.29; allowed 0.3) */
  const mc_int far_off[3] = IDS3(0, 2, 6);
  FAILS(mc_set_contact_curved(m, 1, 1, far_off), MC_ERROR_CONTACT, "lies 0.4 chord lengths off it");
  /* a node both a middle and an end: 1 is edge 1's middle and edge 2's end (2 the other way) */
  const mc_int both[6] = {base, 2 + base, 1 + base, 1 + base, 4 + base, 2 + base};
  FAILS(mc_set_contact_curved(m, 1, 2, both), MC_ERROR_CONTACT, "never both");
  printf("base %d, a middle that is also an end: %s\n", base, mc_errmsg(m));
  snprintf(needle, sizeof needle, "node %d is the middle of edge %d (%s", 1 + base, base, AT_RANGE("edges", 0, 2, base));
  ck_assert_msg(strstr(mc_errmsg(m), needle), "message \"%s\" lacks \"%s\"", mc_errmsg(m), needle);
  snprintf(needle, sizeof needle, "an end of edge %d (%s", 1 + base, AT_RANGE("edges", 3, 5, base));
  ck_assert_msg(strstr(mc_errmsg(m), needle), "message \"%s\" lacks \"%s\"", mc_errmsg(m), needle);
  /* a node the middle of two edges: 5 between 0 and 2 and between 7 and 6 */
  const mc_int twice[6] = {base, 2 + base, 5 + base, 7 + base, 6 + base, 5 + base};
  FAILS(mc_set_contact_curved(m, 1, 2, twice), MC_ERROR_CONTACT, "both have node");
  printf("base %d, a node the middle of two edges: %s\n", base, mc_errmsg(m));
  snprintf(needle, sizeof needle, "both have node %d as their middle", 5 + base);
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), needle));
  /* one edge given corner, middle, corner with its middle at the midpoint: taken as (0, 2, 1) */
  const mc_int cmc[3] = IDS3(0, 1, 2);
  SUCCEEDS(mc_set_contact_curved(m, 1, 1, cmc));
#undef IDS3
  mc_destroy(m);
}
END_TEST

/* An inverted element handed over by mc_add_element_matrices (its nodes clockwise: a program
   that integrates with the signed Jacobian gives the negated matrix) is named at the call,
   not found later as a bad diagonal at some equation; a negative diagonal given through
   coordinate entries is said to be one at mc_solve. A host body whose contact edges run with
   the body on their right: the message of surfaces that do not face each other names it. */
START_TEST(host_inverted_element_and_reversed_surface) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  small_host sh;
  small_host_build(m, &sh); /* base 1 */
  const body_def *b = &sh.s.b[0];
  const int nd = 2 * b->npc;
  mc_int eltptr[2] = {1, 1 + nd}, eltvar[6];
  double inverted[36];
  for (int l = 0; l < nd; ++l) eltvar[l] = host_number(&sh.hb, b->cells[l / 2], l % 2, 1);
  for (int k = 0; k < nd * nd; ++k) inverted[k] = -sh.ke[k]; /* cell 0, clockwise */
  FAILS(mc_add_element_matrices(m, 1, 1, eltptr, eltvar, inverted), MC_ERROR_MESH, "element 1 looks inverted");
  printf("inverted element: %s\n", mc_errmsg(m));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "clockwise"));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "not positive semidefinite"));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "at row 1 (a_elt(1), "));
  assert_same_as_reference(m, &sh, "a refused inverted element");

  /* body 1's contact edges reversed (the body on their right) */
  mc_int *reversed = malloc(sizeof(mc_int) * 2 * (size_t)b->n_contact);
  for (mc_int e = 0; e < b->n_contact; ++e)
    reversed[2 * e] = b->contact[2 * e + 1] + 1, reversed[2 * e + 1] = b->contact[2 * e] + 1;
  SUCCEEDS(mc_set_contact(m, 1, b->n_contact, reversed));
  FAILS(mc_solve(m), MC_ERROR_CONTACT, "do not face each other");
  printf("reversed host surface: %s\n", mc_errmsg(m));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "Body 1's surface looks reversed"));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "body 1's (0, 1) points away from body 2"));
  ck_assert_ptr_null(strstr(mc_errmsg(m), "Body 2's surface"));
  for (mc_int e = 0; e < b->n_contact; ++e)
    reversed[2 * e] = b->contact[2 * e] + 1, reversed[2 * e + 1] = b->contact[2 * e + 1] + 1;
  SUCCEEDS(mc_set_contact(m, 1, b->n_contact, reversed));
  free(reversed);
  assert_same_as_reference(m, &sh, "the surface given the right way round");
  small_host_free(&sh);
  mc_destroy(m);
}
END_TEST

START_TEST(bad_host_input_is_refused_clearly) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  small_host sh;
  small_host_build(m, &sh);
  const body_def *b = &sh.s.b[0];
  const mc_int n_eq = sh.hb.n_eq, nn = b->n_nodes;
  mc_int *equations = malloc(sizeof(mc_int) * 2 * (size_t)nn);
  for (mc_int i = 0; i < nn; ++i) equations[2 * i] = host_number(&sh.hb, i, 0, 1), equations[2 * i + 1] = host_number(&sh.hb, i, 1, 1);

  /* mc_set_host_body: an equation number above n_equations, two freedoms sharing an equation */
  {
    mc_int *bad = malloc(sizeof(mc_int) * 2 * (size_t)nn);
    memcpy(bad, equations, sizeof(mc_int) * 2 * (size_t)nn);
    bad[7] = n_eq + 1; /* base 1: n_eq is the last */
    FAILS(mc_set_host_body(m, 1, nn, b->xy, bad, n_eq), MC_ERROR_ARGUMENT, "equations(8)");
    printf("equation above n_equations: %s\n", mc_errmsg(m));
    memcpy(bad, equations, sizeof(mc_int) * 2 * (size_t)nn);
    bad[9] = bad[5]; /* node 4's y shares node 2's y equation (nodes 5 and 3 with base 1) */
    FAILS(mc_set_host_body(m, 1, nn, b->xy, bad, n_eq), MC_ERROR_ARGUMENT, "equations(10)");
    printf("two freedoms on one equation: %s\n", mc_errmsg(m));
    ck_assert_msg(strstr(mc_errmsg(m), "node 5") && strstr(mc_errmsg(m), "node 3"), "the message names nodes 5 and 3: %s",
                  mc_errmsg(m));
    FAILS(mc_set_host_body(m, 1, nn, b->xy, equations, 0), MC_ERROR_ARGUMENT, "n_equations");
    FAILS(mc_set_host_body(m, 3, nn, b->xy, equations, n_eq), MC_ERROR_ARGUMENT, "body");
    free(bad);
  }
  /* the model is unchanged: the scene still solves to the reference */
  assert_same_as_reference(m, &sh, "refused mc_set_host_body calls");

  /* mc_add_stiffness: a number above the system, a NaN, an infinity, a TRIANGLE call mixing both
     triangles, a bad storage, a mesh body; each adds nothing */
  {
    const mc_int rows[4] = {1, 2, 2, 1}, cols[4] = {1, 2, 1, 2};
    double vals[4] = {1, 1, 0.5, 0.5};
    const mc_int above[4] = {1, 2, n_eq + 1, 1};
    FAILS(mc_add_stiffness(m, 1, 4, above, cols, vals, MC_MATRIX_FULL), MC_ERROR_ARGUMENT, "rows(3)");
    printf("row above the system: %s\n", mc_errmsg(m));
    const mc_int col_above[4] = {1, 2, 2, n_eq + 1};
    FAILS(mc_add_stiffness(m, 1, 4, rows, col_above, vals, MC_MATRIX_FULL), MC_ERROR_ARGUMENT, "cols(4)");
    vals[3] = NAN;
    FAILS(mc_add_stiffness(m, 1, 4, rows, cols, vals, MC_MATRIX_FULL), MC_ERROR_ARGUMENT, "values(4)");
    printf("NaN entry: %s\n", mc_errmsg(m));
    vals[3] = INFINITY;
    FAILS(mc_add_stiffness(m, 1, 4, rows, cols, vals, MC_MATRIX_TRIANGLE), MC_ERROR_ARGUMENT, "values(4)");
    vals[3] = 0.5;
    FAILS(mc_add_stiffness(m, 1, 4, rows, cols, vals, MC_MATRIX_TRIANGLE), MC_ERROR_ARGUMENT, "rows(4)");
    printf("TRIANGLE with both triangles: %s\n", mc_errmsg(m));
    FAILS(mc_add_stiffness(m, 1, 4, rows, cols, vals, 0), MC_ERROR_ARGUMENT, "storage");
    FAILS(mc_add_stiffness(m, 2, 4, rows, cols, vals, MC_MATRIX_FULL), MC_ERROR_STATE, NULL); /* a mesh body */
    printf("mc_add_stiffness on a mesh body: %s\n", mc_errmsg(m));
    /* one-triangle calls are fine in either triangle: the lower, then the upper undoing it */
    const mc_int r2[3] = {1, 2, 2}, c2[3] = {1, 2, 1};
    const double plus[3] = {1, 2, 0.5}, minus[3] = {-1, -2, -0.5};
    SUCCEEDS(mc_add_stiffness(m, 1, 3, r2, c2, plus, MC_MATRIX_TRIANGLE));
    SUCCEEDS(mc_add_stiffness(m, 1, 3, c2, r2, minus, MC_MATRIX_TRIANGLE));
  }
  assert_same_as_reference(m, &sh, "refused mc_add_stiffness calls");

  /* an asymmetric MC_MATRIX_FULL matrix: the two triangles are summed apart and compared when the
     stiffness is assembled (mc_solve), naming the two entries; repaired by adding what is missing */
  {
    const mc_int rows[4] = {1, 2, 2, 1}, cols[4] = {1, 2, 1, 2}, one_row = 1, one_col = 2;
    const double vals[4] = {1, 1, 0.5, 0.6}, undo[4] = {-1, -1, -0.5, -0.5}, missing = -0.1; /* (1,2) 0.6, (2,1) 0.5 */
    SUCCEEDS(mc_add_stiffness(m, 1, 4, rows, cols, vals, MC_MATRIX_FULL));
    FAILS(mc_solve(m), MC_ERROR_ARGUMENT, "MC_MATRIX_FULL");
    printf("asymmetric FULL: %s\n", mc_errmsg(m));
    ck_assert_msg(strstr(mc_errmsg(m), "(1, 2)") && strstr(mc_errmsg(m), "(2, 1)"), "the message names (1, 2) and (2, 1)");
    SUCCEEDS(mc_add_stiffness(m, 1, 1, &one_row, &one_col, &missing, MC_MATRIX_FULL));
    SUCCEEDS(mc_add_stiffness(m, 1, 4, rows, cols, undo, MC_MATRIX_FULL));
  }
  assert_same_as_reference(m, &sh, "an asymmetric MC_MATRIX_FULL matrix repaired");

  /* mc_add_element_matrices: eltptr not starting at the base, decreasing, an equation above the
     system, a non-finite or asymmetric element matrix */
  {
    /* (arrays longer than the elements need: a library reading them by a bad eltptr stays inside) */
    const mc_int eltvar[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    double a_elt[32] = {1, 0.5, 0.5, 1, 2, 0, 0, 2};
    const mc_int ptr_ok[3] = {1, 3, 5}, ptr_start[3] = {2, 3, 5}, ptr_down[3] = {1, 4, 3};
    FAILS(mc_add_element_matrices(m, 1, 2, ptr_start, eltvar, a_elt), MC_ERROR_ARGUMENT, "eltptr(1)");
    printf("eltptr[0] not the base: %s\n", mc_errmsg(m));
    FAILS(mc_add_element_matrices(m, 1, 2, ptr_down, eltvar, a_elt), MC_ERROR_ARGUMENT, "eltptr(3)");
    printf("eltptr decreasing: %s\n", mc_errmsg(m));
    const mc_int var_above[8] = {1, 2, 3, n_eq + 1, 5, 6, 7, 8};
    FAILS(mc_add_element_matrices(m, 1, 2, ptr_ok, var_above, a_elt), MC_ERROR_ARGUMENT, "eltvar(4)");
    a_elt[5] = NAN;
    FAILS(mc_add_element_matrices(m, 1, 2, ptr_ok, eltvar, a_elt), MC_ERROR_ARGUMENT, "a_elt(6)");
    a_elt[5] = 0.25; /* the second element's (1,0) = 0.25, its (0,1) = 0; with base 1 it is element 2 */
    FAILS(mc_add_element_matrices(m, 1, 2, ptr_ok, eltvar, a_elt), MC_ERROR_ARGUMENT, "a_elt(7) (element 2");
    printf("asymmetric element matrix: %s\n", mc_errmsg(m));
    FAILS(mc_add_element_matrices(m, 2, 2, ptr_ok, eltvar, a_elt), MC_ERROR_STATE, NULL);
  }
  assert_same_as_reference(m, &sh, "refused mc_add_element_matrices calls");

  /* the load vector: its length, a NaN */
  {
    double *f = malloc(sizeof(double) * (size_t)n_eq);
    memcpy(f, sh.hb.f, sizeof(double) * (size_t)n_eq);
    FAILS(mc_set_load_vector(m, 1, n_eq - 1, f), MC_ERROR_ARGUMENT, "n_equations");
    f[4] = NAN;
    FAILS(mc_set_load_vector(m, 1, n_eq, f), MC_ERROR_ARGUMENT, "f(5)");
    FAILS(mc_set_load_vector(m, 2, n_eq, sh.hb.f), MC_ERROR_STATE, NULL);
    free(f);
  }
  assert_same_as_reference(m, &sh, "refused mc_set_load_vector calls");

  /* a contact node without equations: node 1's (the bottom left corner, base 1) x is restrained;
     give it no y equation either */
  {
    mc_int *bad = malloc(sizeof(mc_int) * 2 * (size_t)nn);
    memcpy(bad, equations, sizeof(mc_int) * 2 * (size_t)nn);
    const mc_int corner = b->contact[0]; /* 0-based */
    ck_assert_int_lt(bad[2 * corner], 1);
    mc_model *m2 = NULL;
    ck_assert_int_eq(mc_create(&m2), MC_OK);
    {
      mc_model *m = m2;
      OK(mc_set_index_base(m, 1));
      bad[2 * corner + 1] = 0;
      /* the equation number it had is now no node's: fine for mc_set_host_body */
      SUCCEEDS(mc_set_host_body(m, 1, nn, b->xy, bad, n_eq));
      mc_int *edges = sc_ids(b->contact, 2 * b->n_contact, 1);
      FAILS(mc_set_contact(m, 1, b->n_contact, edges), MC_ERROR_CONTACT, "node 1");
      printf("contact node without equations: %s\n", mc_errmsg(m));
      SUCCEEDS(mc_set_contact(m, 1, b->n_contact - 1, edges + 2)); /* without that edge */
      /* an edge from a node to itself, an edge given twice (either way round) */
      const mc_int self[2] = {edges[2], edges[2]}, twice[4] = {edges[2], edges[3], edges[3], edges[2]};
      const mc_int curved_self[3] = {edges[2], edges[3], edges[2]};
      FAILS(mc_set_contact(m, 1, 1, self), MC_ERROR_CONTACT, "uses a node twice");
      FAILS(mc_set_contact_curved(m, 1, 1, curved_self), MC_ERROR_CONTACT, "uses a node twice");
      printf("curved edge using a node twice: %s\n", mc_errmsg(m));
      char needle[64];
      snprintf(needle, sizeof needle, "edge (%d, %d) is given twice", (int)(edges[2] < edges[3] ? edges[2] : edges[3]),
               (int)(edges[2] < edges[3] ? edges[3] : edges[2]));
      FAILS(mc_set_contact(m, 1, 2, twice), MC_ERROR_CONTACT, needle);
      FAILS(mc_solve(m), MC_ERROR_STATE, "body 1 is a host body without stiffness");
      free(edges);
    }
    mc_destroy(m2);
    free(bad);
  }

  /* what a host body refuses */
  {
    const mc_int node = 2, edge[2] = {2, 3};
    const double zero2[2] = {0, 0}, one = 1, d[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    FAILS(mc_set_material(m, 1, 1, 0.3), MC_ERROR_STATE, "host");
    printf("mc_set_material on a host body: %s\n", mc_errmsg(m));
    FAILS(mc_set_cell_elasticity(m, 1, d), MC_ERROR_STATE, "host");
    FAILS(mc_fix(m, 1, 1, &node, MC_X, NULL), MC_ERROR_STATE, "host");
    printf("mc_fix on a host body: %s\n", mc_errmsg(m));
    FAILS(mc_add_traction(m, 1, 1, edge, zero2), MC_ERROR_STATE, "host");
    printf("mc_add_traction on a host body: %s\n", mc_errmsg(m));
    FAILS(mc_add_pressure(m, 1, 1, edge, &one), MC_ERROR_STATE, "host");
    FAILS(mc_set_body_force(m, 1, 0, -1), MC_ERROR_STATE, "host");
    SUCCEEDS(mc_solve(m));
    double *out = malloc(sizeof(double) * 4 * (size_t)(b->n_cells + nn));
    FAILS(mc_get_stress(m, 1, out), MC_ERROR_STATE, "host");
    printf("mc_get_stress on a host body: %s\n", mc_errmsg(m));
    FAILS(mc_get_nodal_stress(m, 1, out), MC_ERROR_STATE, "host");
    FAILS(mc_get_reaction(m, 1, out), MC_ERROR_STATE, "host");
    SUCCEEDS(mc_get_stress(m, 2, out)); /* the mesh body's are there */
    free(out);
  }
  assert_same_as_reference(m, &sh, "refused calls on a host body");

  /* a non-positive diagonal, reported at mc_solve naming the equation; repaired by adding back */
  {
    const mc_int e = sh.hb.eq[2 * 8 + 1] + 1; /* node 9's y (base 1) */
    double kee = 0;
    for (size_t k = 0; k < sh.hb.K.n; ++k)
      if (sh.hb.K.row[k] == e - 1 && sh.hb.K.col[k] == e - 1) kee += sh.hb.K.val[k];
    const double minus = -2 * kee, plus = 2 * kee;
    SUCCEEDS(mc_add_stiffness(m, 1, 1, &e, &e, &minus, MC_MATRIX_TRIANGLE));
    char needle[64];
    snprintf(needle, sizeof needle, "equation %d", (int)e);
    FAILS(mc_solve(m), MC_ERROR_SINGULAR, needle);
    printf("negative diagonal: %s\n", mc_errmsg(m));
    ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "negative diagonal")); /* said as such, with its likely cause */
    ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "inverted element"));
    SUCCEEDS(mc_add_stiffness(m, 1, 1, &e, &e, &plus, MC_MATRIX_FULL));
  }
  assert_same_as_reference(m, &sh, "a negative diagonal repaired");

  /* singular beyond the rigid modes: body 2 a host body with two more equations than its nodes
     name (an internal mode of the host's element), coupled as [[1, 1], [1, 1]]: positive
     diagonals, singular; repaired by adding 1 to the first */
  {
    mc_model *m2 = NULL, *keep = m;
    ck_assert_int_eq(mc_create(&m2), MC_OK);
    m = m2;
    OK(mc_set_index_base(m, 1));
    set_mesh_body(m, &sh.s, 0, 1, 1.0);
    double *ke2 = element_matrices(&sh.s, 1), *F2 = calloc(2 * (size_t)sh.s.b[1].n_nodes, sizeof(double));
    variant v = {1, IN_UPPER, 1, NUM_REVERSE, 0, 0, 2};
    host_body h2;
    set_host_body(m, &sh.s, 1, ke2, F2, &v, &h2, 5u);
    const mc_int e1 = h2.n_eq - 1, e2 = h2.n_eq; /* the two appended equations, base 1 */
    const mc_int er[3] = {e1, e2, e2}, ec[3] = {e1, e2, e1};
    const double ev[3] = {1, 1, 1}, one = 1;
    SUCCEEDS(mc_add_stiffness(m, 2, 3, er, ec, ev, MC_MATRIX_TRIANGLE));
    char n1[32], n2[32];
    snprintf(n1, sizeof n1, "equation %d", (int)e1), snprintf(n2, sizeof n2, "equation %d", (int)e2);
    for (int solver = MC_INTERFACE_CONDENSED; solver <= MC_INTERFACE_SPARSE; ++solver) {
      OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver));
      FAILS(mc_solve(m), MC_ERROR_SINGULAR, "equation");
      printf("singular beyond the rigid modes (%s): %s\n", solver == MC_INTERFACE_SPARSE ? "sparse" : "condensed",
             mc_errmsg(m));
      ck_assert_msg(strstr(mc_errmsg(m), n1) || strstr(mc_errmsg(m), n2), "the message names %s or %s", n1, n2);
    }
    SUCCEEDS(mc_add_stiffness(m, 2, 1, &e1, &e1, &one, MC_MATRIX_FULL));
    SUCCEEDS(mc_solve(m));
    host_body_free(&h2);
    free(ke2), free(F2);
    m = keep;
    mc_destroy(m2);
  }

  free(equations);
  small_host_free(&sh);
  mc_destroy(m);
}
END_TEST

int main(void) {
  Suite *s = suite_create("host bodies");
  TCase *tc = tcase_create("same as mesh bodies");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, flat_patch_host_equals_mesh);
  tcase_add_test(tc, axisymmetric_flat_patch_host_equals_mesh);
  tcase_add_test(tc, hertz_host_equals_mesh);
  tcase_add_test(tc, layered_orthotropic_host_body_patch_test);
  suite_add_tcase(s, tc);
  TCase *edges = tcase_create("host contact edges and host elements");
  tcase_set_timeout(edges, 120);
  tcase_add_test(edges, host_corner_middle_corner_sides);
  tcase_add_loop_test(edges, host_curved_edges_checked, 0, 2);
  tcase_add_test(edges, host_inverted_element_and_reversed_surface);
  suite_add_tcase(s, edges);
  TCase *bad = tcase_create("bad input");
  tcase_set_timeout(bad, 120);
  tcase_add_test(bad, bad_host_input_is_refused_clearly);
  suite_add_tcase(s, bad);
  return sc_run_suite(s);
}
