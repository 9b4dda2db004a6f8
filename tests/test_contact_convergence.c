/*
 * test_contact_convergence.c - the paper's Theorem 4.1 observed: on nested non-matching
 * meshes (h2/h1 = 1.375) the H1 error of the mortar solution against an overkill solution
 * decreases at a rate >= 0.75 (the theorem's h1^{3/4} + h2 for H2 solutions). The full study
 * (all methods, matching and not, the pressure's L2 error) is bench/convergence_study.
 */
#include "contact_study.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <stdio.h>

START_TEST(mortar_h1_rate_non_matching) {
  contact_study_level levels[4];
  ck_assert_int_eq(contact_study_run(MC_METHOD_MORTAR, 0, 4, 5, levels), 0);
  for (int k = 0; k < 4; ++k) {
    printf("level %d h1 %.5f h2 %.5f DOFs %ld  H1 error %.4e", k, levels[k].h1, levels[k].h2, levels[k].dofs,
           levels[k].error_h1);
    if (k > 0) printf("  rate %.3f", contact_study_rate(levels[k - 1].error_h1, levels[k].error_h1));
    printf("\n");
  }
  double last = contact_study_rate(levels[2].error_h1, levels[3].error_h1);
  double previous = contact_study_rate(levels[1].error_h1, levels[2].error_h1);
  ck_assert_msg(last >= 0.75, "observed H1 rate %.3f < 0.75", last);
  ck_assert_msg(previous >= 0.75, "observed H1 rate %.3f < 0.75", previous);
}
END_TEST

int main(void) {
  Suite *suite = suite_create("contact_convergence");
  TCase *tc = tcase_create("theorem_4_1");
  tcase_set_timeout(tc, 600);
  tcase_add_test(tc, mortar_h1_rate_non_matching);
  suite_add_tcase(suite, tc);
  return sc_run_suite(suite);
}
