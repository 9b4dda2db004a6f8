/*
 * nafems_roller.c - NAFEMS R0094 benchmark 1, "cylinder roller contact" (A. W. A. Konter,
 * Advanced Finite Element Contact Benchmarks, NAFEMS R0094, 2006; Code_Aster validation test
 * SSNP154, V6.03.154), frictionless, plane strain, solved on a few refinement levels with the
 * three methods and both contact surfaces; prints a Markdown table beside the published values
 * (docs/benchmarks.md, "NAFEMS R0094 benchmark 1").
 *
 * The benchmark (as built by SSNP154 and COMSOL's verification model of it): a steel cylinder,
 * R = 50 mm, E = 210 000 N/mm^2, nu = 0.3, pressed by F = 35 kN (per mm of thickness, applied at
 * its top point; 17.5 kN on the half model) onto an aluminium block 200 mm wide and 200 mm high,
 * E = 70 000 N/mm^2, nu = 0.3, clamped at its bottom; symmetric about x = 0. Reported: the
 * vertical displacement DY and the stress SIYY at B, the point of the block's top on the
 * symmetry plane (the contact point); Hertz's a and p0.
 *
 * Meshes (built here): the cylinder is the shared Hertz scene's half-disc (hertz_scene.h) scaled
 * to R = 50 plus its mirror image about the diameter, merged along it (so both halves are graded
 * towards the contact point and towards the loaded top point); the block is the Hertz scene's
 * block scaled by 25 in x and stretched in y by y -> 25 y (1 + y^2 / 16) to reach 200 mm deep
 * while keeping the fine zone at the top. Body 1 (non-mortar) = the cylinder, body 2 = the block.
 * u_x = 0 on the cylinder's axis; the block clamped at its bottom; the cylinder held vertically
 * by contact alone.
 *
 * Usage: nafems_roller [finest_h1_mm]   (default 0.125; levels 2, 1, 0.5, ... down to it)
 */
#include "hertz_scene.h"
#include "mortarcontact.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static const double RADIUS = 50, FORCE = 35000, E_CYLINDER = 210000, E_BLOCK = 70000, NU = 0.3;

/* Published values: SSNP154 (code_aster astest/ssnp154a.comm, TEST_RESU with
   REFERENCE='SOURCE_EXTERNE', i.e. the NAFEMS benchmark's values) and its analytic solution. */
static const double REF_DY_B = -1.3069040401076999;    /* mm, DY at B */
static const double REF_SIYY_B = -3800.4949548282998;  /* N/mm^2, SIYY at B (extrapolated from the volume) */
static const double HERTZ_A = 6.21, HERTZ_P0 = 3585.37; /* mm, N/mm^2 (ssnp154a.comm, "solution analytique") */

typedef struct mesh {
  int n_nodes, n_cells, npc;
  double *xy;
  int *cells;
} mesh;

typedef struct roller_scene {
  mesh body[2];                /* cylinder, block */
  int n_contact[2], *contact[2];
  int n_axis, *axis;           /* cylinder nodes on x = 0 */
  int top, point_b;            /* the cylinder's loaded top node, the block's node B */
  int n_bottom, *bottom;       /* block nodes on y = -200 */
} roller_scene;

/* The full cylinder from the Hertz half-disc d (radius 1, centre (0, 1), flat top y = 1): d and
   its mirror image y -> 2 - y, merged along the diameter (row nt of the structured grid), scaled
   by RADIUS. Ids: d's own, then the mirror's nodes off the diameter. */
static int cylinder_build(roller_scene *r, const hertz_scene *hs) {
  const hertz_mesh *d = &hs->body[0];
  const int ns = hs->n_top_edges, row = ns + 1, nt = d->n_nodes / row - 1, off_diameter = nt * row;
  int *mirror = malloc(sizeof(int) * (size_t)d->n_nodes);
  mesh *c = &r->body[0];
  c->npc = d->nodes_per_cell;
  c->n_nodes = d->n_nodes + off_diameter;
  c->n_cells = 2 * d->n_cells;
  c->xy = malloc(sizeof(double) * 2 * (size_t)c->n_nodes);
  c->cells = malloc(sizeof(int) * (size_t)(c->npc * c->n_cells));
  if (!mirror || !c->xy || !c->cells) return 1;
  for (int i = 0; i < d->n_nodes; ++i) {
    mirror[i] = i < off_diameter ? d->n_nodes + i : i; /* rows 0 .. nt-1, then the shared diameter */
    c->xy[2 * i] = RADIUS * d->xy[2 * i], c->xy[2 * i + 1] = RADIUS * d->xy[2 * i + 1];
    if (i < off_diameter)
      c->xy[2 * mirror[i]] = RADIUS * d->xy[2 * i], c->xy[2 * mirror[i] + 1] = RADIUS * (2 - d->xy[2 * i + 1]);
  }
  for (int e = 0; e < d->n_cells; ++e) { /* the mirror reverses the orientation: reverse the cell */
    const int *v = d->cells + c->npc * e;
    for (int k = 0; k < c->npc; ++k) {
      c->cells[c->npc * e + k] = v[k];
      c->cells[c->npc * (d->n_cells + e) + k] = mirror[v[c->npc - 1 - k]];
    }
  }
  r->n_axis = 2 * hs->n_axis_nodes - 1;
  r->axis = malloc(sizeof(int) * (size_t)r->n_axis);
  for (int k = 0; k < hs->n_axis_nodes; ++k) r->axis[k] = hs->axis_nodes[k];
  for (int k = 0, n = hs->n_axis_nodes; k < hs->n_axis_nodes; ++k)
    if (hs->axis_nodes[k] < off_diameter) r->axis[n++] = mirror[hs->axis_nodes[k]];
  r->top = mirror[ns / 2]; /* the mirror of the contact point (0, 0): (0, 2 R) */
  r->n_contact[0] = hs->n_contact_edges[0];
  r->contact[0] = malloc(sizeof(int) * 2 * (size_t)r->n_contact[0]);
  memcpy(r->contact[0], hs->contact_edges[0], sizeof(int) * 2 * (size_t)r->n_contact[0]);
  free(mirror);
  return 0;
}

/* The block from the Hertz block ([-4, 4] x [-4, 0]): x -> 25 x, y -> 25 y (1 + y^2 / 16). */
static int block_build(roller_scene *r, const hertz_scene *hs) {
  const hertz_mesh *b = &hs->body[1];
  mesh *k = &r->body[1];
  k->npc = b->nodes_per_cell, k->n_nodes = b->n_nodes, k->n_cells = b->n_cells;
  k->xy = malloc(sizeof(double) * 2 * (size_t)k->n_nodes);
  k->cells = malloc(sizeof(int) * (size_t)(k->npc * k->n_cells));
  if (!k->xy || !k->cells) return 1;
  memcpy(k->cells, b->cells, sizeof(int) * (size_t)(k->npc * k->n_cells));
  r->point_b = -1;
  for (int i = 0; i < k->n_nodes; ++i) {
    const double x = b->xy[2 * i], y = b->xy[2 * i + 1];
    k->xy[2 * i] = 25 * x, k->xy[2 * i + 1] = 25 * y * (1 + y * y / 16);
    if (x == 0 && y == 0) r->point_b = i;
  }
  r->n_bottom = hs->n_bottom_nodes;
  r->bottom = malloc(sizeof(int) * (size_t)r->n_bottom);
  memcpy(r->bottom, hs->bottom_nodes, sizeof(int) * (size_t)r->n_bottom);
  r->n_contact[1] = hs->n_contact_edges[1];
  r->contact[1] = malloc(sizeof(int) * 2 * (size_t)r->n_contact[1]);
  memcpy(r->contact[1], hs->contact_edges[1], sizeof(int) * 2 * (size_t)r->n_contact[1]);
  return r->point_b < 0;
}

static void roller_free(roller_scene *r) {
  for (int b = 0; b < 2; ++b) free(r->body[b].xy), free(r->body[b].cells), free(r->contact[b]);
  free(r->axis), free(r->bottom);
  memset(r, 0, sizeof *r);
}

/* h1: the cylinder's spacing at the contact point (mm); the block's is 1.37 h1. */
static int roller_build(roller_scene *r, double h1) {
  hertz_scene hs;
  memset(r, 0, sizeof *r);
  if (hertz_scene_build(&hs, h1 / RADIUS, 1.37 * h1 / 25, 0)) return 1;
  const int rc = cylinder_build(r, &hs) || block_build(r, &hs);
  hertz_scene_free(&hs);
  return rc;
}

typedef struct roller_result {
  double dy_b, siyy_b, p_axis, p_max, a, seconds, complementarity, equilibrium, force;
  long dofs, iterations;
} roller_result;

/* SIYY at node B of the block: the mean of the (constant) stresses of the cells around it, as a
   nodal stress from the volume. */
static double block_siyy_at(const mc_model *m, const mesh *k, int node) {
  double *sigma = malloc(sizeof(double) * 4 * (size_t)k->n_cells), sum = 0;
  int n = 0;
  mc_get_stress(m, 2, sigma);
  for (int e = 0; e < k->n_cells; ++e)
    for (int v = 0; v < k->npc; ++v)
      if (k->cells[k->npc * e + v] == node) sum += sigma[4 * e + 1], ++n;
  free(sigma);
  return n ? sum / n : NAN;
}

static int roller_solve(const roller_scene *r, int method, int surface, roller_result *out) {
  mc_model *m = NULL;
  if (mc_create(&m) != MC_OK) return 1;
  const double e[2] = {E_CYLINDER, E_BLOCK}, load[2] = {0, -FORCE};
  int rc = 1;
  for (int b = 0; b < 2; ++b)
    if (mc_set_mesh(m, b + 1, r->body[b].n_nodes, r->body[b].xy, r->body[b].n_cells, r->body[b].npc, r->body[b].cells) ||
        mc_set_material(m, b + 1, e[b], NU) || mc_set_contact(m, b + 1, r->n_contact[b], r->contact[b]))
      goto done;
  if (mc_fix(m, 1, r->n_axis, r->axis, MC_X, NULL) || mc_fix(m, 2, r->n_bottom, r->bottom, MC_XY, NULL) ||
      mc_add_nodal_force(m, 1, 1, &r->top, load) || mc_set_option_int(m, MC_OPTION_METHOD, method) ||
      mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, surface) || mc_solve(m))
    goto done;
  double *u = malloc(sizeof(double) * 2 * (size_t)r->body[1].n_nodes);
  mc_get_displacement(m, 2, u);
  out->dy_b = u[2 * r->point_b + 1];
  free(u);
  out->siyy_b = block_siyy_at(m, &r->body[1], r->point_b);
  mc_int n;
  mc_get_contact_count(m, &n);
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)n);
  double *p = malloc(sizeof(double) * (size_t)n), *f = malloc(sizeof(double) * (size_t)n),
         *normal = malloc(sizeof(double) * 2 * (size_t)n);
  mc_get_contact_nodes(m, nodes);
  mc_get_contact_pressure(m, p);
  mc_get_contact_force(m, f);
  mc_get_contact_normal(m, normal);
  double m0 = 0, m2 = 0;
  out->p_max = out->p_axis = out->force = 0;
  for (mc_int j = 0; j < n; ++j) {
    const double x = r->body[0].xy[2 * nodes[j]];
    out->p_max = fmax(out->p_max, p[j]);
    if (x == 0) out->p_axis = p[j];
    m0 += f[j], m2 += f[j] * x * x;
    out->force -= f[j] * normal[2 * j + 1];
  }
  out->a = 2 * sqrt(m2 / m0); /* the second moment of the forces: a^2 / 4 for Hertz's profile */
  free(nodes), free(p), free(f), free(normal);
  int64_t v;
  mc_get_info_int(m, MC_INFO_DOFS, &v), out->dofs = (long)v;
  mc_get_info_int(m, MC_INFO_ITERATIONS, &v), out->iterations = (long)v;
  mc_get_info_real(m, MC_INFO_TIME_TOTAL, &out->seconds);
  mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &out->complementarity);
  mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &out->equilibrium);
  rc = 0;
done:
  if (rc) fprintf(stderr, "nafems_roller: %s\n", mc_errmsg(m));
  mc_destroy(m);
  return rc;
}

static const char *method_name(int method) {
  return method == MC_METHOD_MORTAR ? "mortar" : method == MC_METHOD_DUAL_MORTAR ? "dual mortar" : "node-to-segment";
}

int main(int argc, char **argv) {
  const double finest = argc > 1 ? atof(argv[1]) : 0.125;
  if (!(finest > 0) || finest > 2) {
    fprintf(stderr, "usage: nafems_roller [finest_h1_mm in (0, 2]]\n");
    return 2;
  }
  /* Hertz, plane strain (Johnson, Contact Mechanics, 1985, sec. 4.2): 1/E* = (1 - nu^2)(1/E1 + 1/E2),
     a = sqrt(4 F R / (pi E*)), p0 = 2 F / (pi a), with the block flat (R the cylinder's). */
  const double e_star = 1 / ((1 - NU * NU) * (1 / E_CYLINDER + 1 / E_BLOCK));
  const double a = sqrt(4 * FORCE * RADIUS / (PI * e_star)), p0 = 2 * FORCE / (PI * a);
  printf("NAFEMS R0094 benchmark 1 (cylinder roller, frictionless, plane strain)\n\n");
  printf("Hertz: a = %.4f mm, p0 = %.2f N/mm^2 (SSNP154: a = %.2f, p0 = %.2f)\n\n", a, p0, HERTZ_A, HERTZ_P0);
  printf("| method | surface | h1 (mm) | DOFs | DY(B) (mm) | vs ref | SIYY(B) (N/mm^2) | vs ref | p(x=0) | vs Hertz p0 | "
         "max p | a (mm) | vs Hertz a | iterations | seconds |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (double h1 = 2; h1 >= finest * 0.999; h1 /= 2) {
    roller_scene r;
    if (roller_build(&r, h1)) {
      fprintf(stderr, "nafems_roller: mesh generation failed at h1 = %g\n", h1);
      return 1;
    }
    for (int method = 0; method < 3; ++method)
      for (int surface = MC_SURFACE_SMOOTH; surface <= MC_SURFACE_FACETED; ++surface) {
        roller_result o;
        if (roller_solve(&r, method, surface, &o)) return 1;
        if (fabs(o.force - FORCE) > 1e-8 * FORCE || o.complementarity > 1e-8 || o.equilibrium > 1e-8)
          fprintf(stderr, "nafems_roller: %s h1 %g: vertical contact force %.10g, complementarity %g, equilibrium %g\n",
                  method_name(method), h1, o.force, o.complementarity, o.equilibrium);
        printf("| %s | %s | %g | %ld | %.5f | %+.2f %% | %.1f | %+.2f %% | %.1f | %+.2f %% | %.1f | %.4f | %+.2f %% | %ld | "
               "%.2f |\n",
               method_name(method), surface == MC_SURFACE_SMOOTH ? "smooth" : "faceted", h1, o.dofs, o.dy_b,
               100 * (o.dy_b / REF_DY_B - 1), o.siyy_b, 100 * (o.siyy_b / REF_SIYY_B - 1), o.p_axis,
               100 * (o.p_axis / p0 - 1), o.p_max, o.a, 100 * (o.a / a - 1), o.iterations, o.seconds);
        fflush(stdout);
      }
    roller_free(&r);
  }
  printf("| NAFEMS (SSNP154 reference) | | | | %.5f | | %.1f | | | | | | | | |\n", REF_DY_B, REF_SIYY_B);
  printf("| Hertz | | | | | | | | %.1f | | | %.4f | | | |\n", p0, a);
  return 0;
}
