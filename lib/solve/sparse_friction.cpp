// Friction on the sparse interface path (docs/theory.md, "Friction"): the stick/slip iteration
// (friction_iteration.hpp) whose linear systems are the sparse path's KKT systems
// (sparse_contact_solve.hpp). For frozen states the rows held as equations are the contact rows
// in contact and the sticking tangential rows; a slipping row's multiplier is known:
//   Tresca:   l_t = sign g         a force, moved to the loads: F - sign g c_t^T
//   Coulomb:  l_t = sign mu l_n    its normal row pushes along D_r = c_n + sign mu c_t
// so the system is H x + D_E^T l_E = F', C_E x = t_E: symmetric (CG) without slipping Coulomb
// rows, nonsymmetric (GMRES) with them; the same augmented factor H_P either way, refactorized
// when the rows held change.
#include "solve/model.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

void Model::solve_sparse_friction(std::vector<LoadSolve> &loads, std::vector<double> &lambda, std::vector<double> &alpha) {
  ContactSystem &cs = *contact_;
  const SparseContactStructure &st = cs.structure;
  const int q = cs.rows.size(), m = int(cs.tangent_of.size()), nrows = st.rows(), t0 = cs.tangent_row_offset;
  const double start = now();
  Stopwatch watch(infos.t_contact);
  std::vector<double> load, target;
  sparse_loads(loads, load, target);
  std::vector<char> start_active(cs.last_active);
  if (int(start_active.size()) != q) start_active.assign(q, 1);  // (as the frictionless sparse path)
  // The floating bodies' rigid motion guessed and taken out (sparse_rigid_shift).
  std::vector<char> near(nrows, 1);
  std::copy(start_active.begin(), start_active.end(), near.begin());
  const std::vector<double> alpha_0 = sparse_rigid_shift(near, target);
  const FrictionProblem f = friction_problem();
  // The iteration's scales: the largest compliance of a row (the Jacobi estimate P is made from).
  FrictionScales scales;
  scales.compliance = 0;
  for (int r = 0; r < q; ++r) scales.compliance = std::max(scales.compliance, cs.solver.row_compliance(r));
  for (int j = 0; j < m; ++j) scales.compliance = std::max(scales.compliance, cs.solver.row_compliance(t0 + j));

  SparseContactResult linear;  // what the linear solves cost, summed
  std::vector<double> x, l(nrows, 0.0);
  auto solve_states = [&](const std::vector<char> &active, const std::vector<FrictionState> &state,
                          FrictionStatesSolution &out) {
    // 1. The rows held as equations, the coupled rows, the slipping Tresca rows' forces.
    std::vector<char> held(nrows, 0);
    for (int r = 0; r < q; ++r) held[r] = active[r];
    std::vector<SparseContactSolver::Coupling> coupling;
    std::vector<double> f_states(load);
    for (int j = 0; j < m; ++j) {
      const int row = t0 + j;
      if (f.sticks(j, active, state)) held[row] = 1;
      else if (f.live(j, active) && slipping(state[j])) {
        const double sign = slip_sign(state[j]);
        if (f.law[j] == MC_FRICTION_COULOMB) {
          if (f.bound[j] != 0) coupling.push_back({f.tangent_of[j], row, sign * f.bound[j]});  // (mu = 0: none)
        } else {
          for (int p = st.row_start[row]; p < st.row_start[row + 1]; ++p)
            f_states[st.column[p]] -= sign * f.bound[j] * st.value[p];
        }
      }
    }
    if (!rows_hold_modes(held)) return false;
    // 2. The system's exact solution.
    cs.solver.set_threads(threads_);
    cs.solver.solve_rows(f_states, target, held, coupling, x, l, linear);
    // 3. The multipliers and gaps in the iteration's rows (q normal, then m tangential).
    out.lambda.assign(size_t(q + m), 0.0), out.gap.assign(size_t(q + m), 0.0);
    double gap_size = 0;
    auto gap_of = [&](int row) {
      double terms = std::fabs(target[row]);
      for (int p = st.row_start[row]; p < st.row_start[row + 1]; ++p) terms += std::fabs(st.value[p] * x[st.column[p]]);
      gap_size = std::max(gap_size, terms);
      return target[row] - cs.solver.row_times(row, x);
    };
    for (int r = 0; r < q; ++r) out.lambda[r] = l[r], out.gap[r] = gap_of(r);
    for (int j = 0; j < m; ++j) {
      out.gap[q + j] = gap_of(t0 + j);
      if (f.sticks(j, active, state)) out.lambda[q + j] = l[t0 + j];
      else if (f.live(j, active) && slipping(state[j]))
        out.lambda[q + j] =
            slip_sign(state[j]) * f.bound[j] * (f.law[j] == MC_FRICTION_COULOMB ? l[f.tangent_of[j]] : 1.0);
    }
    out.alpha = sparse_rigid_amplitudes(x);
    for (size_t c = 0; c < alpha_0.size(); ++c) out.alpha[c] += alpha_0[c];
    out.gap_scale = gap_size;
    return true;
  };
  FrictionResult result;
  try {
    result = iterate_friction_states(f, solve_states, scales, options.tolerance, options.iteration_limit(cs.b_rows()), start_active,
                                     cs.friction_state, friction_log());
  } catch (const Error &error) {
    if (error.status() != MC_ERROR_SINGULAR) throw;
    fail_sparse_singular(error);
  }
  infos.factorizations += linear.factorizations;
  infos.t_factor += linear.t_factor;
  infos.t_solve += linear.t_solve;
  infos.factor_nnz += cs.solver.factor_nnz();
  progress(MC_LOG_PHASE, "sparse friction solve: %d factorizations, %d factor updates, %d Krylov steps (%d of the "
           "updates modified the factor in place)",
           linear.factorizations, linear.updates + linear.modifications, linear.cg_steps, linear.modifications);
  accept_friction(f, result, start, " (sparse)", lambda, alpha);
  sparse_displacements(x, alpha_0, loads, alpha);
}

}  // namespace mc
