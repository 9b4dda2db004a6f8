/*
 * contact_checks.h - results at the contact nodes and the checks every contact scene makes
 * (KKT of (3.5) from the returned arrays and the library's residual infos, force balance of both
 * bodies), and the shared Hertz scene (hertz_scene.h) in any role and unit system. Used by the
 * Check programs test_contact_scenes and test_contact_geometry (CMake target mc_contact_checks).
 * The assertions are Check's: call these from inside a Check test.
 */
#ifndef MC_TESTS_CONTACT_CHECKS_H
#define MC_TESTS_CONTACT_CHECKS_H

#include <stddef.h>

#include "hertz_scene.h"
#include "mortarcontact.h"

double max_d(double a, double b);
double max_abs(const double *v, size_t n);
/* Displacements of a body, 2 per node (caller frees). */
double *displacement(mc_model *m, int body, mc_int n_nodes);
long info_int(mc_model *m, int info);

/* ---- results at the body-1 contact nodes, KKT and equilibrium ---------------------------- */

typedef struct contact_data {
  mc_int n;
  mc_int *nodes;
  double *force, *gap, *g0, *pressure, *normal; /* normal: 2 per node */
} contact_data;


/* Every contact array of the last solve (caller frees with contact_free). */
contact_data contact_get(mc_model *m);
void contact_free(contact_data *c);
/* KKT of (3.5) from the returned arrays: lambda >= 0, gap >= 0, lambda gap = 0 (relative to the
   largest force and to length_scale, the size of the displacements and initial gaps), no force
   where no mortar surface is seen; plus the library's own residual infos
   (MC_INFO_EQUILIBRIUM, MC_INFO_COMPLEMENTARITY, MC_INFO_GAP_RESIDUAL < 1e-10). */
void assert_kkt(mc_model *m, const contact_data *c, double length_scale);
/* Largest |displacement| of both bodies and |g0| of the seeing nodes: the length scale of the
   gap checks. */
double length_scale_of(mc_model *m, const mc_int n_nodes[2], const contact_data *c);
/* Force balance of each body from returned data: support reactions + applied loads (their
   resultants load[b]) + contact forces = 0; body 1 receives -lambda_j n_j, body 2 the opposite. */
void assert_force_balance(mc_model *m, const contact_data *c, const mc_int n_nodes[2], const double load1[2],
                          const double load2[2]);
void assert_kkt_and_balance(mc_model *m, const mc_int n_nodes[2], const double load1[2], const double load2[2]);

/* ---- the Hertz scene in any role and unit system ------------------------------------------ */

/* The shared Hertz scene (hertz_scene.h) with the disc as body `disc_body` (1: the disc is the
   non-mortar side, as in the benchmark; 2: the block is), lengths multiplied by `length`
   (also the thickness, so a consistent 3D unit system), moduli and tractions by `young`. */
typedef struct hertz_setup {
  double h_disc, h_block;
  int disc_body, normal, method;
  double length, young;
  int surface; /* MC_OPTION_CONTACT_SURFACE; 0 (the zero-initialized default) is MC_SURFACE_SMOOTH */
} hertz_setup;

typedef struct hertz_run {
  mc_model *m;
  hertz_scene scene;
  mc_int n_nodes[2]; /* per body number */
  const hertz_mesh *mesh[2];
  double *xy1;       /* body 1's scaled coordinates */
  double load_total; /* the downward force on the disc */
} hertz_run;

typedef struct hertz_measure {
  double p0;       /* largest nodal pressure */
  double p0_fit;   /* p0 of the Hertz shape fitted to the nodal pressures, p^2 = p0^2 (1 - x^2/a^2) */
  double a_fit;    /* half-width from the second moment of the nodal forces (Hertz: a^2/4) */
  double a_nodes;  /* half the distance between the outermost loaded nodes */
  double gap_edge; /* half the distance between the innermost unloaded nodes (seeing ones) */
  double vertical; /* the vertical contact force on body 1 (on the disc after hertz_solve) */
  long iterations, active;
} hertz_measure;

void hertz_build(hertz_run *r, const hertz_setup *hs);
void hertz_free(hertz_run *r);
/* The loads on each body (resultants) for the balance check. */
void hertz_loads(const hertz_run *r, const hertz_setup *hs, double load1[2], double load2[2]);
/* Two estimates free of the mesh-spacing quantization of the loaded-node count: p^2 is linear
   in x^2 for the Hertz profile, so a least-squares line through the nodes with p > 0.3 p0 (away
   from the ends, where the lumped pressure of a partly loaded node is not the point value)
   gives p0; the half-width comes from the second moment of the nodal forces, an integral that
   does not see a nodal ripple: sum lambda x^2 / sum lambda = a^2/4 for a Hertz profile. */
hertz_measure hertz_measure_of(const hertz_run *r, double length);
/* The same measures from any solve whose body-1 contact nodes lie along x (coordinates xy1 of
   body 1, divided by length); iterations and active are left 0. */
hertz_measure hertz_profile_of(const contact_data *c, const double *xy1, double length);
/* Builds, solves (asserting KKT and balance), measures and frees; pressures in units of E. */
hertz_measure hertz_solve(const hertz_setup *hs);

#endif
