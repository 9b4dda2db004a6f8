// The bodies' own phases of a solve, each run for both bodies (Model::for_each_body): their
// load vectors, stiffness and rigid modes (assembled from cells, or the host's), the reduced
// matrices, their analyses and factorizations (their stresses: results/results_on_demand.cpp).
#include "bodies/cell_shapes.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include "solve/model.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace mc {

std::vector<double> Model::load_vector(int b) const {
  const Body &body_ = body[b];
  const Mesh &mesh = body_.mesh;
  std::vector<double> f(body_.nodal_force);
  if (body_.host) {  // the host's load vector, plus nodal forces on its nodes' equations
    for (int e = 0; e < body_.host_data.n_equations; ++e) f[e] += body_.host_data.load[e];
    return f;
  }
  f.resize(2 * size_t(mesh.n_nodes()), 0.0);
  double fe[2 * kMaxCellNodes];
  for (const EdgeLoad &load : body_.edge_loads) {
    Point p = mesh.node(load.a), q = mesh.node(load.b);
    const BoundaryEdge *edge = mesh.quadratic() ? mesh.boundary_edge(load.a, load.b) : nullptr;
    if (edge && edge->mid >= 0) {  // a 3-node edge, curved if its middle is off the chord
      quadratic_edge_force(p, q, mesh.node(edge->mid), load.tx, load.ty, load.is_pressure, measure(), fe);
      const int node[3] = {load.a, load.b, edge->mid};
      for (int a = 0; a < 3; ++a) f[2 * node[a]] += fe[2 * a], f[2 * node[a] + 1] += fe[2 * a + 1];
      continue;
    }
    double tx = load.tx, ty = load.ty;
    if (load.is_pressure) {  // pressure pushes against the outward normal (dy, -dx)/|e|
      double length = std::hypot(q.x - p.x, q.y - p.y);
      tx = -load.tx * (q.y - p.y) / length;
      ty = -load.tx * (p.x - q.x) / length;
    }
    edge_traction_force(p, q, tx, ty, measure(), fe);
    f[2 * load.a] += fe[0], f[2 * load.a + 1] += fe[1];
    f[2 * load.b] += fe[2], f[2 * load.b + 1] += fe[3];
  }
  if (body_.body_force[0] != 0 || body_.body_force[1] != 0) {
    const int npc = mesh.nodes_per_cell();
    Point p[kMaxCellNodes];
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int *v = mesh.cell(c);
      for (int a = 0; a < npc; ++a) p[a] = mesh.node(v[a]);
      cell_body_force(p, npc, body_.body_force[0], body_.body_force[1], measure(), fe);
      for (int a = 0; a < npc; ++a) f[2 * v[a]] += fe[2 * a], f[2 * v[a] + 1] += fe[2 * a + 1];
    }
  }
  return f;
}

// Stiffness and rigid modes of one body (the first half of its structure).
std::unique_ptr<BodySystem> Model::assemble_body(int b, BodyWork &work) const {
  const Body &body_ = body[b];
  if (!body_.has_mesh) return nullptr;
  auto sys = std::make_unique<BodySystem>();
  const double t_assembly = now();
  if (body_.host) {
    {
      Stopwatch watch(work.infos.t_assembly);
      sys->stiffness = assemble_host_stiffness(body_.host_data, b + 1, index_base);
      // The rigid modes from the coordinates of every unknown, when every one is a given node's
      // freedom: the motions the host's matrix does not resist.
      const HostBody &h = body_.host_data;
      if (std::all_of(h.node_of_equation.begin(), h.node_of_equation.end(), [](int node) { return node >= 0; })) {
        std::vector<Point> point(h.n_equations);
        for (int e = 0; e < h.n_equations; ++e) point[e] = body_.mesh.node(h.node_of_equation[e]);
        sys->rigid = kernel_rigid_modes(point, h.component_of_equation, sys->stiffness, axisymmetric);
      }
    }
    work.log(MC_LOG_PHASE, "assembly: body %d, host body of %d equations, %zu stiffness entries, %.3g s", b + 1,
             body_.host_data.n_equations, body_.host_data.entry_value.size(), now() - t_assembly);
    check_host_rigid_candidates(b, sys->rigid, work);
    if (sys->rigid.count > 0 && !in_contact(b))
      fail(MC_ERROR_SINGULAR,
           "body %d is not held: the host's stiffness leaves %s free; restrain freedoms (give them no equation), or "
           "give both bodies contact surfaces so that contact can hold it",
           b + 1, sys->rigid.description.c_str());
    return sys;
  }
  {
    Stopwatch watch(work.infos.t_assembly);
    if (!body_.cell_elasticity.empty()) {
      for (int c = 0; c < body_.mesh.n_cells(); ++c) sys->laws.push_back(general_plane_law(&body_.cell_elasticity[9 * size_t(c)]));
    } else {
      sys->laws.push_back(axisymmetric ? isotropic_axisymmetric_law(body_.young, body_.poisson)
                                       : isotropic_plane_law(body_.young, body_.poisson, plane_stress));
    }
    sys->stiffness = assemble_stiffness(body_.mesh, sys->laws, measure(),
                                        options.q1_integration == MC_Q1_BBAR && body_.mesh.nodes_per_cell() == 4);
  }
  work.log(MC_LOG_PHASE, "assembly: body %d, %d nodes, %d cells, stiffness in %.3g s", b + 1,
           body_.mesh.n_nodes(), body_.mesh.n_cells(), now() - t_assembly);
  sys->rigid = axisymmetric ? free_axial_translation(body_.mesh, fixed_[b]) : free_rigid_modes(body_.mesh, fixed_[b]);
  if (sys->rigid.count > 0 && !in_contact(b))
    fail(MC_ERROR_SINGULAR,
         "body %d is not held: its supports leave %s free; add supports with mc_fix, or contact "
         "surfaces on both bodies with mc_set_contact so that contact can hold it",
         b + 1, sys->rigid.description.c_str());
  return sys;
}

// The reduced stiffness of one body: supports and the pins of its rigid modes removed, and its
// contact unknowns (those in B), which the condensed path orders last.
void Model::reduce_body(int b, BodyWork &work) {
  BodySystem *sys = system_[b].get();
  if (!sys) return;
  const int ndof = sys->stiffness.n;
  std::vector<char> excluded(fixed_[b]);
  for (int dof : sys->rigid.pinned_dofs) excluded[dof] = 1;
  sys->solve_index.assign(ndof, -1);
  sys->solve_dofs.clear();
  for (int i = 0; i < ndof; ++i)
    if (!excluded[i]) sys->solve_index[i] = int(sys->solve_dofs.size()), sys->solve_dofs.push_back(i);
  find_interface(b);  // (B partial: found again if it is completed, complete_b)
  reduce_stiffness(b, work);
}

void Model::reduce_stiffness(int b, BodyWork &work) {
  BodySystem *sys = system_[b].get();
  Stopwatch watch(work.infos.t_assembly);
  sys->reduced = sys->stiffness.principal_submatrix(sys->solve_index, int(sys->solve_dofs.size()));
  sys->reduced_held = true;
}

// The condensed path's ordering (interface unknowns last) and symbolic factorization.
void Model::analyze_body(int b, BodyWork &work, bool needed) {
  BodySystem *sys = system_[b].get();
  if (!sys) return;
  std::vector<int> interface_reduced;
  for (int dof : sys->interface) interface_reduced.push_back(sys->solve_index[dof]);
  // The dense trailing block alone: past a billion entries (8 GiB, and near CHOLMOD's 32-bit
  // index range, which made its analysis fail with "too large") the condensed path is out of
  // reach whatever the memory. For the automatic choice (needed false) the body is then left
  // unanalysed and the choice takes the sparse path (measured: two Q8 strips with 32001
  // contact nodes failed here before); the condensed path itself (needed) is refused.
  const double ng = double(interface_reduced.size());
  if (ng * (ng + 1) / 2 > 1e9) {
    if (needed)
      fail(MC_ERROR_MEMORY,
           "the condensed interface solver (MC_INTERFACE_CONDENSED): body %d has %.0f interface unknowns, whose dense "
           "block in its factor would hold %.3g entries: use MC_INTERFACE_SPARSE or MC_INTERFACE_AUTO",
           b + 1, ng, ng * (ng + 1) / 2);
    work.log(MC_LOG_PHASE, "analysis: body %d, %.0f interface unknowns: too many for the condensed path, not analysed "
             "for it", b + 1, ng);
    return;
  }
  const double t_analysis = now();
  {
    Stopwatch watch(work.infos.t_analysis);
    sys->cholesky.analyze(sys->reduced, interface_reduced, options.ordering);
  }
  work.log(MC_LOG_PHASE, "analysis: body %d, %zu unknowns, ordering and symbolic factorization in %.3g s", b + 1,
           sys->solve_dofs.size(), now() - t_analysis);
}

void Model::factorize_body(int b, BodyWork &work) {
  BodySystem *sys = system_[b].get();
  if (!sys) return;
  const double t_factor = now();
  {
    Stopwatch watch(work.infos.t_factor);
    try {
      sys->cholesky.factorize(sys->reduced);
    } catch (const Error &e) {
      if (e.status() != MC_ERROR_SINGULAR) throw;
      const int failed = sys->cholesky.failed_unknown();
      if (body[b].host && failed >= 0 && failed < int(sys->solve_dofs.size())) {
        const int equation = sys->solve_dofs[failed];
        fail(MC_ERROR_SINGULAR,
             "body %d: the host's stiffness is not positive definite: the factorization fails at its equation %d "
             "(a part of the body moves without resistance, beyond %s, or the matrix is not a stiffness)",
             b + 1, equation + index_base,
             sys->rigid.count > 0 ? "the rigid modes found from the coordinates" : "any rigid mode");
      }
      fail(MC_ERROR_SINGULAR, "body %d: %s", b + 1, e.what());
    }
  }
  work.infos.factorizations++;
  work.log(MC_LOG_PHASE, "factorization: body %d, %ld nonzeros in the Cholesky factor, %.3g s", b + 1,
           long(sys->cholesky.factor_nnz()), now() - t_factor);
  if (body[b].host) check_held_motions_in_factor(b, work);
}

// A host body's rigid motions as judged by kernel_rigid_modes, in the log; a direction in the
// ambiguous band (held far less firmly than a support holds, yet more than round-off) is
// refused: treated as free it would drop the hold, treated as held it leaves the rigid motion
// to a near-singular factorization.
void Model::check_host_rigid_candidates(int b, const RigidModes &rigid, BodyWork &work) const {
  for (const RigidCandidate &c : rigid.candidates)
    work.log(MC_LOG_PHASE,
             "rigid modes: body %d, %s: %s (unbalanced share of a row's forces %.3g; |K R v| / (kmax |R v|) = %.3g)",
             b + 1, c.description.c_str(),
             c.kind == RigidCandidate::free ? "free" : c.kind == RigidCandidate::held ? "held" : "ambiguous",
             c.resistance, c.norm_ratio);
  for (const RigidCandidate &c : rigid.candidates)
    if (c.kind == RigidCandidate::ambiguous)
      fail(MC_ERROR_SINGULAR,
           "body %d: the host's stiffness holds a rigid motion (%s) only weakly: it leaves %.3g of a row's forces unbalanced "
           "(|K R v| / (kmax |R v|) = %.3g), above round-off (free: <= %g) but far below a support (held: >= %g); the "
           "rigid motion is not determined: restrain the body (give freedoms no equation), or check the element "
           "matrices' precision",
           b + 1, c.description.c_str(), c.resistance, c.norm_ratio, kFreeResistance, kHeldResistance);
}

// The safety net after a host body's factorization: the compliance of the factor along the held
// rigid motions W (the largest eigenvalue of W^T K^-1 W, orthonormal W on the factor's
// unknowns). Its inverse k_eff is the stiffness that holds the softest rigid motion; the
// factor determines that motion to about eta kmax / k_eff, eta the matrix's own rigid-body
// invariance (the largest resistance of a free mode, else double precision's). Refused when that
// is worse than 1 %: a body held only by round-off, or by a hold the classification could not
// see, never comes back as MC_OK with an arbitrary rigid motion. (The sparse interface path has
// no factor of the body alone; the classification is its check.)
void Model::check_held_motions_in_factor(int b, BodyWork &work) const {
  const BodySystem &sys = *system_[b];
  const RigidModes &rigid = sys.rigid;
  const int h = rigid.held_count, ndof = sys.stiffness.n, nr = int(sys.solve_dofs.size());
  if (h == 0 || nr == 0) return;
  double kmax = 0, eta = std::numeric_limits<double>::epsilon();
  for (double v : sys.stiffness.values) kmax = std::max(kmax, std::fabs(v));
  for (const RigidCandidate &c : rigid.candidates)
    if (c.kind == RigidCandidate::free) eta = std::max(eta, c.resistance);
  // W on the factor's unknowns (pins and supports dropped), orthonormalized; motion keeps each
  // column's (tx, ty, rotation) coefficients through the same operations.
  std::vector<double> w(size_t(nr) * h), motion(3 * size_t(h));
  int kept = 0;
  for (int c = 0, held_index = 0; c < int(rigid.candidates.size()); ++c) {
    const RigidCandidate &cand = rigid.candidates[c];
    if (cand.kind != RigidCandidate::held) continue;
    double *col = &w[size_t(kept) * nr], *m = &motion[3 * size_t(kept)];
    for (int k = 0; k < nr; ++k) col[k] = rigid.held[size_t(held_index) * ndof + sys.solve_dofs[k]];
    for (int x = 0; x < 3; ++x) m[x] = cand.motion[x];
    ++held_index;
    for (int o = 0; o < kept; ++o) {
      const double *other = &w[size_t(o) * nr];
      double dot = 0;
      for (int k = 0; k < nr; ++k) dot += col[k] * other[k];
      for (int k = 0; k < nr; ++k) col[k] -= dot * other[k];
      for (int x = 0; x < 3; ++x) m[x] -= dot * motion[3 * size_t(o) + x];
    }
    double norm = 0;
    for (int k = 0; k < nr; ++k) norm += col[k] * col[k];
    norm = std::sqrt(norm);
    if (!(norm > 1e-8)) continue;  // nothing of it left on the factor's unknowns
    for (int k = 0; k < nr; ++k) col[k] /= norm;
    for (int x = 0; x < 3; ++x) m[x] /= norm;
    ++kept;
  }
  if (kept == 0) return;
  std::vector<double> z(w.begin(), w.begin() + size_t(kept) * nr);
  sys.cholesky.solve(z.data(), kept);
  double compliance[9] = {0}, lambda[3], work_space[32];
  for (int a = 0; a < kept; ++a)
    for (int c = 0; c < kept; ++c) {
      double sum = 0;
      for (int k = 0; k < nr; ++k) sum += w[size_t(a) * nr + k] * z[size_t(c) * nr + k];
      compliance[kept * a + c] = sum;
    }
  int n = kept, lwork = 32, info = 0;
  dsyev_("V", "U", &n, compliance, &n, lambda, work_space, &lwork, &info);
  if (info != 0 || !(lambda[kept - 1] > 0)) return;  // (a positive definite factor has a positive one)
  const double k_eff = 1 / lambda[kept - 1];
  double softest[3] = {0, 0, 0};
  for (int a = 0; a < kept; ++a)
    for (int x = 0; x < 3; ++x) softest[x] += compliance[kept * (kept - 1) + a] * motion[3 * size_t(a) + x];
  const std::string name = axisymmetric ? std::string("translation along the axis (y)") : describe_rigid_motion(softest);
  work.log(MC_LOG_PHASE, "factorization: body %d, its least held rigid motion (%s) held with %.3g kmax (matrix rigid-body invariant to %.3g)", b + 1,
           name.c_str(), k_eff / kmax, eta);
  if (eta * kmax / k_eff > 1e-2)
    fail(MC_ERROR_SINGULAR,
         "body %d: the factorization is nearly singular along a rigid motion (%s): the host's stiffness holds it with %.3g of "
         "max|K_ij| per unit motion, while the matrix is rigid-body invariant only to %.3g of its rows' forces, so "
         "the rigid motion is not determined: restrain the body (give freedoms no equation), or check the element "
         "matrices' precision",
         b + 1, name.c_str(), k_eff / kmax, eta);
}


}  // namespace mc
