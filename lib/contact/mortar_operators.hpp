// The discrete non-penetration constraint: one row per trace point of Gamma_c (the paper's
// cone K_h, section 3):
//     (u1(x_j) - pi_h(u2)(x_j)) . n_j <= g0_j
// where u1(x_j) is body 1's displacement at trace point j (a node, or a point inside a partly
// covered segment at an end of Gamma_c) and pi_h(u2)(x_j) = sum_l w_jl u2(y_l) over body-2
// surface nodes y_l. The weights w depend on the method:
//   mortar       : pi_h of (3.2) with the paper's multiplier space M_h^1 (constant on the two
//                  end elements): end values by interpolation, interior values D^-1 (M - D_E P_E);
//                  on a closed loop (no ends) all values D^-1 M with M_h^1 = W_h^1
//   dual mortar  : the same with Wohlmuth's biorthogonal test functions (D diagonal)
// A body 1 with quadratic cells has weak rows instead (weak_mortar_rows.cpp): one per multiplier,
// integral of psi_i ((u1 - u2) . n - g0) <= 0, with the paper's linear multipliers, quadratic
// ones (MC_OPTION_MULTIPLIER) or the quadratic space's dual basis (dual mortar).
//   node-to-segment: interpolation of u2 at the point each body-1 node projects to (no pi_h)
#pragma once
#include "contact/contact_geometry.hpp"
#include <memory>
#include <vector>

namespace mc {

struct ConstraintRows {
  // Row r: body-1 part sum_k weight1 u1(position1) (CSR start1), body-2 part sum_l weight2 u2
  // (CSR start2), along normal[r], initial gap gap0[r] (the host's offsets not included).
  std::vector<int> start1{0}, position1;
  std::vector<double> weight1;
  std::vector<int> start2{0}, body2_node;
  std::vector<double> weight2;
  std::vector<Point> normal;
  // Rows whose direction varies along the row (the weak rows of a quadratic body 1, where each
  // quadrature point measures the gap along its own normal): the vector weight of each body-1
  // and body-2 entry, parallel to weight1 and weight2 (row r reads sum_k vector1 . u1 -
  // sum_l vector2 . u2 <= g0). Empty: every entry's direction is its row's normal.
  std::vector<Point> vector1, vector2;
  std::vector<double> gap0;
  // Per row, the integral of its multiplier's function over Gamma_c (the line measure included): a
  // traction t acting on the row's multiplier is the force t * measure[r] (friction's Tresca
  // bound). The trace point's hat for the paper's rows, the position's tributary measure for
  // node-to-segment, the multiplier's integral for the weak rows.
  std::vector<double> measure;
  // The contact pressure of a weak row's method (a quadratic body 1): the multiplier field
  // mu = sum_i (lambda_i / int psi_i) psi_i itself, continuous piecewise linear on Gamma_c, at each
  // contact position: pressure[pos] = sum over (row, c) in pressure_of_position[pos] of
  // c lambda[row]. Empty for the paper's rows (their pressure is the lumped one).
  std::vector<std::vector<std::pair<int, double>>> pressure_of_position;
  // The position whose nodal row this is (its gap is reported there); -1 for a row at an end
  // of Gamma_c inside a partly covered segment.
  std::vector<int> own_position;
  int size() const { return int(normal.size()); }

  // The same rows in the form the sparse interface solver uses (sparse_contact_solve.hpp). A
  // mortar row's body-2 weights are D^-1 (M - D_E P_E): D is tridiagonal, so they spread over
  // the whole run (truncated above at 1e-17) and B^T B would be nearly dense along a long
  // interface. Instead the values w_a = pi_h(u2)(x_a) of a run's interior trace points are
  // kept as auxiliary unknowns (two components each), tied to u2 by the sparse equations
  //     sum_b D_ab w_b - sum_l R_al u2_l = 0   (per component; R = M - D_E P_E, (3.2)),
  // and the row reads  sum_k weight1 u1(position1) . n - w_a . n <= g0.
  // aux[r]: row r's auxiliary point, or -1 where the row's weights2 are used as they are (the
  // ends of Gamma_c, one-element runs, node-to-segment).
  std::vector<int> aux;
  int aux_count = 0;
  // Per auxiliary point a: its D entries (aux_d_point, aux_d) and its R entries (aux_r_node,
  // body-2 nodes, aux_r), CSR.
  std::vector<int> aux_d_start{0}, aux_d_point;
  std::vector<double> aux_d;
  std::vector<int> aux_r_start{0}, aux_r_node;
  std::vector<double> aux_r;

  // The explicit weights D^-1 R of a run's interior rows are not stored here (start2 gives those
  // rows none): some 60 per row on a long interface, they go to B only (MortarWeights computes
  // them), and the sparse path, which reads w_a instead, gets them later or not at all. Per such
  // run what computes them: its rows first_row .. first_row + n - 1, interior points first..last
  // (an interior point's row is first_row + point), D (lower, diag, upper; cyclic when closed)
  // and R's rows per point (CSR, merged, zeros kept: the terms the weights sum).
  struct PendingRun {
    int first_row = 0, n = 0, first = 0, last = 0;
    bool closed = false;
    std::vector<double> lower, diag, upper;
    std::vector<int> r_start{0}, r_node;
    std::vector<double> r_value;
    size_t middle_length = 0;  // the run's middle row's weights: n times it sizes B's arrays
  };
  std::vector<PendingRun> pending;
  int body2_columns = 0;  // the body-2 node ids the weights range over (0 .. body2_columns - 1)
  // Row r's weights are computed (not in start2): an interior row of a pending run.
  bool weights_pending(int r) const;
  // The body-2 weights the pending rows will have (n times each run's middle row): an estimate.
  size_t pending_weights_estimate() const;
  // The body-2 weights and what computes them, freed once B holds them (the stacked rows never
  // had them).
  void release_mortar_weights() {
    std::vector<int>().swap(body2_node);
    std::vector<double>().swap(weight2);
    std::vector<Point>().swap(vector2);
    std::vector<PendingRun>().swap(pending);
  }
};

// The body-2 weights of rows row after row: the stored ones (start2) as they are, a pending
// run's interior rows computed: row k is sum_j (D^-1)_kj R_j, the same arithmetic, term for term
// and in the same order, as when they were stored.
class MortarWeights {
public:
  explicit MortarWeights(const ConstraintRows &rows);
  ~MortarWeights();
  // Row r's body-2 nodes (ascending) and weights, and its vector2 entries (empty unless the rows
  // have them).
  void row(int r, std::vector<int> &nodes, std::vector<double> &weights, std::vector<Point> &vectors);

private:
  struct Work;
  const ConstraintRows &rows_;
  std::unique_ptr<Work> work_;
};

// measure: the weight of the mortar integrals (the dual basis is biorthogonal in it).
// multiplier: MC_MULTIPLIER_*, a quadratic body 1's multiplier space (unused for a linear one).
ConstraintRows build_constraint_rows(const ContactGeometry &geometry, int method, int multiplier,
                                     const LineMeasure &measure);

}  // namespace mc
