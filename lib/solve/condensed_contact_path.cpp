// The condensed interface solver (MC_INTERFACE_CONDENSED; design note "Solving the QP fast"):
// each body factorized alone with its contact unknowns last, the problem condensed onto the
// q contact rows through the trailing blocks of the factors,
//     S = B K^+ B^T = sum_b W_b^T W_b,  W_b = L_GG^-1 (P B_b^T)_G,
// and the dual QP (dual_qp.hpp) solved on it. S is stored by blocks of rows (block_sparse_operator.hpp):
// s_b couples only the rows touching body b, so a block of S between two pairs that share no
// body is never formed, and the active-set systems are factorized sparse when there is more
// than one block (a chain of N bodies: block tridiagonal, cost linear in N). Cheap while each
// body's contact rows are few beside the body (a re-solve then costs two triangular solves per
// body); with two bodies S is one dense block, O(q^3) time and O(q^2) memory, and when q is
// large the sparse path (sparse_contact_path.cpp) takes over.
#include "solve/model.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>
#include <string>

namespace mc {

// One body's share of the interface operator, s_b = B_G L_GG^-T L_GG^-1 B_G^T (upper triangle,
// q_b x q_b over the q_b rows that touch the body, ContactSystem::body_rows): a triangular solve
// with the trailing block of the factor and a rank-k update, all dense BLAS 3. W_b is kept for
// the loads and the recovery. (With two bodies every row touches both: q_b = q.)
void Model::interface_block(int b, std::vector<double> &s_b, BodyWork &work) {
  Stopwatch watch(work.infos.t_contact);
  ContactSystem &cs = *contact_;
  BodySystem &sys = *system_[b];
  const std::vector<int> &columns = cs.body_rows[b];
  const int qb = int(columns.size()), ng = int(sys.interface.size());
  if (ng == 0 || qb == 0) return;
  std::vector<int> order;
  std::vector<double> l = sys.cholesky.interface_factor(order);
  std::vector<int> factor_position(sys.stiffness.n, -1);
  for (int k = 0; k < ng; ++k) factor_position[sys.interface[order[k]]] = k;
  std::vector<double> w(size_t(ng) * qb, 0.0);
  for (int c = 0; c < qb; ++c) {
    const int r = columns[c];
    for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p) {
      int k = factor_position[cs.b_dof[b][p]];
      if (k >= 0) w[size_t(c) * ng + k] += cs.b_value[b][p];
    }
  }
  double one = 1.0, zero = 0.0;
  dtrsm_("L", "L", "N", "N", &ng, &qb, &one, l.data(), &ng, w.data(), &ng);
  s_b.assign(size_t(qb) * qb, 0.0);
  dsyrk_("U", "T", &qb, &ng, &one, w.data(), &ng, &zero, s_b.data(), &qb);
  cs.w[b] = std::move(w), cs.w_rows[b] = ng;
}

// y += W_b^T x_G for body b (x_G: the trailing interface part of a forward solve), on the rows
// touching b: B_b K_b^+ f in the condensed problem's terms.
static void add_interface_product(const ContactSystem &cs, int b, const double *x_interface, std::vector<double> &y) {
  const std::vector<int> &columns = cs.body_rows[b];
  const int ng = cs.w_rows[b], qb = int(columns.size());
  if (ng == 0 || qb == 0) return;
  int one = 1;
  double plus = 1.0, zero = 0.0;
  if (qb == int(y.size())) {  // every row touches b (two bodies): straight into y, as it always was
    dgemv_("T", &ng, &qb, &plus, cs.w[b].data(), &ng, x_interface, &one, &plus, y.data(), &one);
    return;
  }
  std::vector<double> yb(qb, 0.0);
  dgemv_("T", &ng, &qb, &plus, cs.w[b].data(), &ng, x_interface, &one, &zero, yb.data(), &one);
  for (int c = 0; c < qb; ++c) y[columns[c]] += yb[c];
}

// Each body's factorization, its share of S = sum_b s_b and, through `then`, its load solve,
// in one phase per body; then S. The sum is formed the same way whatever the thread count, so
// that the results do not depend on it. Bodies not yet analysed for this path (the sparse path
// was forced, or chosen and then fell back) are analysed first.
void Model::build_condensed(const std::function<void(int, BodyWork &)> &then) {
  if (contact_) {
    complete_b(nullptr);  // (a partial B: the sparse path's, handing over when its iteration cycled)
    contact_->sparse = false;
    contact_->w.assign(body.size(), {});
    contact_->w_rows.assign(body.size(), 0);
  }
  std::vector<std::vector<double>> s_b(body.size());
  std::vector<double> t_operator(body.size(), 0.0);
  for_each_body([&](int b, BodyWork &work) {
    if (system_[b] && !system_[b]->reduced_held)
      reduce_stiffness(b, work);  // (the sparse path frees it: its blocks read the stiffness itself)
    if (system_[b] && !system_[b]->cholesky.analyzed()) analyze_body(b, work, true);
    factorize_body(b, work);
    if (contact_ && system_[b]) {
      const double start = now();
      interface_block(b, s_b[b], work);
      t_operator[b] = now() - start;
    }
    then(b, work);
  });
  if (contact_) {
    Stopwatch watch(infos.t_contact);
    const double start = now();
    ContactSystem &cs = *contact_;
    const int q = cs.b_rows();  // with friction the tangential rows too
    cs.s = BlockSparseOperator(q, cs.body_rows);
    double t_blocks = 0;
    for (int b = 0; b < n_bodies(); ++b) {
      t_blocks += t_operator[b];
      if (!s_b[b].empty()) cs.s.add_share(cs.body_rows[b], s_b[b]);
      std::vector<double>().swap(s_b[b]);
    }
    cs.s.symmetrize();
    cs.last_active.clear();
    progress(MC_LOG_PHASE, "interface operator: S = B K^+ B^T of order %d, %d block%s of rows, %zu entries stored, %.3g s",
             q, cs.s.blocks(), cs.s.blocks() == 1 ? "" : "s", cs.s.stored_entries(), t_blocks + now() - start);
  }
}

Model::CondensedOperatorCost Model::condensed_operator_cost() const {
  const ContactSystem &cs = *contact_;
  const BlockSparseOperator pattern(cs.b_rows(), cs.body_rows);
  return {8 * double(pattern.stored_entries()), pattern.elimination_flops(), pattern.blocks()};
}

// The sparse path's active-set iteration cycled (SparseContactResult::cycled): the condensed
// path, whose QP solver then falls back to a primal active-set method that cannot cycle
// (dual_qp.cpp), if it fits in memory (choose_interface_solver refuses it otherwise, with
// MC_ERROR_MEMORY). The structure stays condensed until it is rebuilt.
void Model::fall_back_to_condensed(std::vector<LoadSolve> &loads) {
  const double start = now();
  complete_b(nullptr);  // (a partial B: the condensed path reads B whole, its interface too)
  check_condensed_fits();
  contact_->last_active.clear();
  contact_->solver.release();
  infos.dofs = 0, infos.factor_nnz = 0;  // counted again by the condensed path's load solves
  // The structure is neither path's until the condensed one is built: a failure on the way (a
  // host body whose factorization fails in the condensed path's ordering) must make the next
  // solve rebuild, not find the sparse path released and no interface operator (a fuzz finding,
  // b97bf1d6: the next solve read S out of an empty array).
  built_version_ = 0;
  build_condensed([&](int b, BodyWork &work) { solve_loads(b, work, loads[b]); });
  built_version_ = structure_version_;
  progress(MC_LOG_PHASE,
           "interface solver: condensed (the sparse path's active-set iteration cycled; the condensed QP has a "
           "fallback for that), factorized in %.3g s",
           now() - start);
}

// The condensed problem of the current loads (d, G, e; S from the structure), its QP, and the
// errors it can report. lambda and alpha: the contact forces and the floating bodies' rigid
// motion; qp keeps S and G for the refinement.
void Model::solve_condensed(std::vector<LoadSolve> &loads, DualQp &qp, std::vector<double> &lambda, std::vector<double> &alpha) {
  ContactSystem &cs = *contact_;
  const int q = cs.b_rows(), q_normal = cs.rows.size();
  qp.q = q;
  {
    Stopwatch watch(infos.t_contact);
    qp.s = cs.s;
    // d = B K^+ f_eff - g0 (with the prescribed values' share of the gap): B K^+ f_eff is
    // sum W_b^T y_G. A tangential row's g0 is where its slip starts, B_t u0 (friction.cpp).
    std::vector<double> bv(q, 0.0);
    for (int b = 0; b < n_bodies(); ++b)
      if (system_[b] && cs.w_rows[b] > 0)
        add_interface_product(cs, b, loads[b].y.data() + system_[b]->cholesky.interface_start(), bv);
    qp.d.assign(q, 0.0);
    for (int r = 0; r < q_normal; ++r) {
      double g = row_initial_gap(r);
      for (int b = 0; b < n_bodies(); ++b)
        for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p) {
          int dof = cs.b_dof[b][p];
          if (fixed_[b][dof]) g -= cs.b_value[b][p] * fixed_value_[b][dof];
        }
      qp.d[r] = bv[r] - g;
    }
    for (int r = q_normal; r < q; ++r) qp.d[r] = bv[r] - tangential_reference(r);
    qp.g = rigid_mode_rows();
    qp.e = rigid_mode_loads(loads);
    qp.k = int(qp.e.size());
  }
  if (q > q_normal) return solve_condensed_friction(qp, lambda, alpha);
  DualQpResult result;
  const double t_active_set = now();
  const DualQpObserver observe = iteration_log(q);
  {
    Stopwatch watch(infos.t_contact);
    result = solve_dual_qp(qp, options.tolerance, options.iteration_limit(q), cs.last_active, observe);
  }
  static const char *const outcome[] = {"solved", "loads not balanced", "floating body not held", "not converged"};
  progress(MC_LOG_PHASE, "active-set solve: %s, %d iterations, residual %.3g, %.3g s", outcome[int(result.outcome)],
           result.iterations, result.violation, now() - t_active_set);
  infos.iterations = result.iterations;
  if (result.outcome == DualQpOutcome::loads_not_balanced) {
    const std::string modes = free_modes_description();
    fail(MC_ERROR_SINGULAR,
         "the loads cannot be balanced by contact forces (which only push): with free rigid motion (%s) "
         "the best nonnegative contact forces leave %.3g of the load unbalanced; add supports or change the loads",
         modes.c_str(), result.imbalance);
  }
  if (result.outcome == DualQpOutcome::modes_not_held) {
    const std::string unheld = unheld_modes_description(), modes = unheld.empty() ? free_modes_description() : unheld;
    fail(MC_ERROR_SINGULAR,
         "contact cannot hold the free rigid motion (%s): the contact normals do not restrain it; add supports",
         modes.c_str());
  }
  if (result.outcome == DualQpOutcome::not_converged)
    fail(MC_ERROR_NOT_CONVERGED,
         "the active-set iteration stopped after %d iterations (limit %d) with a relative complementarity "
         "violation of %.3g (tolerance %.3g)",
         result.iterations, options.iteration_limit(q), result.violation, options.tolerance);
  lambda = result.lambda;
  alpha = result.alpha;
  infos.complementarity = result.violation;
  cs.last_active.assign(q, 0);
  for (int r = 0; r < q; ++r) cs.last_active[r] = lambda[r] > 0, infos.active += lambda[r] > 0;
  infos.contact_rows = q;
}

// Iterative refinement of the solution on the active set the QP found (docs/benchmarks.md,
// "Long contact interfaces"). The condensed problem's right-hand side d = B K^+ f - g can be
// far larger than the gaps and displacements it yields (a slender body factorized alone bends
// like a free beam: |d|/|u| reached 4*10^7 on the long strips), and the recovered u then
// carries round-off of d's size. The residuals of the full problem, computed in the original
// unknowns, are free of that cancellation:
//   r_f = f - K u - B^T lambda (free unknowns),  gap = g - B u (active rows),
// and the correction (du, dl, da) with K du + B_A^T dl = r_f, B_A du = gap, i.e.
//   S_AA dl - G_A da = (B K^+ r_f)_A - gap_A,  G_A^T dl = R^T r_f,  du = K^+ (r_f - B^T dl) + R da,
// costs one forward and one backward solve per body and a dense solve of the active block.
// A step is kept only if it lowers MC_INFO_GAP_RESIDUAL by half and keeps lambda >= 0; at most
// kMaxRefinementSteps. Returns whether any step was kept (loads[b].v, lambda, alpha, body[b].u
// and infos.gap_residual then hold the refined solution). `qp` keeps S and G; its d and e are
// overwritten with the residuals.
bool Model::refine_solution(DualQp &qp, std::vector<LoadSolve> &loads, std::vector<double> &lambda, std::vector<double> &alpha) {
  const double start = now(), first = infos.gap_residual;
  const ContactSystem &cs = *contact_;
  const int q = cs.rows.size();
  std::vector<char> active(q);
  for (int r = 0; r < q; ++r) active[r] = lambda[r] > 0;
  int steps = 0;
  for (int step = 0; step < kMaxRefinementSteps; ++step) {
    // 1. The equilibrium residual of each body and its forward solve y_r = L^-1 P r_f.
    std::vector<std::vector<double>> residual(body.size()), residual_y(body.size());
    for_each_body([&](int b, BodyWork &work) {
      if (!system_[b]) return;
      const BodySystem &sys = *system_[b];
      const int ndof = sys.stiffness.n;
      std::vector<double> elastic(loads[b].v), ku(ndof);
      for (int i = 0; i < ndof; ++i)
        if (fixed_[b][i]) elastic[i] = fixed_value_[b][i];
      sys.stiffness.multiply(elastic.data(), ku.data());  // K R = 0: the rigid motion drops out
      std::vector<double> &rf = residual[b];
      rf.assign(ndof, 0.0);
      for (int i = 0; i < ndof; ++i)
        if (!fixed_[b][i]) rf[i] = loads[b].f[i] - ku[i];
      for (int r = 0; r < q; ++r)
        for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p)
          if (!fixed_[b][cs.b_dof[b][p]]) rf[cs.b_dof[b][p]] -= cs.b_value[b][p] * lambda[r];
      std::vector<double> x(sys.solve_dofs.size());
      for (size_t k = 0; k < x.size(); ++k) x[k] = rf[sys.solve_dofs[k]];
      residual_y[b].resize(x.size());
      Stopwatch watch(work.infos.t_solve);
      sys.cholesky.forward(x.data(), residual_y[b].data());
    });
    // 2. The correction on the active set: d = B K^+ r_f - gap (B K^+ r_f = sum W_b^T y_r,G),
    //    e = R^T r_f, in body order.
    qp.d.assign(q, 0.0);
    for (int b = 0; b < n_bodies(); ++b)
      if (system_[b] && cs.w_rows[b] > 0)
        add_interface_product(cs, b, residual_y[b].data() + system_[b]->cholesky.interface_start(), qp.d);
    for (int r = 0; r < q; ++r) qp.d[r] -= row_gap(r);
    qp.e.assign(qp.k, 0.0);
    for (int b = 0; b < n_bodies(); ++b) {
      if (!system_[b]) continue;
      const RigidModes &rm = system_[b]->rigid;
      const int ndof = system_[b]->stiffness.n, offset = mode_offset(b);
      for (int c = 0; c < rm.count; ++c)
        for (int i = 0; i < ndof; ++i) qp.e[offset + c] += rm.modes[size_t(c) * ndof + i] * residual[b][i];
    }
    std::vector<double> dl, da;
    if (!solve_correction(qp, active, dl, da)) break;
    std::vector<double> new_lambda(lambda), new_alpha(alpha);
    bool feasible = true;
    for (int r = 0; r < q; ++r) new_lambda[r] += dl[r], feasible = feasible && new_lambda[r] >= 0;
    for (int c = 0; c < qp.k; ++c) new_alpha[c] += da[c];
    if (!feasible) break;
    // 3. du = K^+ (r_f - B^T dl) + R da = P^T L^-T (y_r - [0; W dl]) + R da, per body.
    std::vector<std::vector<double>> kept_v, kept_u;
    for (int b = 0; b < n_bodies(); ++b) kept_v.push_back(loads[b].v), kept_u.push_back(body[b].u);
    for_each_body([&](int b, BodyWork &work) {
      if (!system_[b]) return;
      const BodySystem &sys = *system_[b];
      const int ndof = sys.stiffness.n, ng = cs.w_rows[b];
      const std::vector<int> &columns = cs.body_rows[b];
      const int qb = int(columns.size());
      std::vector<double> &z = residual_y[b], dx(sys.solve_dofs.size());
      if (ng > 0 && qb > 0) {
        int one = 1;
        double minus = -1.0, plus = 1.0;
        std::vector<double> dl_b(qb);
        for (int c = 0; c < qb; ++c) dl_b[c] = dl[columns[c]];
        dgemv_("N", &ng, &qb, &minus, cs.w[b].data(), &ng, dl_b.data(), &one, &plus, z.data() + sys.cholesky.interface_start(),
               &one);
      }
      {
        Stopwatch watch(work.infos.t_solve);
        sys.cholesky.backward(z.data(), dx.data());
      }
      for (size_t k = 0; k < dx.size(); ++k) loads[b].v[sys.solve_dofs[k]] += dx[k];
      std::vector<double> &u = body[b].u;
      for (int i = 0; i < ndof; ++i) u[i] = fixed_[b][i] ? fixed_value_[b][i] : loads[b].v[i];
      add_rigid_motion(b, new_alpha, u);
    });
    const double refined = recovered_gap_residual(new_lambda);
    if (!(refined <= 0.5 * infos.gap_residual)) {  // no real gain: the step is undone
      for (int b = 0; b < n_bodies(); ++b) loads[b].v = kept_v[b], body[b].u = kept_u[b];
      break;
    }
    lambda = new_lambda, alpha = new_alpha, infos.gap_residual = refined, ++steps;
  }
  progress(MC_LOG_PHASE, "refinement: gap residual of the displacements %.3g -> %.3g in %d step%s, %.3g s", first,
           infos.gap_residual, steps, steps == 1 ? "" : "s", now() - start);
  return steps > 0;
}
}  // namespace mc
