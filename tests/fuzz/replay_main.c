/*
 * replay_main.c - runs the fuzz target (fuzz_api.c) on the files named on the command line,
 * without libFuzzer: the ctest fuzz_corpus_replay, so that the seed corpus runs in every
 * build (plain, ASan/UBSan, valgrind). Any contract violation aborts inside the target.
 *
 * Usage: fuzz_corpus_replay [--min-solves N] [--min-contact-solves N] [--min-host-solves N]
 *                           [--min-pair-solves N] [--min-friction-solves N] FILE...
 * Prints how many solves succeeded (with contact, with a host body, with contact positions on
 * two pairs or more, with friction rows that stick or slip) and fails if fewer than
 * asked: this checks that the corpus still reaches the solver (e.g. after an encoding change of
 * fuzz_api.c) and every kind of body. The fuzz build links the library statically, the plain
 * builds dynamically: tests/fuzz/CMakeLists.txt builds this driver with the fuzz build's flags
 * and link too (fuzz_replay), so that both see the same scenes from the same bytes.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern long fuzz_api_solves_ok, fuzz_api_contact_solves_ok, fuzz_api_host_solves_ok, fuzz_api_pair_solves_ok;
extern long fuzz_api_friction_solves_ok;

int main(int argc, char **argv) {
  long min_solves = 0, min_contact = 0, min_host = 0, min_pairs = 0, min_friction = 0;
  int k, files = 0;
  for (k = 1; k < argc; ++k) {
    FILE *f;
    uint8_t *data;
    long size;
    if (strcmp(argv[k], "--min-solves") == 0 && k + 1 < argc) {
      min_solves = atol(argv[++k]);
      continue;
    }
    if (strcmp(argv[k], "--min-contact-solves") == 0 && k + 1 < argc) {
      min_contact = atol(argv[++k]);
      continue;
    }
    if (strcmp(argv[k], "--min-host-solves") == 0 && k + 1 < argc) {
      min_host = atol(argv[++k]);
      continue;
    }
    if (strcmp(argv[k], "--min-pair-solves") == 0 && k + 1 < argc) {
      min_pairs = atol(argv[++k]);
      continue;
    }
    if (strcmp(argv[k], "--min-friction-solves") == 0 && k + 1 < argc) {
      min_friction = atol(argv[++k]);
      continue;
    }
    f = fopen(argv[k], "rb");
    if (!f) {
      fprintf(stderr, "cannot open %s\n", argv[k]);
      return 2;
    }
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    data = malloc(size > 0 ? (size_t)size : 1);
    if (!data || (size > 0 && fread(data, 1, (size_t)size, f) != (size_t)size)) {
      fprintf(stderr, "cannot read %s\n", argv[k]);
      fclose(f);
      free(data);
      return 2;
    }
    fclose(f);
    LLVMFuzzerTestOneInput(data, (size_t)size);
    free(data);
    files++;
  }
  printf("replayed %d inputs: %ld successful solves, %ld of them with contact, %ld with a host body, %ld with "
         "contact on two pairs or more, %ld with friction\n",
         files, fuzz_api_solves_ok, fuzz_api_contact_solves_ok, fuzz_api_host_solves_ok, fuzz_api_pair_solves_ok,
         fuzz_api_friction_solves_ok);
  if (fuzz_api_solves_ok < min_solves || fuzz_api_contact_solves_ok < min_contact || fuzz_api_host_solves_ok < min_host ||
      fuzz_api_pair_solves_ok < min_pairs || fuzz_api_friction_solves_ok < min_friction) {
    printf("FAILED: expected at least %ld successful solves, %ld with contact, %ld with a host body, %ld with "
           "contact on two pairs and %ld with friction\n",
           min_solves, min_contact, min_host, min_pairs, min_friction);
    return 1;
  }
  return 0;
}
