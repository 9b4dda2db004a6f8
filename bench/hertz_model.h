/*
 * hertz_model.h - the plane-strain Hertz scene (examples/scenes/hertz_scene.h) put into a model
 * the way the benchmarks solve it (bench/hertz_sweep.c, bench/hertz_quadratic.c): both bodies
 * E = 1, nu = 0.3; u_x = 0 on body 1's axis, body 2's bottom clamped; the total force
 * HERTZ_TOTAL_FORCE (scaled) as a uniform traction on body 1's flat top of length 2. Contact and
 * options are the caller's. (The scene library itself does not link the library, hence a header
 * here.)
 */
#ifndef HERTZ_MODEL_H
#define HERTZ_MODEL_H

#include "hertz_scene.h"
#include "mortarcontact.h"
#include <stdlib.h>

#define HERTZ_TOTAL_FORCE 0.01
#define HERTZ_TOP_LENGTH 2.0

/* The load: scale * HERTZ_TOTAL_FORCE downwards on body 1's top, replacing any earlier load. */
static inline mc_status hertz_model_load(mc_model *m, const hertz_scene *s, double scale) {
  double *traction = malloc(sizeof(double) * 2 * (size_t)s->n_top_edges);
  if (!traction) return MC_ERROR_MEMORY;
  for (int e = 0; e < s->n_top_edges; ++e)
    traction[2 * e] = 0, traction[2 * e + 1] = -scale * HERTZ_TOTAL_FORCE / HERTZ_TOP_LENGTH;
  mc_status status = mc_clear_loads(m, 1);
  if (status == MC_OK) status = mc_add_traction(m, 1, s->n_top_edges, s->top_edges, traction);
  free(traction);
  return status;
}

/* Meshes, materials, supports and the load (scale 1). */
static inline mc_status hertz_model_bodies(mc_model *m, const hertz_scene *s) {
  mc_status status = MC_OK;
  for (int b = 0; b < 2 && status == MC_OK; ++b) {
    const hertz_mesh *mesh = &s->body[b];
    status = mc_set_mesh(m, b + 1, mesh->n_nodes, mesh->xy, mesh->n_cells, mesh->nodes_per_cell, mesh->cells);
    if (status == MC_OK) status = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  if (status == MC_OK) status = mc_fix(m, 1, s->n_axis_nodes, s->axis_nodes, MC_X, NULL);
  if (status == MC_OK) status = mc_fix(m, 2, s->n_bottom_nodes, s->bottom_nodes, MC_XY, NULL);
  if (status == MC_OK) status = hertz_model_load(m, s, 1.0);
  return status;
}

#endif
