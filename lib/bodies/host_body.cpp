#include "bodies/host_body.hpp"
#include "support/error.hpp"
#include "mortarcontact.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace mc {

HostBody make_host_body(int n_nodes, const int *equations, int n_equations, int base) {
  if (n_equations < 1) fail(MC_ERROR_ARGUMENT, "n_equations = %d: a host body needs at least 1 equation", n_equations);
  if (!equations) fail(MC_ERROR_ARGUMENT, "equations is NULL");
  HostBody host;
  host.n_equations = n_equations;
  host.equations.assign(2 * size_t(n_nodes), -1);
  host.node_of_equation.assign(n_equations, -1);
  host.component_of_equation.assign(n_equations, -1);
  for (size_t k = 0; k < 2 * size_t(n_nodes); ++k) {
    const long long e = (long long)equations[k] - base;
    if (e < 0) continue;  // no equation: restrained or absent
    if (e >= n_equations)
      fail(MC_ERROR_ARGUMENT, "%s = %d (node %zu, %s): equation number above the system, whose last is %d",
           array_position("equations", k, base).c_str(), equations[k], k / 2 + base, k % 2 ? "y" : "x", n_equations - 1 + base);
    const int other = host.node_of_equation[e];
    if (other >= 0)
      fail(MC_ERROR_ARGUMENT, "%s = %d: node %zu's %s and node %d's %s share equation %d: each freedom "
           "needs its own", array_position("equations", k, base).c_str(), equations[k], k / 2 + base, k % 2 ? "y" : "x", other + base,
           host.component_of_equation[e] ? "y" : "x", equations[k]);
    host.equations[k] = int(e);
    host.node_of_equation[e] = int(k / 2), host.component_of_equation[e] = int(k % 2);
  }
  host.load.assign(n_equations, 0.0);
  return host;
}

namespace {

// An equation number given by the host, made 0-based; -1 below the base (skipped). name[index]
// in messages.
int host_equation(const HostBody &host, int id, const char *name, size_t index, int base) {
  const long long e = (long long)id - base;
  if (e < 0) return -1;
  if (e >= host.n_equations)
    fail(MC_ERROR_ARGUMENT, "%s = %d: equation number above the system, whose last is %d",
         array_position(name, index, base).c_str(), id, host.n_equations - 1 + base);
  return int(e);
}

}  // namespace

void add_coordinate_entries(HostBody &host, int n, const int *rows, const int *cols, const double *values, int storage,
                            int base) {
  if (n < 0) fail(MC_ERROR_ARGUMENT, "n_entries = %d: must not be negative", n);
  if (storage != MC_MATRIX_FULL && storage != MC_MATRIX_TRIANGLE)
    fail(MC_ERROR_ARGUMENT, "storage = %d: must be MC_MATRIX_FULL (1) or MC_MATRIX_TRIANGLE (2)", storage);
  if (n == 0) return;
  if (!rows) fail(MC_ERROR_ARGUMENT, "rows is NULL");
  if (!cols) fail(MC_ERROR_ARGUMENT, "cols is NULL");
  if (!values) fail(MC_ERROR_ARGUMENT, "values is NULL");
  // Appended after the entries so far (reserved: no zero-filled copy first), and cut back if an
  // entry is bad.
  const size_t old = host.entry_row.size();
  host.entry_row.reserve(old + size_t(n)), host.entry_col.reserve(old + size_t(n));
  host.entry_value.reserve(old + size_t(n)), host.entry_half.reserve(old + size_t(n));
  const bool full = storage == MC_MATRIX_FULL;
  int triangle = 0;  // +1 upper (row < col), -1 lower, 0 not yet seen
  double largest = 0;
  try {
    for (size_t k = 0; k < size_t(n); ++k) {
      if (!std::isfinite(values[k]))
        fail(MC_ERROR_ARGUMENT, "%s is not finite", array_position("values", k, base).c_str());
      const int r = host_equation(host, rows[k], "rows", k, base), c = host_equation(host, cols[k], "cols", k, base);
      if (r < 0 || c < 0) continue;  // a restrained freedom's row or column
      if (!full && r != c) {
        const int side = r < c ? 1 : -1;
        if (triangle != 0 && side != triangle)
          fail(MC_ERROR_ARGUMENT,
               "%s, %s = (%d, %d) is in the %s triangle, earlier entries of this call in the %s: "
               "MC_MATRIX_TRIANGLE takes one triangle (each off-diagonal pair once); give both with MC_MATRIX_FULL",
               array_position("rows", k, base).c_str(), array_position("cols", k, base).c_str(), rows[k], cols[k], side > 0 ? "upper" : "lower", side > 0 ? "lower" : "upper");
        triangle = side;
      }
      if (full) largest = std::max(largest, std::fabs(values[k]));
      host.entry_row.push_back(std::min(r, c)), host.entry_col.push_back(std::max(r, c));
      host.entry_value.push_back(values[k]);
      host.entry_half.push_back(full && r != c ? (r < c ? 1 : 2) : 0);
    }
  } catch (...) {
    host.entry_row.resize(old), host.entry_col.resize(old), host.entry_value.resize(old), host.entry_half.resize(old);
    throw;
  }
  host.full_largest = std::max(host.full_largest, largest);
}

void add_element_matrices(HostBody &host, int n_elements, const int *eltptr, const int *eltvar, const double *a_elt,
                          int base) {
  if (n_elements < 0) fail(MC_ERROR_ARGUMENT, "n_elements = %d: must not be negative", n_elements);
  if (n_elements == 0) return;
  if (!eltptr) fail(MC_ERROR_ARGUMENT, "eltptr is NULL");
  if (!eltvar) fail(MC_ERROR_ARGUMENT, "eltvar is NULL");
  if (!a_elt) fail(MC_ERROR_ARGUMENT, "a_elt is NULL");
  if (eltptr[0] != base)
    fail(MC_ERROR_ARGUMENT, "%s = %d: the first element's equations start at eltvar's first entry, %d (the "
         "index base)", array_position("eltptr", 0, base).c_str(), eltptr[0], base);
  for (int e = 0; e < n_elements; ++e)
    if (eltptr[e + 1] < eltptr[e])
      fail(MC_ERROR_ARGUMENT, "%s = %d is less than %s = %d: element %d would have a negative number of "
           "equations", array_position("eltptr", size_t(e) + 1, base).c_str(), eltptr[e + 1],
           array_position("eltptr", size_t(e), base).c_str(), eltptr[e], e + base);
  // Appended in place (reserved first), and cut back if an element is bad: a call that fails
  // adds nothing.
  const size_t old = host.entry_row.size();
  size_t upper = 0;
  for (int e = 0; e < n_elements; ++e) {
    const size_t size = size_t(eltptr[e + 1] - eltptr[e]);
    upper += size * (size + 1) / 2;
  }
  host.entry_row.reserve(old + upper), host.entry_col.reserve(old + upper);
  host.entry_value.reserve(old + upper), host.entry_half.reserve(old + upper);
  std::vector<int> local;
  size_t offset = 0;  // into a_elt
  try {
    for (int e = 0; e < n_elements; ++e) {
      const size_t first = size_t(eltptr[e] - base), size = size_t(eltptr[e + 1] - eltptr[e]);
      local.resize(size);
      for (size_t a = 0; a < size; ++a) local[a] = host_equation(host, eltvar[first + a], "eltvar", first + a, base);
      const double *ke = a_elt + offset;
      double largest = 0;
      for (size_t k = 0; k < size * size; ++k) {
        if (!std::isfinite(ke[k]))
          fail(MC_ERROR_ARGUMENT, "%s (element %d) is not finite", array_position("a_elt", offset + k, base).c_str(),
               e + base);
        largest = std::max(largest, std::fabs(ke[k]));
      }
      // An element stiffness is positive semidefinite, so its diagonal is >= 0. A negative one
      // is what an inverted element gives (its nodes clockwise: the Jacobian, and with it the
      // whole matrix, changes sign). Said here, naming the element; summed with its neighbours
      // it would only show later as a bad diagonal at some equation, far from its cause.
      for (size_t a = 0; a < size; ++a)
        if (ke[a * size + a] < -1e-12 * largest) {
          char freedom[48] = "a restrained freedom";
          if (local[a] >= 0) std::snprintf(freedom, sizeof freedom, "equation %d", local[a] + base);
          fail(MC_ERROR_MESH, "element %d looks inverted (its nodes in clockwise order) or is otherwise not positive "
               "semidefinite: its matrix has the negative diagonal %g at row %zu (%s, %s), and an element "
               "stiffness has none; number the element's nodes counter-clockwise",
               e + base, ke[a * size + a], a + base, array_position("a_elt", offset + a * size + a, base).c_str(),
               freedom);
        }
      for (size_t j = 0; j < size; ++j)
        for (size_t i = 0; i <= j; ++i) {
          const double upper_value = ke[j * size + i], lower_value = ke[i * size + j];
          if (std::fabs(upper_value - lower_value) > 1e-12 * largest)
            fail(MC_ERROR_ARGUMENT, "%s (element %d, row %zu, column %zu) = %.17g but its mirror is %.17g: an "
                 "element matrix must be symmetric", array_position("a_elt", offset + j * size + i, base).c_str(),
                 e + base, i + base, j + base, upper_value, lower_value);
          const int r = local[i], c = local[j];
          if (r < 0 || c < 0) continue;  // a restrained freedom's row or column
          // the mean of the two halves; an equation listed twice in one element gets both
          // off-diagonal halves on its diagonal
          const double v = i == j ? upper_value : (r == c ? upper_value + lower_value : 0.5 * (upper_value + lower_value));
          host.entry_row.push_back(std::min(r, c)), host.entry_col.push_back(std::max(r, c));
          host.entry_value.push_back(v), host.entry_half.push_back(0);
        }
      offset += size * size;
    }
  } catch (...) {
    host.entry_row.resize(old), host.entry_col.resize(old), host.entry_value.resize(old), host.entry_half.resize(old);
    throw;
  }
}

SymmetricCsc assemble_host_stiffness(const HostBody &host, int body, int base) {
  const int n = host.n_equations;
  const size_t count = host.entry_row.size();
  // Counting sort by column, then rows sorted and duplicates summed within each column; an
  // MC_MATRIX_FULL pair's two triangles are summed apart and must agree.
  std::vector<int> start(size_t(n) + 1, 0);
  for (size_t k = 0; k < count; ++k) start[host.entry_col[k] + 1]++;
  for (int j = 0; j < n; ++j) start[j + 1] += start[j];
  std::vector<int> next(start.begin(), start.end() - 1), order(count);
  for (size_t k = 0; k < count; ++k) order[size_t(next[host.entry_col[k]]++)] = int(k);
  SymmetricCsc a;
  a.n = n;
  a.colptr.assign(size_t(n) + 1, 0);
  a.rows.reserve(count), a.values.reserve(count);
  struct Sum {
    int row;
    double whole, upper, lower;
  };
  std::vector<std::pair<int, int>> column;  // (row, entry)
  for (int j = 0; j < n; ++j) {
    column.clear();
    for (int p = start[j]; p < start[j + 1]; ++p) column.emplace_back(host.entry_row[order[p]], order[p]);
    std::sort(column.begin(), column.end());
    for (size_t p = 0; p < column.size();) {
      Sum sum{column[p].first, 0, 0, 0};
      for (; p < column.size() && column[p].first == sum.row; ++p) {
        const int k = column[p].second;
        const double v = host.entry_value[k];
        (host.entry_half[k] == 1 ? sum.upper : host.entry_half[k] == 2 ? sum.lower : sum.whole) += v;
      }
      if (std::fabs(sum.upper - sum.lower) > 1e-12 * host.full_largest)
        fail(MC_ERROR_ARGUMENT,
             "body %d: the MC_MATRIX_FULL entries at (%d, %d) sum to %.17g and at (%d, %d) to %.17g: a matrix given "
             "in both triangles must be symmetric (or give one triangle with MC_MATRIX_TRIANGLE)",
             body, sum.row + base, j + base, sum.upper, j + base, sum.row + base, sum.lower);
      a.rows.push_back(sum.row), a.values.push_back(sum.whole + 0.5 * (sum.upper + sum.lower));
    }
    const bool has_diagonal = int(a.rows.size()) > a.colptr[j] && a.rows.back() == j;
    if (!has_diagonal || !(a.values.back() > 0)) {
      const double d = has_diagonal ? a.values.back() : 0.0;
      char whose[64] = "";
      if (host.node_of_equation[j] >= 0)
        std::snprintf(whose, sizeof whose, " (node %d, %s)", host.node_of_equation[j] + base,
                      host.component_of_equation[j] ? "y" : "x");
      if (d < 0)
        fail(MC_ERROR_SINGULAR,
             "body %d: the host's stiffness has the negative diagonal %g at equation %d%s: it is not positive "
             "semidefinite, as a stiffness is; an inverted element (nodes in clockwise order) gives a negative "
             "stiffness: check the orientation of the elements at that node",
             body, d, j + base, whose);
      fail(MC_ERROR_SINGULAR,
           "body %d: the host's stiffness has diagonal %g at equation %d%s: a stiffness matrix has a positive "
           "diagonal (an equation no entry reaches is a freedom nothing holds)",
           body, d, j + base, whose);
    }
    a.colptr[j + 1] = int(a.rows.size());
  }
  return a;
}

}  // namespace mc
