/* A minimal out-of-tree consumer of an installed mortarcontact: checks that the header and
 * the library agree on the version, that errors come back with a message, and solves one
 * small elasticity problem (no contact) so that the dependencies are really loaded. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <mortarcontact.h>

#define CHECK(call)                                                                      \
  do {                                                                                   \
    mc_status s_ = (call);                                                               \
    if (s_ != MC_OK) {                                                                   \
      fprintf(stderr, "%s:%d: %s -> %s: %s\n", __FILE__, __LINE__, #call,                \
              mc_status_string(s_), mc_errmsg(m));                                       \
      mc_destroy(m);                                                                     \
      return 1;                                                                          \
    }                                                                                    \
  } while (0)

int main(void) {
  mc_model *m = NULL;
  printf("mortarcontact header %s, library %s\n", MC_VERSION_STRING, mc_version_string());
  if (mc_version_number() != MC_VERSION_NUMBER || strcmp(mc_version_string(), MC_VERSION_STRING) != 0) {
    fprintf(stderr, "version mismatch between header and library\n");
    return 1;
  }
  CHECK(mc_create(&m));

  /* A unit square of two P1 triangles on body 1, bottom clamped, pulled up on top. */
  const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
  const mc_int cells[] = {0, 1, 2, 0, 2, 3};
  const mc_int bottom[] = {0, 1};
  const mc_int top[] = {2, 3};
  const double traction[] = {0.0, 1e-3};
  CHECK(mc_set_mesh(m, 1, 4, xy, 2, 3, cells));

  /* An error must come back as a status with a message, leaving the model usable. */
  mc_status bad = mc_set_material(m, 1, -1.0, 0.3);
  if (bad == MC_OK || mc_errmsg(m)[0] == '\0') {
    fprintf(stderr, "mc_set_material(E=-1) did not fail with a message (status %d)\n", (int)bad);
    mc_destroy(m);
    return 1;
  }
  printf("expected error: %s: %s\n", mc_status_string(bad), mc_errmsg(m));

  CHECK(mc_set_material(m, 1, 1.0, 0.3));
  CHECK(mc_fix(m, 1, 2, bottom, MC_XY, NULL));
  CHECK(mc_add_traction(m, 1, 1, top, traction));
  CHECK(mc_solve(m));
  double u[8];
  CHECK(mc_get_displacement(m, 1, u));
  printf("u_y at the top: %g %g\n", u[5], u[7]);
  mc_destroy(m);
  if (!(u[5] > 0 && u[7] > 0 && isfinite(u[5]) && isfinite(u[7]))) {
    fprintf(stderr, "the top of the square did not move up\n");
    return 1;
  }
  printf("consumer OK\n");
  return 0;
}
