// B per body, the contact rows' coefficients on each body's unknowns (ContactSystem::b_start,
// b_dof, b_value): a row's non-mortar weights on its group's non-mortar body, its mortar weights
// (negated) on the mortar body; with friction, each row of a pair with friction again along
// t = (-n_y, n_x) as B's row q + j, after all normal rows.
//
// A long interface's mortar weights are most of B (D^-1 R: some 60 per row) and most of the
// contact geometry's cost (docs/notes/contact-geometry-cost.md). The sparse path reads a row's
// mortar value w_a instead (ConstraintRows::aux), so B is first built without them (partial).
// Without friction it stays so: the gaps read -n . w_a for a row's mortar part and the mortar
// body's contact forces are R^T mu (Model::row_gap, add_contact_force). The condensed path and
// friction read B whole: complete_b completes it first (on another thread while the sparse
// path's ordering runs, with friction).
#include "solve/model.hpp"
#include "bodies/plane_vectors.hpp"
#include "support/stopwatch.hpp"
#include <exception>
#include <functional>
#include <system_error>
#include <thread>

namespace mc {

void Model::assemble_b(const ContactSystem &cs, bool mortar_values_weights, BArrays &out) const {
  const int n = n_bodies();
  out.start.assign(n, std::vector<int>{0});
  out.dof.assign(n, {}), out.value.assign(n, {});
  std::vector<std::vector<int>> t_start(n, std::vector<int>{0}), t_dof(n);
  std::vector<std::vector<double>> t_value(n);
  // B's entries, at most two per weight (and as many again for the tangential rows), reserved:
  // a long interface's B holds millions, and grown entry by entry its arrays were copied into
  // fresh memory again and again: with first touches of new pages dear, a third of the
  // geometry's time (docs/notes/contact-geometry-cost.md). Computed weights: estimated.
  {
    std::vector<size_t> entries(n, 0), t_entries(n, 0);
    size_t rows = 0;
    for (const ContactGroup &group : cs.groups) {
      const bool friction = group_friction(group).friction_law != MC_FRICTION_NONE;
      const size_t nonmortar = 2 * group.rows.position1.size();
      const size_t mortar =
          2 * (group.rows.body2_node.size() + (mortar_values_weights ? group.rows.pending_weights_estimate() : 0));
      entries[group.nonmortar] += nonmortar, entries[group.mortar] += mortar;
      if (friction) t_entries[group.nonmortar] += nonmortar, t_entries[group.mortar] += mortar;
      rows += size_t(group.rows.size()) * (friction ? 2 : 1);
    }
    for (int b = 0; b < n; ++b) {
      out.dof[b].reserve(entries[b] + t_entries[b]), out.value[b].reserve(entries[b] + t_entries[b]);
      out.start[b].reserve(rows + 1);
      t_dof[b].reserve(t_entries[b]), t_value[b].reserve(t_entries[b]);
    }
  }
  std::vector<int> nodes;
  std::vector<double> weights;
  std::vector<Point> vectors2;
  for (const ContactGroup &group : cs.groups) {
    const ConstraintRows &rows = group.rows;
    const bool friction = group_friction(group).friction_law != MC_FRICTION_NONE;
    const bool vectors = !rows.vector1.empty();  // each entry with its own direction
    MortarWeights mortar(rows);
    for (int r = 0; r < rows.size(); ++r) {
      const Point normal = rows.normal[r];
      // (A host body's freedom without an equation is restrained: it adds nothing to B.)
      const bool with_mortar = mortar_values_weights || rows.aux[r] < 0;
      if (with_mortar) mortar.row(r, nodes, weights, vectors2);
      // One row of B into (dofs, values, starts): each entry's vector v, or t = (-v_y, v_x) for
      // the tangential row.
      auto add_row = [&](std::vector<std::vector<int>> &dofs, std::vector<std::vector<double>> &values,
                         std::vector<std::vector<int>> &starts, bool tangential) {
        auto add = [&](int b, int node, Point v) {
          if (tangential) v = Point{-v.y, v.x};
          for (int c = 0; c < 2; ++c) {
            const int dof = dof_of(b, node, c);
            if (dof >= 0) dofs[b].push_back(dof), values[b].push_back(c == 0 ? v.x : v.y);
          }
        };
        for (int p = rows.start1[r]; p < rows.start1[r + 1]; ++p)
          add(group.nonmortar, group.geometry.nodes[rows.position1[p]],
              vectors ? rows.vector1[p] : scaled(normal, rows.weight1[p]));
        if (with_mortar)
          for (size_t p = 0; p < nodes.size(); ++p)
            add(group.mortar, nodes[p], scaled(vectors ? vectors2[p] : scaled(normal, weights[p]), -1));
        for (int b = 0; b < n; ++b) starts[b].push_back(int(dofs[b].size()));
      };
      add_row(out.dof, out.value, out.start, false);
      if (friction) add_row(t_dof, t_value, t_start, true);
    }
  }
  // The tangential rows after the normal ones: row q + j.
  const size_t tangential = n > 0 ? t_start[0].size() - 1 : 0;
  for (size_t j = 0; j < tangential; ++j) {
    for (int b = 0; b < n; ++b) {
      for (int p = t_start[b][j]; p < t_start[b][j + 1]; ++p)
        out.dof[b].push_back(t_dof[b][p]), out.value[b].push_back(t_value[b][p]);
      out.start[b].push_back(int(out.dof[b].size()));
    }
  }
}

// The interface unknowns of body b: its free DOFs in B, in B's order (the condensed path orders
// them last).
void Model::find_interface(int b) {
  BodySystem *sys = system_[b].get();
  if (!sys) return;
  sys->interface.clear();
  if (!contact_) return;
  std::vector<char> mark(sys->stiffness.n, 0);
  for (int dof : contact_->b_dof[b])
    if (sys->solve_index[dof] >= 0 && !mark[dof]) mark[dof] = 1, sys->interface.push_back(dof);
}

// B with every row's mortar weights, from a partial one (build_contact_system): on a second
// thread while `meanwhile` runs (the caller's work that does not read B), or before it without
// a second core, with MC_OPTION_THREADS 1 or without `meanwhile` (empty). The interface
// unknowns follow B.
void Model::complete_b(const std::function<void()> &meanwhile) {
  ContactSystem &cs = *contact_;
  if (!cs.b_partial) {
    if (meanwhile) meanwhile();
    return;
  }
  BArrays full;
  double seconds = 0;  // (measured where it runs; logged by the caller, on the calling thread)
  auto assemble = [&] {
    const double start = now();
    assemble_b(cs, true, full);
    seconds = now() - start;
  };
  if (threads_ > 1 && meanwhile) {
    std::exception_ptr error;
    std::thread worker;
    try {
      worker = std::thread([&] {
        try {
          assemble();
        } catch (...) {
          error = std::current_exception();
        }
      });
    } catch (const std::system_error &) {  // no thread to be had: before `meanwhile`
      assemble();
    }
    cs.b_completed_alongside = worker.joinable();
    try {
      meanwhile();
    } catch (...) {
      if (worker.joinable()) worker.join();
      throw;
    }
    if (worker.joinable()) worker.join();
    if (error) std::rethrow_exception(error);
  } else {
    assemble();
    if (meanwhile) meanwhile();
  }
  cs.b_completion_seconds += seconds;
  cs.b_start = std::move(full.start), cs.b_dof = std::move(full.dof), cs.b_value = std::move(full.value);
  cs.b_partial = false;
  for (ContactGroup &group : cs.groups) group.rows.release_mortar_weights();
  for (int b = 0; b < n_bodies(); ++b) find_interface(b);
}

}  // namespace mc
