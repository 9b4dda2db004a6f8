/*
 * assemblies.c - assemblies of three bodies (issue 32) against closed forms, as convergence
 * tables (docs/convergence.md, "Assemblies: closed forms").
 *
 * 1. Three concentric cylinders shrunk together (Lame). Radii 10, 15, 20, 25, radial
 *    interference delta = 0.01 at r = 15 and at r = 20 (gap offsets -delta on the non-mortar
 *    side, the meshes touch), E = 210000, nu = 0.3, Q1 cells, non-matching at both interfaces.
 *    - plane strain: quarter rings (u_x = 0 on x = 0, u_y = 0 on y = 0);
 *    - axisymmetric (x = r): a slice 0 <= z <= 5 of each cylinder with both axial faces on
 *      rollers (u_z = 0), i.e. eps_z = 0: the long cylinder in plane strain, so the closed form
 *      is the same as in plane strain. (A thin disc with free faces would be plane stress:
 *      p1 = 42.13, p2 = 26.25, printed for comparison, not what this model represents.)
 *    Pairs: inner on middle (pair 1, non-mortar the inner cylinder's outside), middle on outer
 *    (pair 2); the middle cylinder is mortar in one pair and non-mortar in the other. Each
 *    cylinder is held radially by contact alone.
 *    The closed form: sigma_r = A - B / r^2 in each cylinder, u = (1 + nu) / E ((1 - 2 nu) A r +
 *    B / r) (plane strain), p1 and p2 from u_outer(r_k) - u_inner(r_k) = delta_k (k = 1, 2).
 * 2. A roller between two plates (plane strain). A disc R = 10 between two plates 80 wide and 40
 *    thick, E = 210000, nu = 0.3 for all three, P = 1000 per unit length pushing the top plate
 *    down (a uniform traction on its top), the bottom plate on rollers at its bottom. Hertz at
 *    both contacts (E* = E / (2 (1 - nu^2)), a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a)) and
 *    the disc's centre stresses of the Brazilian test (sigma_xx = 2 P / (pi D), sigma_yy =
 *    -6 P / (pi D), Timoshenko and Goodier; the contact widths change them by O((a/R)^2) ~ 1e-3).
 *    Symmetry: only x >= 0 is modelled (u_x = 0 on x = 0 in all three bodies, P / 2 on the half
 *    plate). It also holds the disc's rotation, which frictionless plates leave free; the disc
 *    and the top plate are held vertically by contact alone. Meshes: the shared Hertz scene's
 *    (examples/scenes/hertz_scene.h, P1, graded towards the contact point: fine zone of half-width
 *    0.1 R, growth 1.05), its half-disc mirrored into a disc graded at both poles, its block
 *    scaled by R into the bottom plate and mirrored into the top plate; plate spacing 1.37 h1.
 *    Reported: p0 (the pressure at the node on x = 0), a (from the second moment of the contact
 *    forces: a^2 / 4 for Hertz's profile), the centre's nodal stresses (mc_get_nodal_stress).
 *
 * usage: assemblies [--quick] [lame|roller ...]
 *   --quick  coarse meshes only, and exit status 1 unless every error is below its bound (the
 *            bounds printed; ctest bench_assemblies_quick). Without it: the mesh sequences.
 */
#include "hertz_scene.h"
#include "mortarcontact.h"
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static const double YOUNG = 210000, NU = 0.3;

static int failures = 0;

#define CALL(call)                                                                 \
  do {                                                                             \
    if ((call) != MC_OK) {                                                         \
      fprintf(stderr, "assemblies: %s failed: %s\n", #call, mc_errmsg(m));         \
      exit(1);                                                                     \
    }                                                                              \
  } while (0)

/* A quick-mode bound: prints the check and counts a failure. */
static void bound(const char *what, double error, double limit) {
  const int ok = fabs(error) <= limit;
  printf("  %-48s |error| %.3f %% <= %.2f %%: %s\n", what, 100 * fabs(error), 100 * limit, ok ? "ok" : "FAILED");
  failures += !ok;
}

/* ---- three concentric cylinders ------------------------------------------------------------ */

static const double RADII[4] = {10, 15, 20, 25}, DELTA = 0.01, SLICE = 5;

/* Radial displacement at r of a Lame cylinder a <= r <= b under p_in inside and p_out outside:
   A = (p_in a^2 - p_out b^2) / (b^2 - a^2), B = (p_in - p_out) a^2 b^2 / (b^2 - a^2), then
   plane strain u = (1 + nu) / E ((1 - 2 nu) A r + B / r), plane stress u = ((1 - nu) A r +
   (1 + nu) B / r) / E. */
static double lame_u(double a, double b, double p_in, double p_out, double r, int plane_stress) {
  const double A = (p_in * a * a - p_out * b * b) / (b * b - a * a), B = (p_in - p_out) * a * a * b * b / (b * b - a * a);
  return plane_stress ? ((1 - NU) * A * r + (1 + NU) * B / r) / YOUNG
                      : (1 + NU) / YOUNG * ((1 - 2 * NU) * A * r + B / r);
}

/* The two interface pressures: the misfits u_outer(r_k) - u_inner(r_k) are linear in (p1, p2);
   their values for unit pressures give a 2 x 2 system, the right side the interferences. */
static void lame_pressures(int plane_stress, double p[2]) {
  double misfit[2][2]; /* misfit[k][j]: at interface k for p_j = 1 */
  for (int j = 0; j < 2; ++j) {
    const double p1 = j == 0, p2 = j == 1;
    misfit[0][j] = lame_u(RADII[1], RADII[2], p1, p2, RADII[1], plane_stress) - lame_u(RADII[0], RADII[1], 0, p1, RADII[1], plane_stress);
    misfit[1][j] = lame_u(RADII[2], RADII[3], p2, 0, RADII[2], plane_stress) - lame_u(RADII[1], RADII[2], p1, p2, RADII[2], plane_stress);
  }
  const double det = misfit[0][0] * misfit[1][1] - misfit[0][1] * misfit[1][0];
  p[0] = (DELTA * misfit[1][1] - DELTA * misfit[0][1]) / det;
  p[1] = (misfit[0][0] * DELTA - misfit[1][0] * DELTA) / det;
}

/* (r, theta) -> (x, y), exactly on the axes at theta = 0 and pi / 2. */
static void to_polar(double *x, double *y, void *ctx) {
  (void)ctx;
  const double r = *x, t = *y;
  *x = t >= PI / 2 - 1e-14 ? 0 : r * cos(t);
  *y = t <= 1e-14 ? 0 : r * sin(t);
}

typedef struct lame_result {
  long dofs;
  int positions[2];
  double mean[2], worst[2]; /* per pair: mean pressure, largest |p_j / exact - 1| */
  double seconds;
} lame_result;

/* Level L: cylinder k has 2^L nr radial cells and 2^L nt[k] around (plane strain: quarter
   circle) or along z (axisymmetric), non-matching at both interfaces. */
static void lame_solve(int axisymmetric, int level, const double exact[2], lame_result *out) {
  static const int nt_plane[3] = {8, 11, 14}, nz_axi[3] = {3, 4, 5}, nr = 2;
  const int f = 1 << level;
  sc_mesh mesh[3];
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(1);
  CALL(mc_set_body_count(m, 3));
  if (axisymmetric) CALL(mc_set_plane(m, MC_AXISYMMETRIC, 0));
  for (int k = 0; k < 3; ++k) {
    const int ny = f * (axisymmetric ? nz_axi[k] : nt_plane[k]);
    if (sc_mesh_rect(&mesh[k], 4, f * nr, ny, RADII[k], 0, RADII[k + 1] - RADII[k], axisymmetric ? SLICE : PI / 2, 0, 1)) {
      fprintf(stderr, "assemblies: mesh of cylinder %d failed\n", k + 1);
      exit(1);
    }
    if (!axisymmetric) sc_mesh_map(&mesh[k], to_polar, NULL);
    CALL(sc_set_mesh(m, k + 1, &mesh[k], 0));
    CALL(mc_set_material(m, k + 1, YOUNG, NU));
    /* plane strain: y = 0 and x = 0 are symmetry lines; axisymmetric: both faces of the slice on
       rollers (eps_z = 0). Nothing holds a cylinder radially but contact. */
    CALL(sc_fix_side(m, k + 1, &mesh[k], SC_BOTTOM, MC_Y, 0));
    CALL(sc_fix_side(m, k + 1, &mesh[k], SC_TOP, axisymmetric ? MC_Y : MC_X, 0));
  }
  for (int k = 0; k < 2; ++k) {
    int pair;
    CALL(mc_add_contact_pair(m, k + 1, k + 2, &pair));
    CALL(mc_set_pair_surface(m, pair, k + 1, mesh[k].n_side_edges[SC_RIGHT], mesh[k].side_edges[SC_RIGHT]));
    CALL(mc_set_pair_surface(m, pair, k + 2, mesh[k + 1].n_side_edges[SC_LEFT], mesh[k + 1].side_edges[SC_LEFT]));
    const mc_int n = mesh[k].n_side_nodes[SC_RIGHT];
    double *offset = malloc(sizeof(double) * (size_t)n);
    for (mc_int j = 0; j < n; ++j) offset[j] = -DELTA;
    CALL(mc_set_pair_gap_offset(m, pair, n, mesh[k].side_nodes[SC_RIGHT], offset));
    free(offset);
  }
  CALL(mc_solve(m));
  int64_t dofs;
  CALL(mc_get_info_int(m, MC_INFO_DOFS, &dofs));
  CALL(mc_get_info_real(m, MC_INFO_TIME_TOTAL, &out->seconds));
  out->dofs = (long)dofs;
  for (int k = 0; k < 2; ++k) {
    mc_int n;
    CALL(mc_get_pair_contact_count(m, k + 1, &n));
    double *p = malloc(sizeof(double) * (size_t)n), sum = 0, worst = 0;
    CALL(mc_get_pair_contact(m, k + 1, MC_CONTACT_PRESSURE, p));
    for (mc_int j = 0; j < n; ++j) sum += p[j], worst = fmax(worst, fabs(p[j] / exact[k] - 1));
    out->positions[k] = (int)n, out->mean[k] = sum / n, out->worst[k] = worst;
    free(p);
  }
  mc_destroy(m);
  for (int k = 0; k < 3; ++k) sc_mesh_free(&mesh[k]);
}

static void lame_table(int axisymmetric, int quick) {
  double exact[2], thin_disc[2];
  lame_pressures(0, exact);
  lame_pressures(1, thin_disc);
  printf("\n### Three concentric cylinders shrunk together, %s\n\n", axisymmetric ? "axisymmetric (x = r, eps_z = 0)" : "plane strain (quarter rings)");
  printf("Lame (eps_z = 0): p1 = %.4f at r = 15, p2 = %.4f at r = 20", exact[0], exact[1]);
  printf(" (a thin disc, plane stress, would give %.4f and %.4f)\n\n", thin_disc[0], thin_disc[1]);
  if (!quick) {
    printf("| level | cells (radial x %s) per cylinder | DOFs | p1 mean | error | largest nodal error | p2 mean | error | "
           "largest nodal error | seconds |\n",
           axisymmetric ? "axial" : "around");
    printf("|---|---|---|---|---|---|---|---|---|---|\n");
  }
  const int levels = quick ? 1 : 5;
  for (int level = 0; level < levels; ++level) {
    lame_result o;
    lame_solve(axisymmetric, level, exact, &o);
    const int f = 1 << level;
    if (!quick) {
      printf("| %d | %dx%d, %dx%d, %dx%d | %ld | %.4f | %+.3f %% | %.3f %% | %.4f | %+.3f %% | %.3f %% | %.2f |\n", level,
             2 * f, f * (axisymmetric ? 3 : 8), 2 * f, f * (axisymmetric ? 4 : 11), 2 * f, f * (axisymmetric ? 5 : 14),
             o.dofs, o.mean[0], 100 * (o.mean[0] / exact[0] - 1), 100 * o.worst[0], o.mean[1],
             100 * (o.mean[1] / exact[1] - 1), 100 * o.worst[1], o.seconds);
      fflush(stdout);
    } else {
      printf("coarsest mesh (%ld DOFs): p1 %.4f, p2 %.4f\n", o.dofs, o.mean[0], o.mean[1]);
      /* bounds: about twice the errors measured on this mesh (docs/convergence.md) */
      bound("p1 (mean over the interface)", o.mean[0] / exact[0] - 1, axisymmetric ? 0.01 : 0.006);
      bound("p2 (mean over the interface)", o.mean[1] / exact[1] - 1, axisymmetric ? 0.01 : 0.006);
      bound("p1 at every node", o.worst[0], axisymmetric ? 0.01 : 0.04);
      bound("p2 at every node", o.worst[1], axisymmetric ? 0.01 : 0.04);
    }
  }
}

/* ---- a roller between two plates ---------------------------------------------------------- */

static const double ROLLER_R = 10, ROLLER_P = 1000, PLATE_HALF_WIDTH = 40;

typedef struct mesh {
  int n_nodes, n_cells, npc;
  double *xy;
  mc_int *cells;
} mesh;

typedef struct roller_scene {
  mesh body[3];                   /* disc, bottom plate, top plate */
  int n_edges[4]; mc_int *edges[4]; /* disc bottom arc, bottom plate top, disc top arc, top plate bottom */
  int n_axis[3]; mc_int *axis[3]; /* nodes on x = 0 */
  int n_bottom; mc_int *bottom;   /* bottom plate's bottom nodes */
  int n_top; mc_int *top_edges;   /* top plate's top edges */
  int centre;                     /* the disc's centre node */
} roller_scene;

/* Keeps the part x >= 0 of a mesh (x = 0 is a grid line of both Hertz meshes): new_id maps old
   ids to new ones or -1. */
static void keep_right_half(mesh *k, int *new_id) {
  int n = 0, kept = 0;
  for (int i = 0; i < k->n_nodes; ++i) new_id[i] = k->xy[2 * i] >= 0 ? n++ : -1;
  for (int c = 0; c < k->n_cells; ++c) {
    int left = 0;
    for (int v = 0; v < k->npc; ++v) left += k->xy[2 * k->cells[k->npc * c + v]] < 0;
    if (left) continue;
    for (int v = 0; v < k->npc; ++v) k->cells[k->npc * kept + v] = new_id[k->cells[k->npc * c + v]];
    ++kept;
  }
  for (int i = 0; i < k->n_nodes; ++i)
    if (new_id[i] >= 0) k->xy[2 * new_id[i]] = k->xy[2 * i], k->xy[2 * new_id[i] + 1] = k->xy[2 * i + 1];
  k->n_nodes = n, k->n_cells = kept;
}

static int keep_edges(mc_int *e, int n, const int *new_id) {
  int kept = 0;
  for (int j = 0; j < n; ++j)
    if (new_id[e[2 * j]] >= 0 && new_id[e[2 * j + 1]] >= 0) e[2 * kept] = new_id[e[2 * j]], e[2 * kept + 1] = new_id[e[2 * j + 1]], ++kept;
  return kept;
}

/* A copy of a Hertz mesh scaled by s. */
static mesh copy_scaled(const hertz_mesh *h, double s) {
  mesh k = {h->n_nodes, h->n_cells, h->nodes_per_cell, malloc(sizeof(double) * 2 * (size_t)h->n_nodes),
            malloc(sizeof(mc_int) * (size_t)(h->nodes_per_cell * h->n_cells))};
  for (int i = 0; i < 2 * h->n_nodes; ++i) k.xy[i] = s * h->xy[i];
  for (int i = 0; i < h->nodes_per_cell * h->n_cells; ++i) k.cells[i] = h->cells[i];
  return k;
}

/* Mirrors mesh k about y = y_m: nodes on y = y_m (exactly) are shared when merge is set (the
   disc's diameter), otherwise every node is copied. Cells are reversed (the mirror turns them
   clockwise). mirror[i]: the id of node i's image. Returns the merged or the mirrored mesh
   (merge: k's nodes first, then the images off the line). */
static mesh mirror_mesh(const mesh *k, double y_m, int merge, int *mirror) {
  mesh out;
  const int keep = merge ? k->n_nodes : 0;
  int n = keep;
  for (int i = 0; i < k->n_nodes; ++i) mirror[i] = merge && k->xy[2 * i + 1] == y_m ? i : n++;
  out.npc = k->npc, out.n_nodes = n, out.n_cells = (merge ? 2 : 1) * k->n_cells;
  out.xy = malloc(sizeof(double) * 2 * (size_t)n);
  out.cells = malloc(sizeof(mc_int) * (size_t)(out.npc * out.n_cells));
  if (merge) memcpy(out.xy, k->xy, sizeof(double) * 2 * (size_t)k->n_nodes);
  for (int i = 0; i < k->n_nodes; ++i) out.xy[2 * mirror[i]] = k->xy[2 * i], out.xy[2 * mirror[i] + 1] = 2 * y_m - k->xy[2 * i + 1];
  const int first = merge ? k->n_cells : 0;
  if (merge) memcpy(out.cells, k->cells, sizeof(mc_int) * (size_t)(k->npc * k->n_cells));
  for (int c = 0; c < k->n_cells; ++c)
    for (int v = 0; v < k->npc; ++v) out.cells[k->npc * (first + c) + v] = mirror[k->cells[k->npc * c + k->npc - 1 - v]];
  return out;
}

/* The edges' images (each reversed, to stay counter-clockwise). */
static mc_int *mirror_edges(const mc_int *e, int n, const int *mirror) {
  mc_int *out = malloc(sizeof(mc_int) * 2 * (size_t)n);
  for (int j = 0; j < n; ++j) out[2 * j] = mirror[e[2 * j + 1]], out[2 * j + 1] = mirror[e[2 * j]];
  return out;
}

static mc_int *nodes_where(const mesh *k, int coordinate, double value, int *n) {
  mc_int *ids = malloc(sizeof(mc_int) * (size_t)k->n_nodes);
  *n = 0;
  for (int i = 0; i < k->n_nodes; ++i)
    if (fabs(k->xy[2 * i + coordinate] - value) < 1e-12 * ROLLER_R) ids[(*n)++] = i;
  return ids;
}

/* h1: the disc's spacing at its poles over R; the plates' is 1.37 h1. */
static int roller_build(roller_scene *r, double h1) {
  hertz_scene hs;
  memset(r, 0, sizeof *r);
  /* growth 1.05, not the Hertz scene's 1.15: the centre stresses need cells at the centre
     smaller than about R / 20 (with 1.15 sigma_xx there stays 3 % off whatever h1) */
  if (hertz_scene_build_graded(&hs, h1, 1.37 * h1, 3, 1.05, 0.1)) return 1;
  int *new_id = malloc(sizeof(int) * (size_t)(hs.body[0].n_nodes + hs.body[1].n_nodes));
  /* the half-disc's part x >= 0, scaled: a quarter disc below its centre (0, R) */
  mesh quarter = copy_scaled(&hs.body[0], ROLLER_R);
  keep_right_half(&quarter, new_id);
  mc_int *arc = malloc(sizeof(mc_int) * 2 * (size_t)hs.n_contact_edges[0]);
  memcpy(arc, hs.contact_edges[0], sizeof(mc_int) * 2 * (size_t)hs.n_contact_edges[0]);
  const int n_arc = keep_edges(arc, hs.n_contact_edges[0], new_id);
  int *mirror = malloc(sizeof(int) * (size_t)quarter.n_nodes);
  r->body[0] = mirror_mesh(&quarter, ROLLER_R, 1, mirror);
  r->n_edges[0] = n_arc, r->edges[0] = arc;
  r->n_edges[2] = n_arc, r->edges[2] = mirror_edges(arc, n_arc, mirror);
  free(mirror), free(quarter.xy), free(quarter.cells);
  /* the plates: the block's part x >= 0 scaled by R (top at y = 0), and its mirror about y = R */
  r->body[1] = copy_scaled(&hs.body[1], ROLLER_R);
  keep_right_half(&r->body[1], new_id);
  mc_int *top = malloc(sizeof(mc_int) * 2 * (size_t)hs.n_contact_edges[1]);
  memcpy(top, hs.contact_edges[1], sizeof(mc_int) * 2 * (size_t)hs.n_contact_edges[1]);
  r->n_edges[1] = keep_edges(top, hs.n_contact_edges[1], new_id), r->edges[1] = top;
  mirror = malloc(sizeof(int) * (size_t)r->body[1].n_nodes);
  r->body[2] = mirror_mesh(&r->body[1], ROLLER_R, 0, mirror);
  r->n_edges[3] = r->n_edges[1], r->edges[3] = mirror_edges(top, r->n_edges[1], mirror);
  free(mirror);
  for (int b = 0; b < 3; ++b) r->axis[b] = nodes_where(&r->body[b], 0, 0, &r->n_axis[b]);
  r->bottom = nodes_where(&r->body[1], 1, -4 * ROLLER_R, &r->n_bottom);
  /* the top plate's top y = 6 R: its nodes sorted by x give its edges */
  int n_top;
  mc_int *top_nodes = nodes_where(&r->body[2], 1, 6 * ROLLER_R, &n_top);
  for (int i = 1; i < n_top; ++i)
    for (int k = i; k > 0 && r->body[2].xy[2 * top_nodes[k - 1]] > r->body[2].xy[2 * top_nodes[k]]; --k) {
      mc_int t = top_nodes[k];
      top_nodes[k] = top_nodes[k - 1], top_nodes[k - 1] = t;
    }
  r->n_top = n_top - 1;
  r->top_edges = malloc(sizeof(mc_int) * 2 * (size_t)r->n_top);
  for (int j = 0; j < r->n_top; ++j) r->top_edges[2 * j] = top_nodes[j + 1], r->top_edges[2 * j + 1] = top_nodes[j];
  free(top_nodes);
  r->centre = -1;
  for (int j = 0; j < r->n_axis[0]; ++j)
    if (r->body[0].xy[2 * r->axis[0][j] + 1] == ROLLER_R) r->centre = r->axis[0][j];
  free(new_id);
  hertz_scene_free(&hs);
  return r->centre < 0 || r->n_top < 1 || r->n_bottom < 2;
}

static void roller_free(roller_scene *r) {
  for (int b = 0; b < 3; ++b) free(r->body[b].xy), free(r->body[b].cells), free(r->axis[b]);
  for (int e = 0; e < 4; ++e) free(r->edges[e]);
  free(r->bottom), free(r->top_edges);
}

typedef struct roller_result {
  long dofs;
  double p0[2], a[2], force[2]; /* per contact: bottom (pair 1), top (pair 2); force: vertical, both halves */
  double sxx, syy, seconds;
} roller_result;

static void roller_solve(const roller_scene *r, roller_result *out) {
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(1);
  CALL(mc_set_body_count(m, 3));
  for (int b = 0; b < 3; ++b) {
    CALL(mc_set_mesh(m, b + 1, r->body[b].n_nodes, r->body[b].xy, r->body[b].n_cells, r->body[b].npc, r->body[b].cells));
    CALL(mc_set_material(m, b + 1, YOUNG, NU));
    CALL(mc_fix(m, b + 1, r->n_axis[b], r->axis[b], MC_X, NULL)); /* the symmetry plane x = 0 */
  }
  CALL(mc_fix(m, 2, r->n_bottom, r->bottom, MC_Y, NULL));
  double *traction = malloc(sizeof(double) * 2 * (size_t)r->n_top);
  for (int j = 0; j < r->n_top; ++j) traction[2 * j] = 0, traction[2 * j + 1] = -0.5 * ROLLER_P / PLATE_HALF_WIDTH;
  CALL(mc_add_traction(m, 3, r->n_top, r->top_edges, traction));
  free(traction);
  /* the disc is the non-mortar side of both contacts (its arcs are finer than the plates) */
  for (int k = 0; k < 2; ++k) {
    int pair;
    CALL(mc_add_contact_pair(m, 1, k + 2, &pair));
    CALL(mc_set_pair_surface(m, pair, 1, r->n_edges[2 * k], r->edges[2 * k]));
    CALL(mc_set_pair_surface(m, pair, k + 2, r->n_edges[2 * k + 1], r->edges[2 * k + 1]));
  }
  CALL(mc_solve(m));
  int64_t dofs;
  CALL(mc_get_info_int(m, MC_INFO_DOFS, &dofs));
  CALL(mc_get_info_real(m, MC_INFO_TIME_TOTAL, &out->seconds));
  out->dofs = (long)dofs;
  for (int k = 0; k < 2; ++k) {
    mc_int n;
    CALL(mc_get_pair_contact_count(m, k + 1, &n));
    mc_int *nodes = malloc(sizeof(mc_int) * (size_t)n);
    double *p = malloc(sizeof(double) * (size_t)n), *f = malloc(sizeof(double) * (size_t)n),
           *normal = malloc(sizeof(double) * 2 * (size_t)n), m0 = 0, m2 = 0, vertical = 0;
    CALL(mc_get_pair_contact_nodes(m, k + 1, nodes));
    CALL(mc_get_pair_contact(m, k + 1, MC_CONTACT_NORMAL, normal));
    CALL(mc_get_pair_contact(m, k + 1, MC_CONTACT_PRESSURE, p));
    CALL(mc_get_pair_contact(m, k + 1, MC_CONTACT_FORCE, f));
    out->p0[k] = NAN;
    for (mc_int j = 0; j < n; ++j) {
      const double x = r->body[0].xy[2 * nodes[j]];
      if (x == 0) out->p0[k] = p[j];
      m0 += f[j], m2 += f[j] * x * x, vertical += f[j] * fabs(normal[2 * j + 1]);
    }
    /* on the half model the node on x = 0 carries half its force, as the full model's
       symmetric sum would count it: the moment ratio is the full contact's */
    out->a[k] = 2 * sqrt(m2 / m0), out->force[k] = 2 * vertical;
    free(nodes), free(p), free(f), free(normal);
  }
  double *sigma = malloc(sizeof(double) * 4 * (size_t)r->body[0].n_nodes);
  CALL(mc_get_nodal_stress(m, 1, sigma));
  out->sxx = sigma[4 * r->centre], out->syy = sigma[4 * r->centre + 1];
  free(sigma);
  mc_destroy(m);
}

static void roller_table(int quick) {
  const double e_star = YOUNG / (2 * (1 - NU * NU)), a = sqrt(4 * ROLLER_P * ROLLER_R / (PI * e_star)),
               p0 = 2 * ROLLER_P / (PI * a), sxx = 2 * ROLLER_P / (PI * 2 * ROLLER_R), syy = -6 * ROLLER_P / (PI * 2 * ROLLER_R);
  printf("\n### A roller between two plates, plane strain\n\n");
  printf("Hertz: E* = %.0f, a = %.4f, p0 = %.1f; disc centre: sigma_xx = %+.2f, sigma_yy = %+.2f\n\n", e_star, a, p0, sxx, syy);
  if (!quick) {
    printf("| h1 (disc, at the poles) | a / h1 | DOFs | p0 bottom | error | p0 top | error | a bottom | error | a top | error | "
           "centre sigma_xx | error | centre sigma_yy | error | contact force / P | seconds |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  }
  static const double full[] = {0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625}, coarse[] = {0.005};
  const double *h = quick ? coarse : full;
  const int n = quick ? 1 : 6;
  for (int level = 0; level < n; ++level) {
    roller_scene r;
    if (roller_build(&r, h[level])) {
      fprintf(stderr, "assemblies: roller meshes failed at h1 = %g\n", h[level]);
      exit(1);
    }
    roller_result o;
    roller_solve(&r, &o);
    roller_free(&r);
    const double force = 0.5 * (o.force[0] + o.force[1]) / ROLLER_P;
    if (!quick) {
      printf("| %.4g | %.1f | %ld | %.1f | %+.2f %% | %.1f | %+.2f %% | %.4f | %+.2f %% | %.4f | %+.2f %% | %+.2f | %+.2f %% | "
             "%+.2f | %+.2f %% | %.6f | %.2f |\n",
             h[level] * ROLLER_R, a / (h[level] * ROLLER_R), o.dofs, o.p0[0], 100 * (o.p0[0] / p0 - 1), o.p0[1],
             100 * (o.p0[1] / p0 - 1), o.a[0], 100 * (o.a[0] / a - 1), o.a[1], 100 * (o.a[1] / a - 1), o.sxx,
             100 * (o.sxx / sxx - 1), o.syy, 100 * (o.syy / syy - 1), force, o.seconds);
      fflush(stdout);
    } else {
      printf("h1 = %g (%ld DOFs): p0 %.1f and %.1f, a %.4f and %.4f, centre %+.2f %+.2f\n", h[level] * ROLLER_R, o.dofs,
             o.p0[0], o.p0[1], o.a[0], o.a[1], o.sxx, o.syy);
      /* bounds: about twice the errors measured on this mesh (docs/convergence.md) */
      bound("p0, bottom contact", o.p0[0] / p0 - 1, 0.03);
      bound("p0, top contact", o.p0[1] / p0 - 1, 0.03);
      bound("a, bottom contact", o.a[0] / a - 1, 0.03);
      bound("a, top contact", o.a[1] / a - 1, 0.03);
      bound("centre sigma_xx", o.sxx / sxx - 1, 0.02);
      bound("centre sigma_yy", o.syy / syy - 1, 0.005);
      /* each contact carries the whole load (to round-off: the iteration's tolerance) */
      bound("contact forces / P", force - 1, 1e-8);
    }
  }
}

int main(int argc, char **argv) {
  int quick = 0, lame = 0, roller = 0;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--quick")) quick = 1;
    else if (!strcmp(argv[i], "lame")) lame = 1;
    else if (!strcmp(argv[i], "roller")) roller = 1;
    else {
      fprintf(stderr, "usage: assemblies [--quick] [lame|roller ...]\n");
      return 2;
    }
  }
  if (!lame && !roller) lame = roller = 1;
  if (lame) lame_table(0, quick), lame_table(1, quick);
  if (roller) roller_table(quick);
  if (quick) printf("\n%s\n", failures ? "FAILED: an error above its bound" : "all errors below their bounds");
  return failures ? 1 : 0;
}
