/* readme_example.c - the 20-line example of README.md, built and run by the test suite. */
#include <mortarcontact.h>
#include <stdio.h>
int main(void) {              /* a unit square pressed onto a clamped one, P1, plane strain */
  double xy[] = {0,0, 1,0, 1,1, 0,1};      mc_int tri[] = {0,1,2, 0,2,3};
  double xy2[] = {0,-1, 1,-1, 1,0, 0,0};   mc_int top[] = {1,2}, bottom1[] = {0,1};
  mc_int left[] = {0,3}, base[] = {0,1}, surface2[] = {2,3}; double p[] = {0.1}; /* on rollers */
  mc_model *m; mc_create(&m);
  mc_set_mesh(m, 1, 4, xy, 2, 3, tri);     mc_set_mesh(m, 2, 4, xy2, 2, 3, tri);
  mc_set_material(m, 1, 1.0, 0.3);         mc_set_material(m, 2, 1.0, 0.3);
  mc_fix(m, 1, 2, left, MC_X, NULL);       mc_fix(m, 2, 2, left, MC_X, NULL);
  mc_fix(m, 2, 2, base, MC_Y, NULL);
  mc_add_pressure(m, 1, 1, (mc_int[]){2,3}, p);   /* on the top edge */
  mc_set_contact(m, 1, 1, bottom1);        mc_set_contact(m, 2, 1, surface2);
  if (mc_solve(m) != MC_OK) { fprintf(stderr, "%s\n", mc_errmsg(m)); return 1; }
  mc_int n; mc_get_contact_count(m, &n); double pressure[8]; mc_get_contact_pressure(m, pressure);
  for (mc_int j = 0; j < n; ++j) printf("p[%d] = %g\n", (int)j, pressure[j]);
  mc_destroy(m); return 0;
}
