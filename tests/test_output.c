/*
 * test_output.c - what the library hands to the outside besides result arrays:
 *
 * - mc_write_vtu: the VTK XML files of a solved contact scene parse (a small structural
 *   reader: balanced tags, declared counts, exact number of values per array) and hold exactly
 *   the values the result getters return (numbers are written with 17 digits: bit-exact);
 *   the .pvd variant writes a collection and one file per body; no inf/nan reaches a file;
 *   errors: before a solve, after the scene changed, unwritable path, NULL arguments; the
 *   friction fields (shear, slip, slip_total, state) of every non-mortar contact node, frictionless
 *   (no shear; contact slips or is open) and in a frictional slip patch test (every
 *   node slips with shear -mu p; slip and accumulated slip after one and after two solves).
 * - mc_set_log_callback: phase and iteration messages reach the callback with its user_data,
 *   one line each, with the phase times; the iteration messages match MC_INFO_ITERATIONS and
 *   MC_INFO_COMPLEMENTARITY; a load step reports reuse and no factorization; removing the
 *   callback stops the calls.
 *
 * The files are written into the working directory (ctest: the build's tests/ directory).
 * tests/test_output_meshio.py reads such files with meshio.
 */
#include "check_helpers.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the scene ------------------------------------------------------------------------- */

/* Body 1 = [-0.25,1.25]x[0,0.5] (P1) rests on body 2 = [0,1]x[-0.5,0] (Q1): mixed cell types
   in one file, and body-1 contact nodes beyond body 2's ends that see no mortar surface (gap
   +infinity in the API). A parabolic clearance (x - 1/2)^2 (gap offsets) makes only the middle touch, so
   there are active and inactive nodes. Body 1 is held by contact alone vertically. */
typedef struct scene {
  sc_mesh mesh[2];
  mc_model *m;
} scene;

static void scene_build(scene *s) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  s->m = m;
  ck_assert_int_eq(sc_mesh_rect(&s->mesh[0], 3, 12, 4, -0.25, 0, 1.5, 0.5, 0, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&s->mesh[1], 4, 7, 3, 0, -0.5, 1, 0.5, 0.1, 2), 0);
  for (int b = 0; b < 2; ++b) OK(sc_set_mesh(m, b + 1, &s->mesh[b], 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  OK(mc_set_material(m, 2, 2, 0.25));
  OK(sc_fix_side(m, 1, &s->mesh[0], SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &s->mesh[1], SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &s->mesh[1], SC_BOTTOM, MC_Y, 0));
  OK(mc_set_contact(m, 1, s->mesh[0].n_side_edges[SC_BOTTOM], s->mesh[0].side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, s->mesh[1].n_side_edges[SC_TOP], s->mesh[1].side_edges[SC_TOP]));
  OK(mc_set_body_force(m, 1, 0, -0.05));
  const sc_mesh *b1 = &s->mesh[0];
  const mc_int n = b1->n_side_nodes[SC_BOTTOM];
  double *offset = malloc(sizeof(double) * n);
  for (mc_int k = 0; k < n; ++k) {
    double x = b1->xy[2 * b1->side_nodes[SC_BOTTOM][k]];
    offset[k] = 1.0 * (x - 0.5) * (x - 0.5);
  }
  OK(mc_set_gap_offset(m, n, b1->side_nodes[SC_BOTTOM], offset));
  free(offset);
}

static void scene_free(scene *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->mesh[0]);
  sc_mesh_free(&s->mesh[1]);
}

/* What the getters return after a solve. */
typedef struct results {
  double *u[2], *stress[2], *nodal_stress[2];
  mc_int n_contact, *contact_nodes;
  double *pressure, *force, *gap, *gap0;
  double *shear, *slip, *slip_total, *state; /* mc_get_pair_contact of pair 1 */
} results;

static results results_get(const scene *s) {
  mc_model *m = s->m;
  results r;
  for (int b = 0; b < 2; ++b) {
    r.u[b] = malloc(sizeof(double) * 2 * s->mesh[b].n_nodes);
    r.stress[b] = malloc(sizeof(double) * 4 * s->mesh[b].n_cells);
    r.nodal_stress[b] = malloc(sizeof(double) * 4 * s->mesh[b].n_nodes);
    OK(mc_get_displacement(m, b + 1, r.u[b]));
    OK(mc_get_stress(m, b + 1, r.stress[b]));
    OK(mc_get_nodal_stress(m, b + 1, r.nodal_stress[b]));
  }
  OK(mc_get_contact_count(m, &r.n_contact));
  r.contact_nodes = malloc(sizeof(mc_int) * r.n_contact);
  r.pressure = malloc(sizeof(double) * r.n_contact);
  r.force = malloc(sizeof(double) * r.n_contact);
  r.gap = malloc(sizeof(double) * r.n_contact);
  r.gap0 = malloc(sizeof(double) * r.n_contact);
  OK(mc_get_contact_nodes(m, r.contact_nodes));
  OK(mc_get_contact_pressure(m, r.pressure));
  OK(mc_get_contact_force(m, r.force));
  OK(mc_get_contact_gap(m, r.gap));
  OK(mc_get_contact_initial_gap(m, r.gap0));
  double **friction[4] = {&r.shear, &r.slip, &r.slip_total, &r.state};
  const int field[4] = {MC_CONTACT_SHEAR, MC_CONTACT_SLIP, MC_CONTACT_SLIP_TOTAL, MC_CONTACT_STATE};
  for (int k = 0; k < 4; ++k) {
    *friction[k] = malloc(sizeof(double) * r.n_contact);
    OK(mc_get_pair_contact(m, 1, field[k], *friction[k]));
  }
  return r;
}

static void results_free(results *r) {
  for (int b = 0; b < 2; ++b) free(r->u[b]), free(r->stress[b]), free(r->nodal_stress[b]);
  free(r->contact_nodes), free(r->pressure), free(r->force), free(r->gap), free(r->gap0);
  free(r->shear), free(r->slip), free(r->slip_total), free(r->state);
}

/* ---- a small structural reader of the VTK XML files ------------------------------------- */

static char *slurp(const char *path) {
  FILE *f = fopen(path, "rb");
  ck_assert_msg(f != NULL, "cannot open %s", path);
  fseek(f, 0, SEEK_END);
  long size = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *text = malloc((size_t)size + 1);
  ck_assert_int_eq(fread(text, 1, (size_t)size, f), (size_t)size);
  text[size] = '\0';
  fclose(f);
  return text;
}

static int file_exists(const char *path) {
  FILE *f = fopen(path, "rb");
  if (f) fclose(f);
  return f != NULL;
}

static int count_of(const char *text, const char *needle) {
  int n = 0;
  for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle)) ++n;
  return n;
}

/* A case-insensitive search for a lowercase needle. */
static int contains_nocase(const char *text, const char *needle) {
  size_t n = strlen(needle);
  for (const char *p = text; *p; ++p) {
    size_t k = 0;
    while (k < n && p[k] && tolower((unsigned char)p[k]) == needle[k]) ++k;
    if (k == n) return 1;
  }
  return 0;
}

/* Every element of the VTK unstructured-grid layout opens and closes exactly once, nested in
   order; there are `arrays` DataArrays, each closed. */
static void check_structure(const char *xml, int arrays) {
  static const char *const open[] = {"<VTKFile ", "<UnstructuredGrid>", "<Piece ", "<PointData ",
                                     "<CellData ", "<Points>", "<Cells>"};
  static const char *const close[] = {"</VTKFile>", "</UnstructuredGrid>", "</Piece>", "</PointData>",
                                      "</CellData>", "</Points>", "</Cells>"};
  ck_assert_msg(strncmp(xml, "<?xml version=\"1.0\"?>\n", 22) == 0, "no XML declaration");
  ck_assert_ptr_nonnull(strstr(xml, "<VTKFile type=\"UnstructuredGrid\""));
  for (int e = 0; e < 7; ++e) {
    ck_assert_msg(count_of(xml, open[e]) == 1 && count_of(xml, close[e]) == 1, "%s: %d open, %d close", open[e],
                  count_of(xml, open[e]), count_of(xml, close[e]));
    ck_assert_msg(strstr(xml, open[e]) < strstr(xml, close[e]), "%s closes before it opens", open[e]);
  }
  for (int e = 1; e < 3; ++e) /* VTKFile > UnstructuredGrid > Piece > (the sections) */
    ck_assert(strstr(xml, open[e - 1]) < strstr(xml, open[e]) && strstr(xml, close[e]) < strstr(xml, close[e - 1]));
  for (int e = 3; e < 7; ++e)
    ck_assert(strstr(xml, open[2]) < strstr(xml, open[e]) && strstr(xml, close[e]) < strstr(xml, close[2]));
  ck_assert_int_eq(count_of(xml, "<DataArray "), arrays);
  ck_assert_int_eq(count_of(xml, "</DataArray>"), arrays);
  /* ParaView and meshio cannot read inf or nan: none is written (no name contains them) */
  ck_assert_msg(!contains_nocase(xml, "inf") && !contains_nocase(xml, "nan"), "a non-finite number in the file");
}

/* The integer value of attribute `name` of the first element that has it. */
static long attribute(const char *xml, const char *name) {
  char pattern[64];
  snprintf(pattern, sizeof pattern, " %s=\"", name);
  const char *p = strstr(xml, pattern);
  ck_assert_msg(p != NULL, "no attribute %s", name);
  return strtol(p + strlen(pattern), NULL, 10);
}

/* Reads DataArray `name`: checks its type and component count and that it holds exactly n
   numbers; returns them (caller frees). */
static double *data_array(const char *xml, const char *name, const char *type, int components, long n) {
  char pattern[128];
  snprintf(pattern, sizeof pattern, "Name=\"%s\"", name);
  const char *p = strstr(xml, pattern);
  ck_assert_msg(p != NULL, "no DataArray %s", name);
  ck_assert_msg(count_of(xml, pattern) == 1, "DataArray %s twice", name);
  const char *start = p;
  while (start > xml && strncmp(start, "<DataArray", 10) != 0) --start;
  const char *end_tag = strchr(p, '>');
  char want[128];
  snprintf(want, sizeof want, "type=\"%s\"", type);
  ck_assert_msg(strstr(start, want) && strstr(start, want) < end_tag, "DataArray %s: not %s", name, type);
  snprintf(want, sizeof want, "NumberOfComponents=\"%d\"", components);
  if (components > 1)
    ck_assert_msg(strstr(start, want) && strstr(start, want) < end_tag, "DataArray %s: not %d components", name,
                  components);
  ck_assert_msg(strstr(start, "format=\"ascii\"") < end_tag, "DataArray %s: not ascii", name);
  double *v = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
  char *q = (char *)end_tag + 1;
  for (long k = 0; k < n; ++k) {
    char *next;
    v[k] = strtod(q, &next);
    ck_assert_msg(next != q, "DataArray %s: %ld values, expected %ld", name, k, n);
    q = next;
  }
  while (isspace((unsigned char)*q)) ++q;
  ck_assert_msg(strncmp(q, "</DataArray>", 12) == 0, "DataArray %s: more than %ld values", name, n);
  return v;
}

/* ---- checks of one piece against the getters ------------------------------------------- */

/* The piece of `xml` holds bodies first..last (0-based) of the scene. */
static void check_piece(const char *xml, const scene *s, const results *r, int first, int last) {
  long n_points = 0, n_cells = 0;
  for (int b = first; b <= last; ++b) n_points += s->mesh[b].n_nodes, n_cells += s->mesh[b].n_cells;
  check_structure(xml, 18);
  ck_assert_int_eq(attribute(xml, "NumberOfPoints"), n_points);
  ck_assert_int_eq(attribute(xml, "NumberOfCells"), n_cells);

  double *u = data_array(xml, "displacement", "Float64", 3, 3 * n_points);
  double *ns = data_array(xml, "nodal_stress", "Float64", 4, 4 * n_points);
  double *x = data_array(xml, "coordinates", "Float64", 3, 3 * n_points);
  double *p = data_array(xml, "pressure", "Float64", 1, n_points);
  double *g = data_array(xml, "gap", "Float64", 1, n_points);
  double *g0 = data_array(xml, "initial_gap", "Float64", 1, n_points);
  double *active = data_array(xml, "active", "Int32", 1, n_points);
  double *contact = data_array(xml, "contact", "Int32", 1, n_points);
  double *shear = data_array(xml, "shear", "Float64", 1, n_points);
  double *slip = data_array(xml, "slip", "Float64", 1, n_points);
  double *slip_total = data_array(xml, "slip_total", "Float64", 1, n_points);
  double *state = data_array(xml, "state", "Int32", 1, n_points);
  double *stress = data_array(xml, "stress", "Float64", 4, 4 * n_cells);
  double *vm = data_array(xml, "von_mises", "Float64", 1, n_cells);
  double *body = data_array(xml, "body", "Int32", 1, n_cells);
  double *types = data_array(xml, "types", "UInt8", 1, n_cells);
  double *offsets = data_array(xml, "offsets", "Int64", 1, n_cells);
  long n_connectivity = 0;
  for (int b = first; b <= last; ++b) n_connectivity += (long)s->mesh[b].npc * s->mesh[b].n_cells;
  double *conn = data_array(xml, "connectivity", "Int64", 1, n_connectivity);

  long point = 0, cell = 0, k = 0, offset = 0;
  for (int b = first; b <= last; ++b) {
    const sc_mesh *mesh = &s->mesh[b];
    for (mc_int i = 0; i < mesh->n_nodes; ++i, ++point) {
      /* bit-exact: 17 significant digits read back to the same double */
      ck_assert_msg(u[3 * point] == r->u[b][2 * i] && u[3 * point + 1] == r->u[b][2 * i + 1] && u[3 * point + 2] == 0,
                    "body %d node %d: displacement (%.17g, %.17g) in the file, (%.17g, %.17g) from the API", b + 1,
                    (int)i, u[3 * point], u[3 * point + 1], r->u[b][2 * i], r->u[b][2 * i + 1]);
      ck_assert(x[3 * point] == mesh->xy[2 * i] && x[3 * point + 1] == mesh->xy[2 * i + 1] && x[3 * point + 2] == 0);
      for (int k = 0; k < 4; ++k)
        ck_assert_msg(ns[4 * point + k] == r->nodal_stress[b][4 * i + k], "body %d node %d: nodal stress %d", b + 1,
                      (int)i, k);
      if (b == 1) /* body 2 carries no contact fields */
        ck_assert(p[point] == 0 && g[point] == 0 && g0[point] == 0 && active[point] == 0 && contact[point] == 0 &&
                  shear[point] == 0 && slip[point] == 0 && slip_total[point] == 0 && state[point] == MC_STATE_OPEN);
    }
    for (mc_int c = 0; c < mesh->n_cells; ++c, ++cell) {
      const double *sa = &r->stress[b][4 * c], *sf = &stress[4 * cell];
      ck_assert_msg(sf[0] == sa[0] && sf[1] == sa[1] && sf[2] == sa[2] && sf[3] == sa[3], "body %d cell %d: stress",
                    b + 1, (int)c);
      double vm_exact = sqrt(0.5 * ((sa[0] - sa[1]) * (sa[0] - sa[1]) + (sa[1] - sa[3]) * (sa[1] - sa[3]) +
                                    (sa[3] - sa[0]) * (sa[3] - sa[0])) + 3 * sa[2] * sa[2]);
      ck_assert_msg(fabs(vm[cell] - vm_exact) <= 1e-14 * vm_exact, "cell %ld: von Mises %.17g, expected %.17g", cell,
                    vm[cell], vm_exact);
      ck_assert(body[cell] == b + 1);
      ck_assert(types[cell] == (mesh->npc == 3 ? 5 : 9));
      offset += mesh->npc;
      ck_assert(offsets[cell] == offset);
      for (int a = 0; a < mesh->npc; ++a, ++k) ck_assert(conn[k] == mesh->cells[mesh->npc * c + a] + (point - mesh->n_nodes));
    }
  }

  if (first == 0) { /* body 1: the contact fields at its contact nodes, zero elsewhere */
    char *on_surface = calloc((size_t)s->mesh[0].n_nodes, 1);
    int unseen = 0, seen = 0, n_active = 0, n_inactive = 0, n_slip = 0;
    for (mc_int j = 0; j < r->n_contact; ++j) {
      mc_int node = r->contact_nodes[j];
      on_surface[node] = 1;
      ck_assert_msg(p[node] == r->pressure[j], "contact node %d: pressure %.17g, API %.17g", (int)j, p[node],
                    r->pressure[j]);
      ck_assert(active[node] == (r->force[j] > 0));
      ck_assert_msg(shear[node] == r->shear[j] && slip[node] == r->slip[j] && slip_total[node] == r->slip_total[j] &&
                        state[node] == r->state[j],
                    "contact node %d: shear %.17g, slip %.17g, slip_total %.17g, state %g in the file; API %.17g, "
                    "%.17g, %.17g, %g", (int)j, shear[node], slip[node], slip_total[node], state[node], r->shear[j],
                    r->slip[j], r->slip_total[j], r->state[j]);
      /* frictionless: no shear; contact slips (or is open), never sticks */
      ck_assert(r->shear[j] == 0 && (r->state[j] == MC_STATE_SLIP || r->state[j] == MC_STATE_OPEN));
      n_slip += r->state[j] == MC_STATE_SLIP;
      n_active += r->force[j] > 0, n_inactive += r->force[j] == 0 && isfinite(r->gap[j]);
      if (isfinite(r->gap[j])) {
        ++seen;
        ck_assert(contact[node] == 1 && g[node] == r->gap[j] && g0[node] == r->gap0[j]);
      } else { /* sees no mortar surface: the documented sentinel */
        ++unseen;
        ck_assert(contact[node] == 0 && g[node] == -1 && g0[node] == -1 && p[node] == 0);
      }
    }
    for (mc_int i = 0; i < s->mesh[0].n_nodes; ++i)
      if (!on_surface[i])
        ck_assert(p[i] == 0 && g[i] == 0 && g0[i] == 0 && active[i] == 0 && contact[i] == 0 && shear[i] == 0 &&
                  slip[i] == 0 && slip_total[i] == 0 && state[i] == MC_STATE_OPEN);
    /* the scene exercises every case */
    ck_assert_msg(unseen >= 2 && seen >= 4 && n_active >= 2 && n_inactive >= 2 && n_slip >= 2,
                  "unseen %d, seen %d, active %d, inactive %d, slipping %d", unseen, seen, n_active, n_inactive, n_slip);
    free(on_surface);
  }
  free(u), free(ns), free(x), free(p), free(g), free(g0), free(active), free(contact);
  free(shear), free(slip), free(slip_total), free(state);
  free(stress), free(vm), free(body), free(types), free(offsets), free(conn);
}

/* ---- mc_write_vtu ---------------------------------------------------------------------- */

START_TEST(vtu_holds_both_bodies_exactly) {
  scene s;
  scene_build(&s);
  mc_model *m = s.m;
  OK(mc_solve(m));
  results r = results_get(&s);
  remove("test_output_scene.vtu");
  SUCCEEDS(mc_write_vtu(m, "test_output_scene.vtu"));
  char *xml = slurp("test_output_scene.vtu");
  check_piece(xml, &s, &r, 0, 1);
  free(xml);
  /* any name other than *.pvd is one file with both bodies */
  SUCCEEDS(mc_write_vtu(m, "test_output_scene.xml"));
  xml = slurp("test_output_scene.xml");
  check_piece(xml, &s, &r, 0, 1);
  free(xml);
  remove("test_output_scene.xml");
  results_free(&r);
  scene_free(&s);
}
END_TEST

START_TEST(pvd_writes_a_collection_and_one_file_per_body) {
  scene s;
  scene_build(&s);
  mc_model *m = s.m;
  OK(mc_solve(m));
  results r = results_get(&s);
  remove("test_output_scene_body1.vtu"), remove("test_output_scene_body2.vtu");
  SUCCEEDS(mc_write_vtu(m, "test_output_scene.pvd"));
  char *pvd = slurp("test_output_scene.pvd");
  ck_assert_ptr_nonnull(strstr(pvd, "<VTKFile type=\"Collection\""));
  ck_assert_int_eq(count_of(pvd, "<Collection>"), 1);
  ck_assert_int_eq(count_of(pvd, "</Collection>"), 1);
  ck_assert_int_eq(count_of(pvd, "<DataSet "), 2);
  /* the pieces are named relative to the collection's directory */
  ck_assert_ptr_nonnull(strstr(pvd, "file=\"test_output_scene_body1.vtu\""));
  ck_assert_ptr_nonnull(strstr(pvd, "file=\"test_output_scene_body2.vtu\""));
  free(pvd);
  for (int b = 0; b < 2; ++b) {
    char path[64];
    snprintf(path, sizeof path, "test_output_scene_body%d.vtu", b + 1);
    char *xml = slurp(path);
    check_piece(xml, &s, &r, b, b);
    free(xml);
  }
  results_free(&r);
  scene_free(&s);
}
END_TEST

/* Friction: the slip patch test on two blocks (nu = 0, non-matching meshes) in the uniform stress
   sigma_yy = -p, sigma_xy = mu p: the upper block's top moved along x by the exact field plus
   delta, Coulomb friction: every contact node slips with shear -mu p and slip delta. Solved
   again with the same loads nothing moves: slip 0, accumulated slip still delta. Both files hold
   the API's values bit for bit at body 1's contact nodes (the collection's body-1 file), zero
   and MC_STATE_OPEN elsewhere and on body 2. */
static void check_friction_file(const char *path, const sc_mesh *upper, mc_model *m, double shear_expected,
                                double slip_expected, double slip_total_expected) {
  mc_int n;
  OK(mc_get_pair_contact_count(m, 1, &n));
  ck_assert_int_eq(n, upper->n_side_nodes[SC_BOTTOM]);
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)n);
  double *api[4];
  const int field[4] = {MC_CONTACT_SHEAR, MC_CONTACT_SLIP, MC_CONTACT_SLIP_TOTAL, MC_CONTACT_STATE};
  OK(mc_get_pair_contact_nodes(m, 1, nodes));
  for (int k = 0; k < 4; ++k) {
    api[k] = malloc(sizeof(double) * (size_t)n);
    OK(mc_get_pair_contact(m, 1, field[k], api[k]));
  }
  char *xml = slurp(path);
  check_structure(xml, 18);
  const long n_points = upper->n_nodes;
  const char *name[4] = {"shear", "slip", "slip_total", "state"};
  double *file[4];
  for (int k = 0; k < 4; ++k) file[k] = data_array(xml, name[k], k == 3 ? "Int32" : "Float64", 1, n_points);
  char *on_surface = calloc((size_t)n_points, 1);
  const double P = 0.01;
  for (mc_int j = 0; j < n; ++j) {
    on_surface[nodes[j]] = 1;
    /* a node of one contact position: its values bit for bit (17 digits) */
    for (int k = 0; k < 4; ++k)
      ck_assert_msg(file[k][nodes[j]] == api[k][j], "%s: contact node %d: %s %.17g in the file, %.17g from the API",
                    path, (int)j, name[k], file[k][nodes[j]], api[k][j]);
    ck_assert_msg(api[3][j] == MC_STATE_SLIP, "node %d: state %g", (int)j, api[3][j]);
    ck_assert_msg(fabs(api[0][j] - shear_expected) <= 1e-10 * P, "node %d: shear %.17g", (int)j, api[0][j]);
    ck_assert_msg(fabs(api[1][j] - slip_expected) <= 1e-10 * 0.05, "node %d: slip %.17g", (int)j, api[1][j]);
    ck_assert_msg(fabs(api[2][j] - slip_total_expected) <= 1e-10 * 0.05, "node %d: slip total %.17g", (int)j, api[2][j]);
  }
  for (long i = 0; i < n_points; ++i)
    if (!on_surface[i])
      ck_assert(file[0][i] == 0 && file[1][i] == 0 && file[2][i] == 0 && file[3][i] == MC_STATE_OPEN);
  for (int k = 0; k < 4; ++k) free(file[k]), free(api[k]);
  free(on_surface), free(nodes), free(xml);
}

START_TEST(vtu_friction_fields) {
  const double P = 0.01, mu = 0.3, delta = 0.05, tau = mu * P, E = 1;
  sc_mesh upper, lower;
  ck_assert_int_eq(sc_mesh_rect(&upper, 3, 3, 2, 0, 1, 1, 1, 0.1, 3), 0);
  ck_assert_int_eq(sc_mesh_rect(&lower, 4, 4, 3, 0, 0, 1, 1, 0.1, 5), 0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &upper, 0));
  OK(sc_set_mesh(m, 2, &lower, 0));
  for (int b = 1; b <= 2; ++b) {
    const sc_mesh *mesh = b == 1 ? &upper : &lower;
    OK(mc_set_material(m, b, E, 0.0));
    OK(sc_traction_side(m, b, mesh, SC_LEFT, 0, -tau, 0));
    OK(sc_traction_side(m, b, mesh, SC_RIGHT, 0, tau, 0));
  }
  OK(sc_fix_side(m, 2, &lower, SC_BOTTOM, MC_XY, 0)); /* the exact field is 0 at y = 0 with nu = 0 */
  OK(sc_traction_side(m, 1, &upper, SC_TOP, 0, -P, 0));
  const mc_int n_top = upper.n_side_nodes[SC_TOP];
  double *top = malloc(sizeof(double) * 2 * (size_t)n_top);
  for (mc_int k = 0; k < n_top; ++k) top[2 * k] = 2 * tau / E * 2 + delta, top[2 * k + 1] = 0; /* gamma y + delta at y = 2 */
  OK(mc_fix(m, 1, n_top, upper.side_nodes[SC_TOP], MC_X, top));
  free(top);
  OK(mc_set_contact(m, 1, upper.n_side_edges[SC_BOTTOM], upper.side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, lower.n_side_edges[SC_TOP], lower.side_edges[SC_TOP]));
  OK(mc_set_friction(m, 1, MC_FRICTION_COULOMB, mu));
  OK(mc_solve(m));
  remove("test_output_friction.vtu");
  SUCCEEDS(mc_write_vtu(m, "test_output_friction.vtu"));
  /* one file holds both bodies: body 2's points follow body 1's and carry nothing */
  char *both = slurp("test_output_friction.vtu");
  double *state = data_array(both, "state", "Int32", 1, upper.n_nodes + lower.n_nodes);
  double *shear = data_array(both, "shear", "Float64", 1, upper.n_nodes + lower.n_nodes);
  for (mc_int i = upper.n_nodes; i < upper.n_nodes + lower.n_nodes; ++i) ck_assert(state[i] == MC_STATE_OPEN && shear[i] == 0);
  free(state), free(shear), free(both);
  SUCCEEDS(mc_write_vtu(m, "test_output_friction.pvd"));
  check_friction_file("test_output_friction_body1.vtu", &upper, m, -tau, delta, delta);
  /* the same loads again: a step of nothing; the accumulated slip stays */
  OK(mc_solve(m));
  SUCCEEDS(mc_write_vtu(m, "test_output_friction.pvd"));
  check_friction_file("test_output_friction_body1.vtu", &upper, m, -tau, 0, delta);
  remove("test_output_friction.vtu"), remove("test_output_friction.pvd");
  remove("test_output_friction_body1.vtu"), remove("test_output_friction_body2.vtu");
  mc_destroy(m);
  sc_mesh_free(&upper), sc_mesh_free(&lower);
}
END_TEST

START_TEST(single_body_solve_writes_that_body) {
  /* no contact, only body 2 meshed: the file has body 2 alone, contact fields zero */
  mc_model *m = NULL;
  sc_mesh mesh;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  ck_assert_int_eq(sc_mesh_rect(&mesh, 4, 3, 2, 0, 0, 1, 1, 0, 1), 0);
  OK(sc_set_mesh(m, 2, &mesh, 0));
  OK(mc_set_material(m, 2, 1, 0.3));
  OK(sc_fix_side(m, 2, &mesh, SC_BOTTOM, MC_XY, 0));
  OK(sc_traction_side(m, 2, &mesh, SC_TOP, 0.1, -0.2, 0));
  OK(mc_solve(m));
  SUCCEEDS(mc_write_vtu(m, "test_output_single.vtu"));
  char *xml = slurp("test_output_single.vtu");
  check_structure(xml, 18);
  ck_assert_int_eq(attribute(xml, "NumberOfPoints"), mesh.n_nodes);
  ck_assert_int_eq(attribute(xml, "NumberOfCells"), mesh.n_cells);
  double *u_api = malloc(sizeof(double) * 2 * mesh.n_nodes);
  OK(mc_get_displacement(m, 2, u_api));
  double *u = data_array(xml, "displacement", "Float64", 3, 3 * mesh.n_nodes);
  double *body = data_array(xml, "body", "Int32", 1, mesh.n_cells);
  double *p = data_array(xml, "pressure", "Float64", 1, mesh.n_nodes);
  for (mc_int i = 0; i < mesh.n_nodes; ++i) ck_assert(u[3 * i] == u_api[2 * i] && u[3 * i + 1] == u_api[2 * i + 1]);
  for (mc_int c = 0; c < mesh.n_cells; ++c) ck_assert(body[c] == 2);
  for (mc_int i = 0; i < mesh.n_nodes; ++i) ck_assert(p[i] == 0);
  free(u), free(body), free(p), free(u_api), free(xml);
  remove("test_output_single.vtu");
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

START_TEST(write_errors_name_the_cause) {
  scene s;
  scene_build(&s);
  mc_model *m = s.m;
  remove("test_output_unsolved.vtu");
  FAILS(mc_write_vtu(m, "test_output_unsolved.vtu"), MC_ERROR_STATE, "mc_solve");
  ck_assert_msg(!file_exists("test_output_unsolved.vtu"), "a file was written before a solve");
  OK(mc_solve(m));
  FAILS(mc_write_vtu(m, NULL), MC_ERROR_ARGUMENT, "path");
  FAILS(mc_write_vtu(m, "/nonexistent-mc-dir/out.vtu"), MC_ERROR_ARGUMENT, "/nonexistent-mc-dir/out.vtu");
  FAILS(mc_write_vtu(m, "/nonexistent-mc-dir/out.pvd"), MC_ERROR_ARGUMENT, "/nonexistent-mc-dir/out");
  FAILS(mc_write_vtu(m, "."), MC_ERROR_ARGUMENT, "path = \".\"");
  ck_assert_int_eq(mc_write_vtu(NULL, "test_output_null.vtu"), MC_ERROR_ARGUMENT);
  /* the model stays usable after failed writes */
  SUCCEEDS(mc_write_vtu(m, "test_output_again.vtu"));
  ck_assert(file_exists("test_output_again.vtu"));
  remove("test_output_again.vtu");
  /* a changed scene has no solution until the next solve */
  OK(mc_set_body_force(m, 1, 0, -0.06));
  FAILS(mc_write_vtu(m, "test_output_changed.vtu"), MC_ERROR_STATE, "mc_solve");
  ck_assert(!file_exists("test_output_changed.vtu"));
  OK(mc_solve(m));
  SUCCEEDS(mc_write_vtu(m, "test_output_changed.vtu"));
  remove("test_output_changed.vtu");
  scene_free(&s);
}
END_TEST

/* ---- mc_set_log_callback --------------------------------------------------------------- */

typedef struct log_record {
  void *self; /* the callback checks it receives this as user_data */
  int calls, phases, iterations, wrong_user_data, bad_lines, bad_levels, iteration_gaps;
  int last_iteration;
  double last_residual;
  char text[8192]; /* all phase messages, one per line */
} log_record;

/* "<...>, <number> s": a phase message ends with its time in seconds */
static int ends_with_time(const char *message) {
  size_t n = strlen(message);
  if (n < 4 || strcmp(message + n - 2, " s") != 0) return 0;
  const char *p = message + n - 2;
  while (p > message && p[-1] != ' ') --p;
  char *end;
  double t = strtod(p, &end);
  return end == message + n - 2 && t >= 0;
}

static void record_log(void *user_data, mc_log_level level, const char *message) {
  log_record *r = user_data;
  if (r->self != user_data) {
    ++r->wrong_user_data;
    return;
  }
  ++r->calls;
  if (strchr(message, '\n') || message[0] == '\0') ++r->bad_lines;
  if (level == MC_LOG_PHASE) {
    ++r->phases;
    if (strncmp(message, "solve: start", 12) != 0 && !ends_with_time(message)) ++r->bad_lines;
    if (strlen(r->text) + 2 >= sizeof r->text) return; /* full: later lines are dropped */
    strncat(r->text, message, sizeof r->text - strlen(r->text) - 2);
    strcat(r->text, "\n");
  } else if (level == MC_LOG_ITERATION) {
    int it = 0, active = 0, q = 0, flip = 0;
    double residual = -1;
    ++r->iterations;
    if (sscanf(message, "active-set iteration %d: %d active of %d, %d to flip, residual %lg", &it, &active, &q, &flip,
               &residual) != 5 ||
        active > q || flip < 0)
      ++r->bad_lines;
    if (it != r->last_iteration + 1) ++r->iteration_gaps;
    r->last_iteration = it;
    r->last_residual = residual;
  } else {
    ++r->bad_levels;
  }
}

static void log_reset(log_record *r) {
  memset(r, 0, sizeof *r);
  r->self = r;
}

START_TEST(log_callback_reports_phases_and_iterations) {
  scene s;
  scene_build(&s);
  mc_model *m = s.m;
  log_record rec;
  log_reset(&rec);
  SUCCEEDS(mc_set_log_callback(m, record_log, &rec));
  OK(mc_solve(m));
  int64_t iterations, factorizations;
  double complementarity;
  OK(mc_get_info_int(m, MC_INFO_ITERATIONS, &iterations));
  OK(mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity));
  ck_assert_int_eq(rec.wrong_user_data, 0);
  ck_assert_msg(rec.bad_lines == 0 && rec.bad_levels == 0, "malformed messages:\n%s", rec.text);
  ck_assert_int_eq(rec.iterations, iterations);
  ck_assert_int_ge(iterations, 1);
  ck_assert_int_eq(rec.iteration_gaps, 0);
  /* the last iteration is the converged one: its residual is MC_INFO_COMPLEMENTARITY (3 digits) */
  ck_assert_msg(fabs(rec.last_residual - complementarity) <= 5e-3 * complementarity + 1e-300,
                "last residual %g, MC_INFO_COMPLEMENTARITY %g", rec.last_residual, complementarity);
  static const char *const phases[] = {"solve: start, assembling", "contact geometry", "assembly: body 1",
                                       "assembly: body 2", "analysis: body 1", "analysis: body 2",
                                       "interface solver: condensed (automatic", "factorization: body 1",
                                       "factorization: body 2", "interface operator", "loads:",
                                       "active-set solve: solved", "recovery:", "solve: done"};
  const char *previous = rec.text;
  for (size_t k = 0; k < sizeof phases / sizeof *phases; ++k) {
    const char *at = strstr(rec.text, phases[k]);
    ck_assert_msg(at != NULL, "no \"%s\" in\n%s", phases[k], rec.text);
    if (k > 0) ck_assert_msg(at > previous, "\"%s\" out of order in\n%s", phases[k], rec.text);
    previous = at;
  }
  ck_assert_int_eq(rec.phases, (int)(sizeof phases / sizeof *phases));
  /* results on demand (the default): the solve computed no stresses and no estimate; the first
     call that asks for each does, with its message after "solve: done", and only once */
  ck_assert_msg(!strstr(rec.text, "error estimate:") && !strstr(rec.text, "stresses:") &&
                    !strstr(rec.text, "reactions, stresses"),
                "%s", rec.text);
  {
    double estimate, estimate_again, *sigma = malloc(sizeof(double) * 4 * (size_t)(s.mesh[0].n_cells + s.mesh[0].n_nodes));
    int phases_before = rec.phases;
    OK(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &estimate));
    OK(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &estimate_again));
    ck_assert(estimate == estimate_again && estimate > 0);
    ck_assert_int_eq(rec.phases, phases_before + 1);
    ck_assert_msg(strstr(rec.text, "solve: done") < strstr(rec.text, "error estimate:"), "%s", rec.text);
    OK(mc_get_stress(m, 1, sigma));
    OK(mc_get_nodal_stress(m, 1, sigma)); /* computed with the cells' */
    ck_assert_int_eq(rec.phases, phases_before + 2);
    ck_assert_msg(strstr(rec.text, "stresses: body 1,") != NULL, "%s", rec.text);
    ck_assert_int_eq(rec.bad_lines, 0);
    free(sigma);
  }
  /* eager results: the solve computes both, the estimate before "solve: done" */
  log_reset(&rec);
  SUCCEEDS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 1));
  OK(mc_solve(m));
  ck_assert_msg(strstr(rec.text, "reactions, stresses") && strstr(rec.text, "error estimate:") &&
                    strstr(rec.text, "error estimate:") < strstr(rec.text, "solve: done"),
                "%s", rec.text);
  SUCCEEDS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 0));

  /* a load step: reuse is reported, and no assembly or factorization happens */
  log_reset(&rec);
  OK(mc_set_body_force(m, 1, 0, -0.08));
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &factorizations));
  ck_assert_int_eq(factorizations, 0);
  ck_assert_msg(strstr(rec.text, "solve: start, reusing") && !strstr(rec.text, "factorization:") &&
                    !strstr(rec.text, "assembly:") && strstr(rec.text, "active-set solve"),
                "%s", rec.text);
  OK(mc_get_info_int(m, MC_INFO_ITERATIONS, &iterations));
  ck_assert_int_eq(rec.iterations, iterations);

  /* removed: no more calls (user_data is ignored then) */
  log_reset(&rec);
  SUCCEEDS(mc_set_log_callback(m, NULL, &rec));
  OK(mc_solve(m));
  ck_assert_int_eq(rec.calls + rec.wrong_user_data, 0);
  ck_assert_int_eq(mc_set_log_callback(NULL, record_log, &rec), MC_ERROR_ARGUMENT);
  scene_free(&s);
}
END_TEST

START_TEST(log_callback_sees_a_failing_solve) {
  /* body 1 pulled away from body 2 while held by contact alone: MC_ERROR_SINGULAR; the
     messages up to the failure arrive, and no "solve: done" */
  scene s;
  scene_build(&s);
  mc_model *m = s.m;
  log_record rec;
  log_reset(&rec);
  OK(mc_set_log_callback(m, record_log, &rec));
  OK(mc_set_body_force(m, 1, 0, +0.05));
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "cannot be balanced");
  ck_assert_msg(strstr(rec.text, "factorization: body 2") && strstr(rec.text, "active-set solve: loads not balanced") &&
                    !strstr(rec.text, "solve: done"),
                "%s", rec.text);
  ck_assert_int_eq(rec.wrong_user_data + rec.bad_lines, 0);
  scene_free(&s);
}
END_TEST

static Suite *output_suite(void) {
  Suite *s = suite_create("output");
  TCase *vtu = tcase_create("write_vtu");
  tcase_add_test(vtu, vtu_holds_both_bodies_exactly);
  tcase_add_test(vtu, pvd_writes_a_collection_and_one_file_per_body);
  tcase_add_test(vtu, single_body_solve_writes_that_body);
  tcase_add_test(vtu, vtu_friction_fields);
  tcase_add_test(vtu, write_errors_name_the_cause);
  suite_add_tcase(s, vtu);
  TCase *logging = tcase_create("log_callback");
  tcase_add_test(logging, log_callback_reports_phases_and_iterations);
  tcase_add_test(logging, log_callback_sees_a_failing_solve);
  suite_add_tcase(s, logging);
  return s;
}

int main(void) { return sc_run_suite(output_suite()); }
