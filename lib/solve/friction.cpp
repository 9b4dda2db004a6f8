// Friction on the condensed path (docs/theory.md, "Friction"; design note friction.md): the
// tangential rows' reference, the frictional interface problem and its errors, the results per
// contact position, and the history a frictional solve steps from.
#include "solve/model.hpp"
#include "bodies/cell_shapes.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>
#include <string>

namespace mc {

bool Model::has_friction() const {
  for (const ContactPair &p : pairs)
    if (p.complete() && p.friction_law != MC_FRICTION_NONE) return true;
  return false;
}

// The friction of a group's pairs, which must agree (pairs joined into one surface).
const ContactPair &Model::group_friction(const ContactGroup &group) const {
  const ContactPair &lead = pairs[group.pairs.front()];
  for (int p : group.pairs)
    if (pairs[p].friction_law != lead.friction_law || pairs[p].friction_value != lead.friction_value)
      fail(MC_ERROR_CONTACT,
           "pairs %d and %d join one surface (non-mortar body %d, mortar body %d) but have different friction "
           "(mc_set_friction): give them the same law and value",
           group.pairs.front() + 1, p + 1, group.nonmortar + 1, group.mortar + 1);
  return lead;
}

// Each tangential row's law and bound from its group's pairs, at every solve (mc_set_friction
// changes values without a rebuild).
void Model::refresh_friction() {
  ContactSystem &cs = *contact_;
  for (size_t j = 0; j < cs.tangent_of.size(); ++j) {
    const int r = cs.tangent_of[j];
    const ContactPair &lead = group_friction(cs.groups[cs.row_group[r]]);
    const double bound = lead.friction_law == MC_FRICTION_COULOMB ? lead.friction_value
                                                                   : lead.friction_value * cs.rows.measure[r];
    // A row whose law or bound changed starts sticking (its last slip state was for another law).
    if ((cs.friction_law[j] != lead.friction_law || cs.friction_bound[j] != bound) && j < cs.friction_state.size())
      cs.friction_state[j] = FrictionState::stick;
    cs.friction_law[j] = lead.friction_law, cs.friction_bound[j] = bound;
  }
}

// Where tangential row q + j's slip starts: B_t u0 (the last converged state) less its
// prescribed part, the tangential rows' counterpart of a normal row's g0 (solve_condensed).
double Model::tangential_reference(int row) const {
  const ContactSystem &cs = *contact_;
  double g = 0;
  for (int b = 0; b < n_bodies(); ++b)
    for (int p = cs.b_start[b][row]; p < cs.b_start[b][row + 1]; ++p) {
      const int dof = cs.b_dof[b][p];
      if (history_.valid) g += cs.b_value[b][p] * history_.u[b][dof];
      if (fixed_[b][dof]) g -= cs.b_value[b][p] * fixed_value_[b][dof];
    }
  return g;
}

namespace {

// "body 2 node 17" for normal row r (its own position, or the first of its body-1 positions).
std::string row_place(const Model &model, const ContactSystem &cs, int r) {
  const int pos = cs.rows.own_position[r] >= 0 ? cs.rows.own_position[r] : cs.rows.position1[cs.rows.start1[r]];
  const ContactGroup &group = cs.group_of_position(pos);
  return "body " + std::to_string(group.nonmortar + 1) + " node " +
         std::to_string(model.position_node(size_t(pos)) + model.index_base);
}

const char *state_name(FrictionState s) {
  switch (s) {
    case FrictionState::open: return "open";
    case FrictionState::stick: return "stick";
    default: return "slip";
  }
}

}  // namespace

FrictionProblem Model::friction_problem() const {
  const ContactSystem &cs = *contact_;
  FrictionProblem f;
  f.normal_rows = cs.rows.size(), f.tangent_of = cs.tangent_of, f.law = cs.friction_law, f.bound = cs.friction_bound;
  f.ct = options.friction_ct;
  // A tangential row whose every term is on a prescribed freedom (or round-off beside its
  // largest) has its slip prescribed (the rigid modes vanish at prescribed components too).
  f.prescribed.assign(cs.tangent_of.size(), 0);
  const int q = cs.rows.size();
  for (size_t j = 0; j < cs.tangent_of.size(); ++j) {
    const int row = q + int(j);
    double largest = 0, free_part = 0;
    for (int b = 0; b < n_bodies(); ++b)
      for (int p = cs.b_start[b][row]; p < cs.b_start[b][row + 1]; ++p) {
        largest = std::max(largest, std::fabs(cs.b_value[b][p]));
        if (!fixed_[b][cs.b_dof[b][p]]) free_part = std::max(free_part, std::fabs(cs.b_value[b][p]));
      }
    f.prescribed[j] = !(free_part > 1e-14 * largest);
  }
  return f;
}

FrictionObserver Model::friction_log() {
  if (!progress.enabled()) return {};
  return [this](const FrictionIteration &it) {
    progress(MC_LOG_ITERATION, "friction iteration %d: %d in contact, %d stick, %d slip, %d states changed", it.iteration,
             it.active, it.stick, it.slip, it.changed);
  };
}

// The frictional interface problem (friction_qp.hpp) on the condensed operator.
void Model::solve_condensed_friction(DualQp &qp, std::vector<double> &lambda, std::vector<double> &alpha) {
  ContactSystem &cs = *contact_;
  const FrictionProblem f = friction_problem();
  FrictionResult result;
  const double start = now();
  {
    Stopwatch watch(infos.t_contact);
    result = solve_friction_qp(qp, f, options.tolerance, options.iteration_limit(cs.b_rows()), cs.last_active, cs.friction_state,
                               friction_log());
  }
  accept_friction(f, result, start, "", lambda, alpha);
}

void Model::accept_friction(const FrictionProblem &f, const FrictionResult &result, double start, const char *path,
                            std::vector<double> &lambda, std::vector<double> &alpha) {
  ContactSystem &cs = *contact_;
  const int q = cs.rows.size();
  infos.iterations += result.iterations;
  static const char *const outcome[] = {"solved", "floating body not held", "not converged", "cycled"};
  progress(MC_LOG_PHASE, "friction solve%s: %s, %d iterations, %ld stick, %ld slip, residuals %.3g and %.3g, %.3g s",
           path, outcome[int(result.outcome)], result.iterations, result.stick, result.slip, result.violation,
           result.friction_violation, now() - start);
  if (result.outcome == FrictionOutcome::modes_not_held) {
    // The rows that hold in the states reached: in contact, and sticking.
    std::vector<char> holding(size_t(cs.b_rows()), 0);
    for (int r = 0; r < q; ++r) holding[r] = result.active[r];
    for (size_t j = 0; j < cs.tangent_of.size(); ++j)
      holding[q + j] = f.live(int(j), result.active) && result.state[j] == FrictionState::stick;
    std::string text = unheld_modes_description(holding);
    if (text.empty()) text = free_modes_description();
    fail(MC_ERROR_SINGULAR,
         "no support and no sticking contact holds %s: the contact there slips or is open; add a support, or loads "
         "that friction can carry",
         text.c_str());
  }
  if (result.outcome != FrictionOutcome::solved) {
    std::string rows;
    int listed = 0;
    for (int row : result.changing_rows) {
      if (listed++ == 4) { rows += "; ..."; break; }
      const bool tangential = row >= q;
      const int r = tangential ? cs.tangent_of[row - q] : row;
      rows += (rows.empty() ? "" : "; ") + row_place(*this, cs, r) +
              (tangential ? std::string(": tangential row, ") + state_name(result.state[row - q])
                          : std::string(result.active[r] ? ": normal row, in contact" : ": normal row, open"));
    }
    if (result.outcome == FrictionOutcome::cycled)
      fail(MC_ERROR_NOT_CONVERGED,
           "the stick/slip iteration cycled after %d iterations: its last step would have changed %zu rows (%s); "
           "Coulomb friction need not have a unique discrete answer for large mu: try smaller load increments "
           "(MC_OPTION_LOAD_STEPS) or a finer mesh there",
           result.iterations, result.changing_rows.size(), rows.c_str());
    fail(MC_ERROR_NOT_CONVERGED,
         "the stick/slip iteration stopped after %d iterations (limit %d) with residuals %.3g (contact) and %.3g "
         "(friction), tolerance %.3g; rows still changing: %s",
         result.iterations, options.iteration_limit(cs.b_rows()), result.violation, result.friction_violation, options.tolerance,
         rows.empty() ? "none" : rows.c_str());
  }
  lambda = result.lambda, alpha = result.alpha;
  cs.last_active = result.active;
  cs.friction_state = result.state;
  infos.complementarity = std::max(infos.complementarity, result.violation);
  infos.friction_complementarity = std::max(infos.friction_complementarity, result.friction_violation);
  infos.stick = result.stick, infos.slip = result.slip;
  infos.active = 0;
  for (int r = 0; r < q; ++r) infos.active += lambda[r] > 0;
  infos.contact_rows = q;
}

// ---- the history ----------------------------------------------------------------------------

// mc_reset_history: the unloaded state, and (with friction) no warm start from the last states.
void Model::reset_history() {
  history_ = History();
  if (contact_ && !contact_->tangent_of.empty()) contact_->friction_state.clear(), contact_->last_active.clear();
}

// The state a frictional solve steps from: the last converged one, or the unloaded state (zero
// displacements, loads and prescribed values) when there is none or the model's unknowns or
// contact positions changed since.
void Model::prepare_history() {
  size_t positions = 0;
  for (const ContactGroup &group : contact_->groups) positions += size_t(group.positions());
  bool fits = history_.valid && int(history_.u.size()) == n_bodies() && history_.slip_total.size() == positions;
  for (int b = 0; fits && b < n_bodies(); ++b) fits = int(history_.u[b].size()) == dof_count(b);
  if (fits) return;
  history_ = History();
  history_.valid = true;
  for (int b = 0; b < n_bodies(); ++b) {
    const size_t n = size_t(dof_count(b));
    history_.u.emplace_back(n, 0.0), history_.f.emplace_back(n, 0.0), history_.prescribed.emplace_back(n, 0.0);
  }
  history_.slip_total.assign(positions, 0.0);
}

// The loads of load step `step` of `steps`: f0 + t (f - f0) and the prescribed values
// p0 + t (p - p0), t = step / steps, from the history's (f0, p0) and the solve's (target).
// Everything a LoadSolve holds is linear in (f, p): y0 (of f0, p0) is one forward solve per
// body, done once (start).
void Model::step_loads(int step, int steps, const std::vector<LoadSolve> &target,
                       const std::vector<std::vector<double>> &target_prescribed, std::vector<LoadSolve> &start,
                       std::vector<LoadSolve> &loads) {
  const double t = double(step) / steps;
  if (step == steps) {
    loads = target, fixed_value_ = target_prescribed;
    return;
  }
  if (start.empty()) {
    start.resize(body.size());
    for_each_body([&](int b, BodyWork &work) {
      if (!system_[b]) return;
      BodySystem &sys = *system_[b];
      const int n = sys.stiffness.n;
      LoadSolve &s = start[b];
      s.f = history_.f[b];
      std::vector<double> up(n, 0.0), kup(n, 0.0);
      for (int i = 0; i < n; ++i)
        if (fixed_[b][i]) up[i] = history_.prescribed[b][i];
      sys.stiffness.multiply(up.data(), kup.data());
      s.lifted.assign(n, 0.0);
      for (int i = 0; i < n; ++i) s.lifted[i] = fixed_[b][i] ? 0 : s.f[i] - kup[i];
      std::vector<double> x(sys.solve_dofs.size());
      for (size_t k = 0; k < x.size(); ++k) x[k] = s.lifted[sys.solve_dofs[k]];
      s.y.resize(x.size());
      Stopwatch watch(work.infos.t_solve);
      sys.cholesky.forward(x.data(), s.y.data());
    });
  }
  auto blend = [t](const std::vector<double> &a, const std::vector<double> &b) {
    std::vector<double> c(b.size());
    for (size_t i = 0; i < b.size(); ++i) c[i] = a[i] + t * (b[i] - a[i]);
    return c;
  };
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    loads[b] = target[b];
    loads[b].f = blend(start[b].f, target[b].f);
    loads[b].lifted = blend(start[b].lifted, target[b].lifted);
    loads[b].y = blend(start[b].y, target[b].y);
    for (size_t i = 0; i < fixed_value_[b].size(); ++i)
      fixed_value_[b][i] = fixed_[b][i] ? history_.prescribed[b][i] + t * (target_prescribed[b][i] - history_.prescribed[b][i])
                                        : target_prescribed[b][i];
  }
}

// After a converged step: its slip added to each position's accumulated slip, and the step's
// displacements, loads and prescribed values become the state the next step starts from.
void Model::record_step(const std::vector<LoadSolve> &loads) {
  const std::vector<double> slip = pointwise_slips(history_.u);
  for (size_t pos = 0; pos < slip.size(); ++pos) history_.slip_total[pos] += std::fabs(slip[pos]);
  for (int b = 0; b < n_bodies(); ++b) {
    history_.u[b] = body[b].u;
    if (system_[b]) history_.f[b] = loads[b].f;
    history_.prescribed[b] = fixed_value_[b];
  }
}

// ---- results per contact position --------------------------------------------------------------

// The slip since `from` (per body, per DOF; empty: zero) at every contact position along
// t_j = (-n_y, n_x): (u1 - u1_from)(x_j) - (u2 - u2_from)(y_j), y_j its projection on the mortar
// body (0 where it has none), or its tangential row's where it has one (below).
std::vector<double> Model::pointwise_slips(const std::vector<std::vector<double>> &from) const {
  size_t positions = 0;
  for (const ContactGroup &group : contact_->groups) positions += size_t(group.positions());
  std::vector<double> slip(positions, 0.0);
  for (const ContactGroup &group : contact_->groups) {
    const ContactGeometry &g = group.geometry;
    auto du = [&](int b, int node, int component) {
      const int dof = dof_of(b, node, component);
      if (dof < 0) return 0.0;
      return body[b].u[dof] - (from.empty() ? 0.0 : from[b][dof]);
    };
    for (int local = 0; local < group.positions(); ++local) {
      if (g.projection[local].segment < 0) continue;
      const CurveSegment &c = g.mortar.segments()[g.projection[local].segment];
      double shape[3], ds[3];
      line_shapes(c.quadratic() ? 3 : 2, g.projection[local].eta, shape, ds);
      const int node2[3] = {c.a, c.b, c.mid}, node1 = g.nodes[local];
      double ux = du(group.nonmortar, node1, 0), uy = du(group.nonmortar, node1, 1);
      for (int a = 0; a < (c.quadratic() ? 3 : 2); ++a)
        ux -= shape[a] * du(group.mortar, node2[a], 0), uy -= shape[a] * du(group.mortar, node2[a], 1);
      const Point n = g.normals[local];
      slip[size_t(group.first_position + local)] = -n.y * ux + n.x * uy;
    }
  }
  // Where a position has a row of its own with a tangential row, the slip the friction law
  // holds to: that row's, B_t (u - from) over its non-mortar weight (for the paper's rows
  // u1(x_j) - pi_h(u2)(x_j) along t, not u1 - u2 at the projection).
  const ContactSystem &cs = *contact_;
  const int q = cs.rows.size();
  for (size_t j = 0; j < cs.tangent_of.size(); ++j) {
    const int r = cs.tangent_of[j], pos = cs.rows.own_position[r], row = q + int(j);
    if (pos < 0) continue;
    double weight = 0, value = 0;
    for (int p = cs.rows.start1[r]; p < cs.rows.start1[r + 1]; ++p) weight += cs.rows.weight1[p];
    for (int b = 0; b < n_bodies(); ++b)
      for (int p = cs.b_start[b][row]; p < cs.b_start[b][row + 1]; ++p) {
        const int dof = cs.b_dof[b][p];
        value += cs.b_value[b][p] * (body[b].u[dof] - (from.empty() ? 0.0 : from[b][dof]));
      }
    if (weight != 0) slip[size_t(pos)] = value / weight;
  }
  return slip;
}

// MC_CONTACT_SHEAR, _SLIP, _SLIP_TOTAL and _STATE at every position (after contact_results).
// solve_start: the displacements the solve started from (empty: zero).
void Model::friction_results(const std::vector<double> &lambda, const std::vector<std::vector<double>> &solve_start) {
  const ContactSystem &cs = *contact_;
  const int q = cs.rows.size();
  const size_t n = contact_force.size();
  std::vector<int> tangent_index(q, -1);
  for (size_t j = 0; j < cs.tangent_of.size(); ++j) tangent_index[cs.tangent_of[j]] = int(j);
  auto lambda_t = [&](int r) { return tangent_index[r] >= 0 ? lambda[q + tangent_index[r]] : 0.0; };
  std::vector<double> shear_force(n, 0.0);
  contact_shear.assign(n, 0.0);
  contact_state.assign(n, MC_STATE_OPEN);
  std::vector<double> state_weight(n, 0.0);
  for (int r = 0; r < q; ++r)
    for (int p = cs.rows.start1[r]; p < cs.rows.start1[r + 1]; ++p) {
      const int pos = cs.rows.position1[p];
      shear_force[pos] += cs.rows.weight1[p] * lambda_t(r);
      // A position's state is that of the row that weighs most on it (its own row, weight 1).
      if (std::fabs(cs.rows.weight1[p]) <= state_weight[pos]) continue;
      state_weight[pos] = std::fabs(cs.rows.weight1[p]);
      // Open: no normal force, unless the row is a Tresca row, whose bound holds out of contact
      // too (friction_qp.hpp, FrictionProblem::live): it sticks or slips there as well.
      const int j = tangent_index[r];
      const bool tresca = j >= 0 && cs.friction_law[j] == MC_FRICTION_TRESCA;
      int state = MC_STATE_OPEN;
      if (lambda[r] > 0 || tresca)
        state = j >= 0 && cs.friction_state[j] == FrictionState::stick ? MC_STATE_STICK : MC_STATE_SLIP;
      contact_state[pos] = state;
    }
  for (const ContactGroup &group : cs.groups) {
    const int first = group.first_position;
    if (!group.rows.pressure_of_position.empty()) {  // the weak rows' own traction field, as the pressure's
      for (int pos = 0; pos < group.positions(); ++pos)
        for (auto &[r, c] : group.rows.pressure_of_position[pos]) contact_shear[first + pos] -= c * lambda_t(group.first_row + r);
    } else {
      for (int pos = 0; pos < group.positions(); ++pos)
        if (group.geometry.tributary[pos] > 0) contact_shear[first + pos] = -shear_force[first + pos] / group.geometry.tributary[pos];
    }
  }
  contact_slip = pointwise_slips(solve_start);
  if (history_.valid && history_.slip_total.size() == n) {
    contact_slip_total = history_.slip_total;
  } else {
    contact_slip_total.resize(n);
    for (size_t pos = 0; pos < n; ++pos) contact_slip_total[pos] = std::fabs(contact_slip[pos]);
  }
}

}  // namespace mc
