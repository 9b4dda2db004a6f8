/*
 * contact_study.h - the nested-mesh convergence study of the paper's Theorem 4.1, shared by
 * the quick Check test (test_contact_convergence) and the full documented study
 * (bench/convergence_study).
 *
 * Scene: body 1 = [0,1]x[0,0.5] (non-mortar) resting on body 2 = [0,1]x[-0.5,0], E = 1,
 * nu = 0.3, plane strain. Body 2 is clamped at y = -0.5; body 1 has u_x = 0 on x = 0 and is
 * held vertically by contact alone. The top of body 1 carries p(x) = 0.5 + 1.5 cos(pi x): it
 * pushes on the left and pulls on the right, so the contact zone ends at a free point that is
 * not a mesh node. Meshes: P1, body 1 with 11*2^k x 11*2^(k-1)... squares, body 2 with 8*2^k
 * (ratio h2/h1 = 1.375) or the same as body 1 (matching). Levels are nested within each body,
 * so the error of level k against the overkill level is computed exactly by interpolating
 * level k onto the overkill mesh.
 */
#ifndef MC_TESTS_CONTACT_STUDY_H
#define MC_TESTS_CONTACT_STUDY_H

typedef struct contact_study_level {
  int level;
  double h1, h2;        /* cell sizes on the contact line */
  long dofs;
  double error_h1;      /* ||u_k - u_ref||_H1 over both bodies */
  double error_l2_pressure;  /* ||p_k - p_ref||_L2(Gamma_c) of the lumped pressures */
  double seconds;
} contact_study_level;

/* Solves levels 0..n_levels-1 and the overkill level `reference` (> all levels) with the
   given method (MC_METHOD_*); matching != 0 uses body 1's mesh size for body 2. Fills out[]
   (n_levels entries). Returns 0 on success. */
int contact_study_run(int method, int matching, int n_levels, int reference, contact_study_level *out);

/* Observed rate between levels k and k+1: log2(e_k / e_{k+1}). */
double contact_study_rate(double coarse, double fine);

#endif
