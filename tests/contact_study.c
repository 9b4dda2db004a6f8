#include "contact_study.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct solution {
  sc_mesh mesh[2];
  double *u[2];
  int n_contact;
  double *contact_x, *pressure;
} solution;

static void solution_free(solution *s) {
  for (int b = 0; b < 2; ++b) sc_mesh_free(&s->mesh[b]), free(s->u[b]);
  free(s->contact_x), free(s->pressure);
}

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Cells on the contact line: body 1 has 11*2^k, body 2 has 8*2^k (or 11*2^k if matching). */
static int cells_of(int body, int level, int matching) { return (body == 0 || matching ? 11 : 8) << level; }

static int solve_level(int method, int matching, int level, solution *s, long *dofs, double *seconds) {
  mc_model *m = NULL;
  if (mc_create(&m) != MC_OK) return 1;
  for (int b = 0; b < 2; ++b) {
    int n = cells_of(b, level, matching);
    if (sc_mesh_rect(&s->mesh[b], 3, n, n / 2 > 0 ? n / 2 : 1, 0, b == 0 ? 0 : -0.5, 1, 0.5, 0, 1)) return 1;
    if (sc_set_mesh(m, b + 1, &s->mesh[b], 0) || mc_set_material(m, b + 1, 1, 0.3)) goto fail;
  }
  const sc_mesh *top = &s->mesh[0];
  if (sc_fix_side(m, 1, top, SC_LEFT, MC_X, 0) || sc_fix_side(m, 2, &s->mesh[1], SC_BOTTOM, MC_XY, 0)) goto fail;
  /* p(x) = 0.5 + 1.5 cos(pi x) on the top edges, evaluated at each edge's midpoint times its
     length would not be exact; use the pressure at the midpoint: nested levels share it to O(h^2). */
  int ne = top->n_side_edges[SC_TOP];
  double *pressure = malloc(sizeof(double) * ne);
  for (int e = 0; e < ne; ++e) {
    const mc_int *ed = top->side_edges[SC_TOP] + 2 * e;
    double x = 0.5 * (top->xy[2 * ed[0]] + top->xy[2 * ed[1]]);
    pressure[e] = 0.5 + 1.5 * cos(M_PI * x);
  }
  mc_status st = mc_add_pressure(m, 1, ne, top->side_edges[SC_TOP], pressure);
  free(pressure);
  if (st) goto fail;
  if (mc_set_contact(m, 1, s->mesh[0].n_side_edges[SC_BOTTOM], s->mesh[0].side_edges[SC_BOTTOM]) ||
      mc_set_contact(m, 2, s->mesh[1].n_side_edges[SC_TOP], s->mesh[1].side_edges[SC_TOP]) ||
      mc_set_option_int(m, MC_OPTION_METHOD, method))
    goto fail;
  double start = now();
  if (mc_solve(m) != MC_OK) goto fail;
  *seconds = now() - start;
  int64_t d;
  mc_get_info_int(m, MC_INFO_DOFS, &d);
  *dofs = (long)d;
  for (int b = 0; b < 2; ++b) {
    s->u[b] = malloc(sizeof(double) * 2 * s->mesh[b].n_nodes);
    mc_get_displacement(m, b + 1, s->u[b]);
  }
  mc_int nc;
  mc_get_contact_count(m, &nc);
  s->n_contact = nc;
  mc_int *nodes = malloc(sizeof(mc_int) * nc);
  s->contact_x = malloc(sizeof(double) * nc), s->pressure = malloc(sizeof(double) * nc);
  mc_get_contact_nodes(m, nodes);
  mc_get_contact_pressure(m, s->pressure);
  for (int j = 0; j < nc; ++j) s->contact_x[j] = s->mesh[0].xy[2 * nodes[j]];
  free(nodes);
  mc_destroy(m);
  return 0;
fail:
  fprintf(stderr, "contact study level %d: %s\n", level, mc_errmsg(m));
  mc_destroy(m);
  return 1;
}

/* The coarse P1 field at a point of its structured rectangle (diagonal (i,j)-(i+1,j+1)). */
static void interpolate(const sc_mesh *mesh, const double *u, double x, double y, double out[2]) {
  double x0 = mesh->xy[0], y0 = mesh->xy[1];
  double hx = (mesh->xy[2 * mesh->nx] - x0) / mesh->nx;
  double hy = (mesh->xy[2 * sc_node(mesh, 0, mesh->ny) + 1] - y0) / mesh->ny;
  double sx = (x - x0) / hx, sy = (y - y0) / hy;
  int i = (int)floor(sx), j = (int)floor(sy);
  if (i >= mesh->nx) i = mesh->nx - 1;
  if (j >= mesh->ny) j = mesh->ny - 1;
  if (i < 0) i = 0;
  if (j < 0) j = 0;
  double s = sx - i, t = sy - j;
  mc_int a = sc_node(mesh, i, j), b = sc_node(mesh, i + 1, j), c = sc_node(mesh, i + 1, j + 1), d = sc_node(mesh, i, j + 1);
  for (int k = 0; k < 2; ++k) {
    if (s >= t) out[k] = u[2 * a + k] + s * (u[2 * b + k] - u[2 * a + k]) + t * (u[2 * c + k] - u[2 * b + k]);
    else out[k] = u[2 * a + k] + t * (u[2 * d + k] - u[2 * a + k]) + s * (u[2 * c + k] - u[2 * d + k]);
  }
}

/* H1 norm (L2 + gradient) of a P1 field e over a mesh, exact per triangle. */
static double h1_norm(const sc_mesh *mesh, const double *e) {
  double sum = 0;
  for (mc_int c = 0; c < mesh->n_cells; ++c) {
    const mc_int *v = mesh->cells + 3 * c;
    double x[3], y[3];
    for (int a = 0; a < 3; ++a) x[a] = mesh->xy[2 * v[a]], y[a] = mesh->xy[2 * v[a] + 1];
    double area2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    for (int k = 0; k < 2; ++k) {
      double gx = 0, gy = 0, mass = 0;
      for (int a = 0; a < 3; ++a) {
        int b = (a + 1) % 3, d = (a + 2) % 3;
        gx += e[2 * v[a] + k] * (y[b] - y[d]) / area2;
        gy += e[2 * v[a] + k] * (x[d] - x[b]) / area2;
      }
      /* exact mass term of a linear function on a triangle: A/6 (sum e_a^2 + sum_{a<b} e_a e_b) */
      double e0 = e[2 * v[0] + k], e1 = e[2 * v[1] + k], e2 = e[2 * v[2] + k];
      mass = area2 / 2 / 6 * (e0 * e0 + e1 * e1 + e2 * e2 + e0 * e1 + e1 * e2 + e0 * e2);
      sum += area2 / 2 * (gx * gx + gy * gy) + mass;
    }
  }
  return sqrt(sum);
}

/* The lumped pressure as a piecewise linear function of x along the contact line. */
static double pressure_at(const solution *s, double x) {
  for (int j = 0; j + 1 < s->n_contact; ++j) {
    double xa = s->contact_x[j], xb = s->contact_x[j + 1];
    double lo = fmin(xa, xb), hi = fmax(xa, xb);
    if (x >= lo - 1e-14 && x <= hi + 1e-14) {
      double t = (x - xa) / (xb - xa);
      return s->pressure[j] + t * (s->pressure[j + 1] - s->pressure[j]);
    }
  }
  return 0;
}

int contact_study_run(int method, int matching, int n_levels, int reference, contact_study_level *out) {
  solution ref = {0};
  long dofs;
  double seconds;
  if (solve_level(method, matching, reference, &ref, &dofs, &seconds)) return 1;
  for (int k = 0; k < n_levels; ++k) {
    solution s = {0};
    if (solve_level(method, matching, k, &s, &out[k].dofs, &out[k].seconds)) return 1;
    out[k].level = k;
    out[k].h1 = 1.0 / cells_of(0, k, matching);
    out[k].h2 = 1.0 / cells_of(1, k, matching);
    double sum = 0;
    for (int b = 0; b < 2; ++b) {
      const sc_mesh *fine = &ref.mesh[b];
      double *e = malloc(sizeof(double) * 2 * fine->n_nodes);
      for (mc_int i = 0; i < fine->n_nodes; ++i) {
        double v[2];
        interpolate(&s.mesh[b], s.u[b], fine->xy[2 * i], fine->xy[2 * i + 1], v);
        e[2 * i] = v[0] - ref.u[b][2 * i], e[2 * i + 1] = v[1] - ref.u[b][2 * i + 1];
      }
      double n = h1_norm(fine, e);
      sum += n * n;
      free(e);
    }
    out[k].error_h1 = sqrt(sum);
    /* L2 of the pressure difference along Gamma_c, trapezoid on the reference nodes. */
    double l2 = 0;
    for (int j = 0; j + 1 < ref.n_contact; ++j) {
      double xa = ref.contact_x[j], xb = ref.contact_x[j + 1];
      double da = pressure_at(&s, xa) - ref.pressure[j], db = pressure_at(&s, xb) - ref.pressure[j + 1];
      l2 += fabs(xb - xa) * (da * da + db * db) / 2;
    }
    out[k].error_l2_pressure = sqrt(l2);
    solution_free(&s);
  }
  solution_free(&ref);
  return 0;
}

double contact_study_rate(double coarse, double fine) { return log(coarse / fine) / log(2.0); }
