/*
 * convergence_study.c - the full nested-mesh study of the paper's Theorem 4.1
 * (docs/convergence.md): the H1 error of u and the L2 error of the contact pressure against
 * an overkill solution, for the three methods, on non-matching (h2/h1 = 1.375) and matching
 * meshes. The scene and the error computation are those of tests/contact_study.c (the quick
 * variant runs in the test suite as test_contact_convergence).
 *
 * usage: convergence_study [levels (default 5)] [reference level (default 7)]
 */
#include "contact_study.h"
#include "mortarcontact.h"
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
  int levels = argc > 1 ? atoi(argv[1]) : 5, reference = argc > 2 ? atoi(argv[2]) : 7;
  const char *names[3] = {"mortar", "dual mortar", "node-to-segment"};
  printf("| method | meshes | level | h1 | h2 | DOFs | H1 error of u | rate | L2 error of p | rate |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (int matching = 0; matching <= 1; ++matching)
    for (int method = 0; method < 3; ++method) {
      contact_study_level *out = calloc(levels, sizeof *out);
      if (contact_study_run(method, matching, levels, reference, out)) return 1;
      for (int k = 0; k < levels; ++k) {
        printf("| %s | %s | %d | %.5f | %.5f | %ld | %.4e | ", names[method], matching ? "matching" : "non-matching", k,
               out[k].h1, out[k].h2, out[k].dofs, out[k].error_h1);
        if (k > 0) printf("%.2f", contact_study_rate(out[k - 1].error_h1, out[k].error_h1));
        printf(" | %.4e | ", out[k].error_l2_pressure);
        if (k > 0) printf("%.2f", contact_study_rate(out[k - 1].error_l2_pressure, out[k].error_l2_pressure));
        printf(" |\n");
        fflush(stdout);
      }
      free(out);
    }
  return 0;
}
