/* check_runner.c - the one Check runner every test program uses (kept out of scenes.c so that
   the benchmarks can reuse the scenes without linking Check). */
#include "scenes.h"

int sc_run_suite(Suite *suite) {
  SRunner *runner = srunner_create(suite);
  srunner_run_all(runner, CK_NORMAL);
  int failed = srunner_ntests_failed(runner);
  srunner_free(runner);
  return failed == 0 ? 0 : 1;
}
