// The error estimate of a solve (MC_INFO_ERROR_ESTIMATE, mc_get_error_indicator; computed on demand,
// results_on_demand.cpp):
// Zienkiewicz-Zhu recovery in the cells of both bodies, plus the contact terms on body 1's
// contact edges (docs/theory.md, "Error estimate").
//
//   eta_K^2 = int_K (sigma* - sigma_h)^T D^-1 (sigma* - sigma_h) w        (cell_recovery_error)
//           + sum over K's contact edges E of
//               h_E / c_K int_E (n . sigma_h n + p_h)^2 w                  (normal stress against pressure)
//             + int_E p_h max(g_h, 0) w                                    (complementarity)
// (g_h interpolated from the rows' gaps, which an exact active-set solve makes complementary: the
// term is round-off here, and would show what a penalty or an inexact solve leaves)
//
// sigma*: the patch-recovered nodal stresses (stress_recovery.hpp) interpolated by the cell's
// shape functions (plain nodal averaging, mc_get_nodal_stress, was measured first: it
// underestimated, effectivity 0.81 to 0.76 on the P1 shrink fit, falling with h);
// c_K: the law's first diagonal entry (an elastic modulus: the term is an energy); p_h, g_h: the
// contact pressure and gap at body 1's contact positions interpolated along the edge. The
// relative estimate divides by sqrt(u^T K u + eta^2).
#include "bodies/cell_shapes.hpp"
#include "solve/model.hpp"
#include "bodies/plane_vectors.hpp"
#include "bodies/stress_recovery.hpp"
#include <cmath>

namespace mc {

namespace {

// The contact terms of body 1's contact edge `seg` (a curve segment of the non-mortar surface),
// added to the indicator of the cell that owns the edge. stress: 4 per edge node (the ends, then
// the middle), the owning cell's own stress there.
double contact_edge_terms(const Model &model, const ContactGeometry &g, int first_position, int seg, const PlaneLaw &law,
                          const double *stress, const std::vector<char> &owns_row) {
  const CurveSegment &c = g.nonmortar.segments()[seg];
  std::array<int, 3> pos = g.segment_positions[seg];  // the stacked positions (Model::contact_pressure's)
  for (int &p : pos)
    if (p >= 0) p += first_position;
  const int nodes = c.quadratic() ? 3 : 2;
  double pressure[3] = {0, 0, 0}, gap[3] = {0, 0, 0};
  bool touched = false;
  for (int a = 0; a < nodes; ++a) {
    pressure[a] = model.contact_pressure[pos[a]];
    // the gap of the cone's own row: a quadratic edge's middle (and a run's end) has none, and its
    // pointwise gap is not what the discrete complementarity holds to (measured: with it, the
    // T6 shrink fit's estimate came out 1.5 to 3.8 times the true error)
    // (and a gap within round-off of closed is closed: the term is linear in it, so round-off
    // 1e-16 would show as 1e-8 in the estimate)
    const double own = owns_row[pos[a]] ? model.contact_gap[pos[a]] : 0.0;
    gap[a] = std::isfinite(own) && own > 1e-10 * c.length ? own : 0.0;
    touched = touched || pressure[a] > 0;
  }
  if (!touched) return 0;  // an open edge: no pressure, nothing to misfit
  // An edge Gamma_c covers only partly (a node of it sees no body 2: Gamma_c ends inside it) has
  // no pressure field of its own over the rest: its nodal pressures stop at 0 where the
  // mechanics does not (measured: the quarter-ring shrink fit, whose arcs end together, came out
  // 3.4 to 5.5 times the true error with it).
  for (int a = 0; a < nodes; ++a)
    if (!std::isfinite(model.contact_gap[pos[a]])) return 0;
  const LineMeasure measure = model.measure();
  const double modulus = law.d[0], length = c.length;
  double s[5], w[5], misfit = 0, complementarity = 0;
  gauss_on_unit_interval(5, s, w);
  for (int q = 0; q < 5; ++q) {
    double shape[3], ds[3];
    line_shapes(nodes, s[q], shape, ds);
    const Point x = g.nonmortar.point(seg, s[q]), n = g.nonmortar.surface_normal(seg, s[q]);
    const double weight = w[q] * g.nonmortar.speed(seg, s[q]) * measure.weight(x);
    double sigma[3] = {0, 0, 0}, p = 0, gp = 0;  // recovered xx, yy, xy along the edge
    for (int a = 0; a < nodes; ++a) {
      for (int k = 0; k < 3; ++k) sigma[k] += shape[a] * stress[4 * a + k];
      p += shape[a] * pressure[a], gp += shape[a] * gap[a];
    }
    const double normal_stress = n.x * n.x * sigma[0] + n.y * n.y * sigma[1] + 2 * n.x * n.y * sigma[2];
    misfit += weight * (normal_stress + p) * (normal_stress + p);
    complementarity += weight * std::max(p, 0.0) * gp;
  }
  return length / modulus * misfit + complementarity;
}

}  // namespace

void Model::estimate_error(double &estimate, std::vector<std::vector<double>> &indicators) const {
  estimate = 0;
  indicators.assign(body.size(), std::vector<double>());
  double eta2 = 0;
  std::vector<std::vector<double>> cell_eta2(body.size()), recovered(body.size());
  // Each body on its own thread when the solve runs two (MC_OPTION_THREADS, as the recovery's
  // phase does); their timings are not infos (the estimate's time is MC_INFO_TIME_RESULTS').
  Infos ignored;
  run_bodies(body_threads(), [&](int b, BodyWork &) {
    const Body &body_ = body[b];
    if (!body_.has_mesh || body_.host || !system_[b]) return;
    const Mesh &mesh = body_.mesh;
    const int npc = mesh.nodes_per_cell();
    const bool bbar = options.q1_integration == MC_Q1_BBAR && npc == 4;
    const std::vector<PlaneLaw> &laws = system_[b]->laws;
    std::vector<double> compliance(16 * laws.size());
    for (size_t l = 0; l < laws.size(); ++l) law_compliance(laws[l], &compliance[16 * l]);
    cell_eta2[b].assign(size_t(mesh.n_cells()), 0.0);
    const RecoveredStress rs = patch_recovered_stresses(mesh, laws, measure(), bbar, body_.u);
    recovered[b] = rs.nodal;
    if (!rs.weight.empty()) {
      // P1 and Q1: the samples are the quadrature points; sigma* there from the reference
      // shapes, the same for every cell (cell_recovery_error's integral, without evaluating the
      // cells' stresses a second time).
      double xi[kMaxCellPoints], eta[kMaxCellPoints], w[kMaxCellPoints], shape[kMaxCellPoints][kMaxCellNodes];
      const int points = quadrature_rule(npc, measure().axisymmetric, xi, eta, w);
      for (int g = 0; g < points; ++g) {
        double dxi[kMaxCellNodes], deta[kMaxCellNodes];
        reference_shapes(npc, xi[g], eta[g], shape[g], dxi, deta);
      }
      const int k = laws[0].n_strain;
      for (int c = 0; c < mesh.n_cells(); ++c) {
        const int *v = mesh.cell(c);
        const size_t l = laws.size() == 1 ? 0 : size_t(c);
        const double *cmp = &compliance[16 * l];
        double error = 0;
        for (int g = 0, s = rs.sample_start[c]; s < rs.sample_start[c + 1]; ++g, ++s) {
          double d[4];
          for (int r = 0; r < k; ++r) {
            double recovered_r = 0;
            for (int a = 0; a < npc; ++a) recovered_r += shape[g][a] * rs.nodal[4 * size_t(v[a]) + r];
            d[r] = recovered_r - rs.sigma[4 * size_t(s) + r];
          }
          double energy = 0;
          for (int r = 0; r < k; ++r)
            for (int q = 0; q < k; ++q) energy += d[r] * cmp[4 * r + q] * d[q];
          error += rs.weight[s] * energy;
        }
        cell_eta2[b][c] = error;
      }
      return;
    }
    Point p[kMaxCellNodes];
    double ue[2 * kMaxCellNodes], nodal[4 * kMaxCellNodes];
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int *v = mesh.cell(c);
      for (int a = 0; a < npc; ++a) {
        p[a] = mesh.node(v[a]);
        ue[2 * a] = body_.u[2 * size_t(v[a])], ue[2 * a + 1] = body_.u[2 * size_t(v[a]) + 1];
        for (int q = 0; q < 4; ++q) nodal[4 * a + q] = recovered[b][4 * size_t(v[a]) + q];
      }
      const size_t l = laws.size() == 1 ? 0 : size_t(c);
      cell_eta2[b][c] = cell_recovery_error(p, npc, laws[l], &compliance[16 * l], measure(), bbar, ue, nodal);
    }
  }, ignored);
  // The contact terms, on each group's non-mortar edges.
  std::vector<char> owns_row(contact_force.size(), 0);
  if (contact_)
    for (int position : contact_->rows.own_position)  // the positions whose gap is their row's
      if (position >= 0) owns_row[position] = 1;
  for (const ContactGroup &group : contact_ ? contact_->groups : std::vector<ContactGroup>{}) {
    const int nm = group.nonmortar;
    if (body[nm].host || cell_eta2[nm].empty()) continue;
    const ContactGeometry &g = group.geometry;
    const std::vector<PlaneLaw> &laws = system_[nm]->laws;
    for (size_t seg = 0; seg < g.nonmortar.segments().size(); ++seg) {
      const CurveSegment &c = g.nonmortar.segments()[seg];
      const BoundaryEdge *edge = body[nm].mesh.boundary_edge(c.a, c.b);
      if (!edge) continue;
      const PlaneLaw &law = laws.size() == 1 ? laws[0] : laws[edge->cell];
      // The cell's own stress at its nodes: the misfit is measured with the discrete stress, as
      // residual estimators do (with the recovered one, whose one-sided patches at a curved
      // coarse boundary extrapolate, the quarter-ring shrink fit's estimate came out 4 to 5.5
      // times the true error, and growing with refinement)
      const Mesh &mesh = body[nm].mesh;
      const int npc = mesh.nodes_per_cell(), *v = mesh.cell(edge->cell);
      Point p[kMaxCellNodes];
      double ue[2 * kMaxCellNodes], at_nodes[4 * kMaxCellNodes];
      for (int a = 0; a < npc; ++a)
        p[a] = mesh.node(v[a]), ue[2 * a] = body[nm].u[2 * size_t(v[a])], ue[2 * a + 1] = body[nm].u[2 * size_t(v[a]) + 1];
      cell_nodal_stresses(p, npc, law, measure(), options.q1_integration == MC_Q1_BBAR && npc == 4, ue, at_nodes);
      // the cell's stress at the edge's nodes (ends, middle), in that order
      double own[12] = {0};
      const int edge_node[3] = {c.a, c.b, c.mid};
      for (int e = 0; e < (c.quadratic() ? 3 : 2); ++e)
        for (int a = 0; a < npc; ++a)
          if (v[a] == edge_node[e])
            for (int k = 0; k < 4; ++k) own[4 * e + k] = at_nodes[4 * a + k];
      cell_eta2[nm][edge->cell] += contact_edge_terms(*this, g, group.first_position, int(seg), law, own, owns_row);
    }
  }
  for (int b = 0; b < n_bodies(); ++b)
    for (double e : cell_eta2[b]) eta2 += e;
  const double denominator = 2 * infos.energy + eta2;
  if (!(denominator > 0)) {  // no deformation, no error: every indicator 0
    for (int b = 0; b < n_bodies(); ++b) indicators[b].assign(cell_eta2[b].size(), 0.0);
    return;
  }
  estimate = std::sqrt(eta2 / denominator);
  for (int b = 0; b < n_bodies(); ++b) {
    indicators[b].resize(cell_eta2[b].size());
    for (size_t c = 0; c < cell_eta2[b].size(); ++c) indicators[b][c] = std::sqrt(cell_eta2[b][c] / denominator);
  }
}

}  // namespace mc
