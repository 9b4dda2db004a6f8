/*
 * test_westergaard.c - Westergaard's periodic wavy contact, the scene of bench/westergaard.c at
 * a small size: N = 4 wavelengths, 40 body-1 cells per wavelength (Q1, non-matching), pm = 0.3 p*
 * (tests/westergaard_scene.h). Many separate contact patches on one interface, against the closed
 * form (K. L. Johnson, Contact Mechanics, section 13.2):
 * - one patch per crest (N - 1 whole ones, a half one at each wall), separate;
 * - the crest-node pressure, averaged over the interior crests, within 3 % of 2 sqrt(pm p*)
 *   (measured: +0.065 %), and at every interior crest within 3 %;
 * - the half-width a, sin^2(pi a / L) = pm / p*: the last active node on every side of every
 *   interior patch within two body-1 spacings h of a (measured: 7 h from the crest, a = 7.38 h),
 *   and the half-width measured (last active node + h/2, averaged) within 2 h (measured: +0.12 h);
 * for each interface solver (MC_INTERFACE_CONDENSED, MC_INTERFACE_SPARSE, MC_INTERFACE_AUTO), and
 * the solvers' pressures the same (to 1e-6 p0: both solve the same discrete problem exactly).
 * The waviness is the initial gap (mc_set_gap_offset); also checked with body 2's top meshed wavy.
 */
#include "check_helpers.h"
#include "mortarcontact.h"
#include "scenes.h"
#include "westergaard_scene.h"
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char *solver_name(int s) {
  return s == MC_INTERFACE_AUTO ? "auto" : s == MC_INTERFACE_CONDENSED ? "condensed" : "sparse";
}

/* Solves the scene with one interface solver, checks it against the closed form, returns the
   pressures (caller frees) and their count. */
static double *solve_and_check(const wg_scene *s, int solver, mc_int *q) {
  mc_model *m = wg_model(s, 1, solver);
  ck_assert_ptr_nonnull(m);
  OK(mc_solve(m));
  OK(mc_get_contact_count(m, q));
  double *pressure = malloc(sizeof(double) * (size_t)*q);
  wg_result r;
  ck_assert_int_eq(wg_measure(m, s, &r, pressure), 0);
  const int N = s->prm.wavelengths;
  const double p0_error = r.p0_mean / s->p0_exact - 1;
  printf("westergaard %s%s (ran %ld): N %d, n %d, DOFs %ld, contact nodes %ld, active %ld, patches %d, iterations "
         "%ld; p0 %+.3f %% (crests %+.3f .. %+.3f %%), a %.5f vs %.5f (%+.2f h), last active node %.2f .. %.2f h\n",
         solver_name(solver), s->prm.wavy_mesh ? ", wavy mesh" : "", r.interface_solver, N, s->prm.cells, r.dofs,
         r.contact_nodes, r.active_nodes, r.patches, r.iterations, 100 * p0_error,
         100 * (r.p0_min / s->p0_exact - 1), 100 * (r.p0_max / s->p0_exact - 1), r.a_mean, s->a_exact,
         (r.a_mean - s->a_exact) / r.h, r.a_last_min / r.h, r.a_last_max / r.h);
  ck_assert_msg(r.patches == N + 1, "%d contact patches, expected %d", r.patches, N + 1);
  ck_assert_msg(fabs(p0_error) < 0.03, "crest pressure %g against 2 sqrt(pm p*) = %g", r.p0_mean, s->p0_exact);
  ck_assert_msg(fabs(r.p0_min / s->p0_exact - 1) < 0.03 && fabs(r.p0_max / s->p0_exact - 1) < 0.03,
                "crest pressures %g .. %g against %g", r.p0_min, r.p0_max, s->p0_exact);
  ck_assert_msg(fabs(r.a_mean - s->a_exact) < 2 * r.h, "half-width %g against %g (h = %g)", r.a_mean, s->a_exact, r.h);
  ck_assert_msg(r.a_last_min >= s->a_exact - 2 * r.h && r.a_last_max <= s->a_exact + 2 * r.h,
                "last active node %g .. %g from the crest, a = %g, h = %g", r.a_last_min, r.a_last_max, s->a_exact,
                r.h);
  mc_destroy(m);
  return pressure;
}

START_TEST(westergaard_patches_against_closed_form) {
  wg_params prm = wg_default_params();
  prm.wavelengths = 4;
  wg_scene s;
  ck_assert_int_eq(wg_scene_build(&s, &prm), 0);
  const int solvers[3] = {MC_INTERFACE_CONDENSED, MC_INTERFACE_SPARSE, MC_INTERFACE_AUTO};
  double *pressure[3];
  mc_int q[3];
  for (int k = 0; k < 3; ++k) pressure[k] = solve_and_check(&s, solvers[k], &q[k]);
  for (int k = 1; k < 3; ++k) {
    ck_assert_int_eq(q[k], q[0]);
    double diff = 0;
    for (mc_int j = 0; j < q[0]; ++j) diff = fmax(diff, fabs(pressure[k][j] - pressure[0][j]));
    printf("westergaard: %s against condensed, largest pressure difference %.2e p0\n", solver_name(solvers[k]),
           diff / s.p0_exact);
    ck_assert_msg(diff < 1e-6 * s.p0_exact, "%s and condensed pressures differ by %g p0", solver_name(solvers[k]),
                  diff / s.p0_exact);
  }
  for (int k = 0; k < 3; ++k) free(pressure[k]);
  wg_scene_free(&s);
}
END_TEST

/* The same with the waviness in body 2's mesh instead of the gap offsets. */
START_TEST(westergaard_wavy_mesh) {
  wg_params prm = wg_default_params();
  prm.wavelengths = 4;
  prm.wavy_mesh = 1;
  wg_scene s;
  ck_assert_int_eq(wg_scene_build(&s, &prm), 0);
  mc_int q;
  free(solve_and_check(&s, MC_INTERFACE_AUTO, &q));
  wg_scene_free(&s);
}
END_TEST

int main(void) {
  setvbuf(stdout, NULL, _IOLBF, 0); /* the measurements reach the log even if a check fails */
  Suite *suite = suite_create("westergaard");
  TCase *tc = tcase_create("westergaard");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, westergaard_patches_against_closed_form);
  tcase_add_test(tc, westergaard_wavy_mesh);
  suite_add_tcase(suite, tc);
  return sc_run_suite(suite);
}
