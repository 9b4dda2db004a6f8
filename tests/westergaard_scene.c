/*
 * westergaard_scene.c - Westergaard's periodic wavy contact: meshes, model, measurements
 * (see westergaard_scene.h for the scene and the closed form).
 */
#include "westergaard_scene.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define WG_PI 3.14159265358979323846 /* M_PI is not C99 */

wg_params wg_default_params(void) {
  wg_params p = {100, 40, 0.83, 4, 1.0, 1.25, 0.3, 0};
  return p;
}

typedef struct wg_map {
  double depth, grading, amplitude, length;
  int body; /* 1: graded upwards from y = 0; 2: graded downwards, and waved if amplitude > 0 */
} wg_map;

static void wg_place(double *x, double *y, void *ctx) {
  const wg_map *w = ctx;
  if (w->body == 1) {
    *y = w->depth * pow(*y / w->depth, w->grading);
  } else {
    const double t = -*y / w->depth; /* 0 at the interface, 1 at the bottom */
    *y = -w->depth * pow(t, w->grading);
    *y -= w->amplitude * (1 - cos(2 * WG_PI * *x / w->length)) * (1 + *y / w->depth);
  }
}

/* Rows in depth so that the first one is at most h high. */
static int wg_rows(double depth, double h, double grading) {
  int ny = (int)ceil(pow(depth / h, 1 / grading) - 1e-9);
  return ny < 1 ? 1 : ny;
}

int wg_scene_build(wg_scene *s, const wg_params *prm) {
  s->prm = *prm;
  s->mesh[0].xy = s->mesh[1].xy = NULL;
  if (prm->wavelengths < 1 || prm->cells < 2 || prm->ratio2 <= 0 || (prm->npc != 3 && prm->npc != 4) ||
      !(prm->depth > 0) || !(prm->grading >= 1) || !(prm->load > 0 && prm->load < 1))
    return 1;
  s->length = 1;
  s->amplitude = 1e-3 * s->length;
  s->young[0] = 1, s->poisson[0] = 0.3;
  s->young[1] = 2, s->poisson[1] = 0.2;
  s->e_star = 1 / ((1 - s->poisson[0] * s->poisson[0]) / s->young[0] +
                   (1 - s->poisson[1] * s->poisson[1]) / s->young[1]);
  s->p_star = WG_PI * s->e_star * s->amplitude / s->length;
  s->pm = prm->load * s->p_star;
  s->a_exact = s->length / WG_PI * asin(sqrt(prm->load));
  s->p0_exact = 2 * sqrt(s->pm * s->p_star);
  const double total = prm->wavelengths * s->length, depth = prm->depth * s->length;
  const int nx1 = prm->cells * prm->wavelengths, nx2 = (int)lround(prm->ratio2 * nx1);
  if (nx2 < 1) return 1;
  const double h1 = total / nx1, h2 = total / nx2;
  if (sc_mesh_rect(&s->mesh[0], prm->npc, nx1, wg_rows(depth, h1, prm->grading), 0, 0, total, depth, 0, 1)) return 1;
  if (sc_mesh_rect(&s->mesh[1], prm->npc, nx2, wg_rows(depth, h2, prm->grading), 0, -depth, total, depth, 0, 2)) {
    sc_mesh_free(&s->mesh[0]);
    return 1;
  }
  for (int b = 0; b < 2; ++b) {
    wg_map map = {depth, prm->grading, b == 1 && prm->wavy_mesh ? s->amplitude : 0, s->length, b + 1};
    sc_mesh_map(&s->mesh[b], wg_place, &map);
  }
  return 0;
}

void wg_scene_free(wg_scene *s) {
  if (s->mesh[0].xy) sc_mesh_free(&s->mesh[0]);
  if (s->mesh[1].xy) sc_mesh_free(&s->mesh[1]);
  s->mesh[0].xy = s->mesh[1].xy = NULL;
}

mc_model *wg_model(const wg_scene *s, int contact, int interface_solver) {
  mc_model *m = NULL;
  mc_status st = mc_create(&m);
  for (int b = 0; b < 2 && !st; ++b) {
    const sc_mesh *mesh = &s->mesh[b];
    st = sc_set_mesh(m, b + 1, mesh, 0);
    if (!st) st = mc_set_material(m, b + 1, s->young[b], s->poisson[b]);
    if (!st) st = sc_fix_side(m, b + 1, mesh, SC_LEFT, MC_X, 0);
    if (!st) st = sc_fix_side(m, b + 1, mesh, SC_RIGHT, MC_X, 0);
  }
  if (!st) st = sc_fix_side(m, 2, &s->mesh[1], SC_BOTTOM, MC_Y, 0);
  const sc_mesh *b1 = &s->mesh[0];
  const mc_int n_top = b1->n_side_edges[SC_TOP], n_bottom = b1->n_side_nodes[SC_BOTTOM];
  double *work = malloc(sizeof(double) * (size_t)(n_top > n_bottom ? n_top : n_bottom));
  if (!work) st = MC_ERROR_MEMORY;
  for (mc_int e = 0; e < n_top && !st; ++e) work[e] = s->pm;
  if (!st) st = mc_add_pressure(m, 1, n_top, b1->side_edges[SC_TOP], work);
  if (contact) {
    if (!st) st = mc_set_contact(m, 1, b1->n_side_edges[SC_BOTTOM], b1->side_edges[SC_BOTTOM]);
    if (!st) st = mc_set_contact(m, 2, s->mesh[1].n_side_edges[SC_TOP], s->mesh[1].side_edges[SC_TOP]);
    if (!st && !s->prm.wavy_mesh) {
      for (mc_int k = 0; k < n_bottom; ++k) {
        const double x = b1->xy[2 * b1->side_nodes[SC_BOTTOM][k]];
        work[k] = s->amplitude * (1 - cos(2 * WG_PI * x / s->length));
      }
      st = mc_set_gap_offset(m, n_bottom, b1->side_nodes[SC_BOTTOM], work);
    }
    if (!st) st = mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, interface_solver);
  } else if (!st) {
    st = sc_fix_side(m, 1, b1, SC_BOTTOM, MC_Y, 0);
  }
  free(work);
  if (st) {
    fprintf(stderr, "westergaard model: %s\n", mc_errmsg(m));
    mc_destroy(m);
    return NULL;
  }
  return m;
}

static double wg_exact(const wg_scene *s, double r) {
  const double s2 = s->prm.load, sp = sin(WG_PI * r / s->length);
  return sp * sp >= s2 ? 0 : 2 * s->pm * cos(WG_PI * r / s->length) * sqrt(s2 - sp * sp) / s2;
}

int wg_measure(mc_model *m, const wg_scene *s, wg_result *r, double *pressure_out) {
  const sc_mesh *b1 = &s->mesh[0];
  const int n = s->prm.cells, N = s->prm.wavelengths, nx1 = n * N;
  int64_t v = 0;
  mc_int q = 0;
  if (mc_get_contact_count(m, &q)) return 1;
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)q), *pos = malloc(sizeof(mc_int) * (size_t)b1->n_nodes);
  double *force = malloc(sizeof(double) * (size_t)q), *pressure = malloc(sizeof(double) * (size_t)q);
  int status = !nodes || !pos || !force || !pressure;
  if (!status)
    status = mc_get_contact_nodes(m, nodes) || mc_get_contact_force(m, force) || mc_get_contact_pressure(m, pressure);
  if (!status) {
    for (mc_int i = 0; i < b1->n_nodes; ++i) pos[i] = -1;
    for (mc_int j = 0; j < q; ++j) pos[nodes[j]] = j;
    for (int i = 0; i <= nx1 && !status; ++i) status = pos[sc_node(b1, i, 0)] < 0; /* every bottom node a position */
  }
  if (status) {
    free(nodes), free(pos), free(force), free(pressure);
    return 1;
  }
#define WG_AT(i) pos[sc_node(b1, (i), 0)]
  mc_get_info_int(m, MC_INFO_DOFS, &v), r->dofs = (long)v;
  mc_get_info_int(m, MC_INFO_CONTACT_NODES, &v), r->contact_nodes = (long)v;
  mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &v), r->active_nodes = (long)v;
  mc_get_info_int(m, MC_INFO_ITERATIONS, &v), r->iterations = (long)v;
  mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &v), r->interface_solver = (long)v;
  mc_get_info_real(m, MC_INFO_GAP_RESIDUAL, &r->gap_residual);
  const double h = s->length / n;
  r->h = h;
  r->patches = 0;
  for (int i = 0; i <= nx1; ++i)
    if (force[WG_AT(i)] > 0 && (i == 0 || !(force[WG_AT(i - 1)] > 0))) ++r->patches;
  r->crests = 0;
  r->p0_mean = 0, r->p0_min = INFINITY, r->p0_max = -INFINITY;
  r->a_mean = 0, r->a_last_min = INFINITY, r->a_last_max = -INFINITY;
  r->profile_error = 0;
  int sides = 0;
  for (int k = 0; k <= N; ++k) {
    if (N > 1 && (k == 0 || k == N)) continue; /* interior crests, away from the walls */
    const int ic = k * n;
    const double p0 = pressure[WG_AT(ic)];
    ++r->crests;
    r->p0_mean += p0;
    r->p0_min = fmin(r->p0_min, p0), r->p0_max = fmax(r->p0_max, p0);
    for (int dir = -1; dir <= 1; dir += 2) {
      if ((dir < 0 && k == 0) || (dir > 0 && k == N)) continue;
      int last = 0; /* steps from the crest to the last active node on this side (half a wavelength at most) */
      for (int step = 1; step <= n / 2 && force[WG_AT(ic + dir * step)] > 0; ++step) last = step;
      r->a_last_min = fmin(r->a_last_min, last * h), r->a_last_max = fmax(r->a_last_max, last * h);
      r->a_mean += (last + 0.5) * h;
      ++sides;
      for (int step = 0; step * h < 0.8 * s->a_exact; ++step) {
        const double err = fabs(pressure[WG_AT(ic + dir * step)] - wg_exact(s, step * h)) / s->p0_exact;
        r->profile_error = fmax(r->profile_error, err);
      }
    }
  }
#undef WG_AT
  r->p0_mean /= r->crests;
  r->a_mean /= sides;
  if (pressure_out)
    for (mc_int j = 0; j < q; ++j) pressure_out[j] = pressure[j];
  free(nodes), free(pos), free(force), free(pressure);
  return 0;
}
