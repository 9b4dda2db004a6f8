/* The name of a cell kind from its number of nodes per cell (3 P1, 4 Q1, 6 T6, 8 Q8, 9 Q9), for
   the messages and tables of the tests and benchmarks. Header-only: the benchmarks include it
   without linking the test helpers. */
#ifndef MC_TESTS_CELL_KIND_NAME_H
#define MC_TESTS_CELL_KIND_NAME_H

static inline const char *cell_kind_name(int nodes_per_cell) {
  switch (nodes_per_cell) {
    case 3: return "P1";
    case 4: return "Q1";
    case 6: return "T6";
    case 8: return "Q8";
    case 9: return "Q9";
    default: return "?";
  }
}

#endif
