/*
 * sphere_on_flat.h - the axisymmetric Hertz scene solved with the library: a sphere of radius
 * 1 pressed on a flat (hertz_scene_axisymmetric), shared by tests/test_axisymmetric.c and
 * bench/axisymmetric_hertz.c.
 *
 * Body 1 (the hemisphere) floats axially, held by contact alone; the axis holds u_r = 0 by
 * itself. Body 2 (a cylinder of radius 4 and height 4) is clamped at its base. E = 1,
 * nu = 0.3 for both; total force SPHERE_LOAD as a uniform pressure on the flat top.
 */
#ifndef SPHERE_ON_FLAT_H
#define SPHERE_ON_FLAT_H

#ifdef __cplusplus
extern "C" {
#endif

#define SPHERE_LOAD 0.0025    /* total force: Hertz a = 0.1506, a / R small */
#define SPHERE_H2_RATIO 1.37 /* body 2 spacing / body 1 spacing: non-matching, as bench/hertz_sweep */

typedef struct sphere_result {
  long dofs;
  double load, total_force;  /* the applied force and the sum of the contact forces (axial) */
  double p0, a;              /* fitted to the pressure profile: p^2 = p0^2 (1 - r^2 / a^2) */
  double a_nodes;            /* midway between the outermost loaded node and the next one */
  double a_moment;           /* sqrt(5/2 sum f r^2 / sum f) over the axial contact forces: exact for
                                Hertz's p0 sqrt(1 - r^2/a^2) (its r^2-moment is 2 a^2 / 5), and it
                                needs no fit (bench/hertz_quadratic's a_moment, axisymmetric) */
  double p_max;              /* the largest nodal pressure */
  double axis_pressure;      /* the nodal pressure at the axis node */
  double p0_hertz, a_hertz;
  double seconds;            /* MC_INFO_TIME_TOTAL of the solve */
  double seconds_assembly, seconds_factorization, seconds_contact; /* MC_INFO_TIME_* */
  int active, iterations;
} sphere_result;

/* h: body 1's fine spacing near the contact (body 2: SPHERE_H2_RATIO h); quads: 0 = P1, 1 = Q1.
   plane: MC_AXISYMMETRIC, or MC_PLANE_STRAIN to solve the same meshes as a plane half-scene
   (u_x = 0 on x = 0; for the speed comparison only: its numbers are not Hertz's).
   normal: MC_NORMAL_*. Returns 0 on success, else the failing mc_status (or -1: bad mesh). */
int sphere_on_flat_solve(double h, int quads, int method, int normal, int plane, sphere_result *r);
/* The default: axisymmetric, body 2's normals (the flat's: exact directions). */
int sphere_on_flat(double h, int quads, int method, sphere_result *r);
/* The same with any cell kind: nodes_per_cell = 3 (P1) or 4 (Q1) (as quads = 0, 1 above), 6 (T6),
   8 (Q8) or 9 (Q9) (hertz_scene_axisymmetric_cells: h is then a cell's size, its mid-edge nodes
   at h / 2). multiplier: MC_OPTION_MULTIPLIER (used by a quadratic body 1). With
   MC_MULTIPLIER_LINEAR (and MC_METHOD_MORTAR) a quadratic body 1 carries its multipliers on the cells' corners, its
   middles' pressures being their linear interpolation: the profile fit, a_nodes and the axis
   pressure then use the corner positions only; otherwise every contact position. */
int sphere_on_flat_solve_cells(double h, int nodes_per_cell, int method, int normal, int plane, int multiplier,
                               sphere_result *r);

#ifdef __cplusplus
}
#endif
#endif
