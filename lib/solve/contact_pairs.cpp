// The model's contact pairs as the solve sees them: the pairs of one non-mortar and one mortar
// body joined into a group (one surface on each side, so that a surface split into pairs gives
// the unsplit answer and no position carries two multipliers), each group's geometry and rows
// (section 3 of the paper: the mortar operators of one non-mortar and one mortar surface), the
// groups' rows stacked into the one set of constraints the interface solvers read, B per body,
// and after the solve the contact results per position.
#include "bodies/plane_vectors.hpp"
#include "bodies/rigid_modes.hpp"
#include "support/lapack.hpp"
#include "solve/model.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace mc {

namespace {

// The pairs' numbers for a message: "pair 2" or "pairs 2 and 3".
std::string pair_list(const std::vector<int> &pairs) {
  std::string text = pairs.size() > 1 ? "pairs " : "pair ";
  for (size_t k = 0; k < pairs.size(); ++k)
    text += (k == 0 ? "" : k + 1 == pairs.size() ? " and " : ", ") + std::to_string(pairs[k] + 1);
  return text;
}

// Appends a group's rows to the stacked ones: its positions from first_position, its
// auxiliary points from the stacked count. Only what the interface solvers read is stacked: the
// non-mortar weights, normals, gaps, the rows' auxiliary points and their mortar equations (the
// mortar weights go to B, the pressures stay with the group's own rows).
void stack_rows(ConstraintRows &all, const ConstraintRows &rows, int first_position) {
  const int first_aux = all.aux_count;
  for (int r = 0; r < rows.size(); ++r) {
    for (int p = rows.start1[r]; p < rows.start1[r + 1]; ++p) {
      all.position1.push_back(rows.position1[p] + first_position);
      all.weight1.push_back(rows.weight1[p]);
      if (!rows.vector1.empty()) all.vector1.push_back(rows.vector1[p]);
    }
    all.start1.push_back(int(all.position1.size()));
    all.normal.push_back(rows.normal[r]);
    all.gap0.push_back(rows.gap0[r]);
    all.measure.push_back(rows.measure[r]);
    all.own_position.push_back(rows.own_position[r] >= 0 ? rows.own_position[r] + first_position : -1);
    all.aux.push_back(rows.aux[r] >= 0 ? rows.aux[r] + first_aux : -1);
  }
  for (int a = 0; a < rows.aux_count; ++a) {
    for (int p = rows.aux_d_start[a]; p < rows.aux_d_start[a + 1]; ++p)
      all.aux_d_point.push_back(rows.aux_d_point[p] + first_aux), all.aux_d.push_back(rows.aux_d[p]);
    all.aux_d_start.push_back(int(all.aux_d_point.size()));
    for (int p = rows.aux_r_start[a]; p < rows.aux_r_start[a + 1]; ++p)
      all.aux_r_node.push_back(rows.aux_r_node[p]), all.aux_r.push_back(rows.aux_r[p]);
    all.aux_r_start.push_back(int(all.aux_r_node.size()));
  }
  all.aux_count += rows.aux_count;
}

}  // namespace

// Before any work: every pair complete, on bodies that have meshes; a non-mortar edge on two
// pairs' surfaces refused (a position would carry two multipliers).
void Model::check_contact_pairs() const {
  for (size_t p = 0; p < pairs.size(); ++p) {
    const ContactPair &pair = pairs[p];
    if (!pair.has_side[0] && !pair.has_side[1]) continue;  // made, no surface yet: not used
    if (!pair.complete()) {
      const int missing = pair.has_side[0] ? 1 : 0;
      if (n_bodies() == 2 && pairs.size() == 1 && pair.nonmortar == 0 && pair.mortar == 1)  // the two-body calls' words
        fail(MC_ERROR_STATE, "body %d has a contact surface but body %d has none: contact needs both (mc_set_contact)",
             pair.body_of_side(1 - missing) + 1, pair.body_of_side(missing) + 1);
      fail(MC_ERROR_STATE, "pair %zu has no surface on its %s body %d: call mc_set_pair_surface", p + 1,
           missing == 0 ? "non-mortar" : "mortar", pair.body_of_side(missing) + 1);
    }
    for (int side = 0; side < 2; ++side)
      if (!body[pair.body_of_side(side)].has_mesh)
        fail(MC_ERROR_STATE, "pair %zu: body %d has no mesh: call mc_set_mesh or mc_set_host_body", p + 1,
             pair.body_of_side(side) + 1);
  }
  // A non-mortar edge belongs to one pair: the same edge given on two pairs' non-mortar sides
  // would be two multipliers for one position (MOOSE's rank-deficient Jacobian).
  std::map<std::pair<int, std::pair<int, int>>, int> owner;  // (body, (a, b)) -> pair
  for (size_t p = 0; p < pairs.size(); ++p) {
    if (!pairs[p].complete()) continue;
    for (const SurfaceSegment &e : pairs[p].side[0]) {
      const auto key = std::make_pair(pairs[p].nonmortar, std::make_pair(std::min(e.a, e.b), std::max(e.a, e.b)));
      auto [it, fresh] = owner.emplace(key, int(p));
      if (!fresh)
        fail(MC_ERROR_CONTACT,
             "body %d's edge (%d, %d) is on the non-mortar side of pair %d and of pair %zu: a non-mortar edge belongs "
             "to one pair",
             pairs[p].nonmortar + 1, e.a + index_base, e.b + index_base, it->second + 1, p + 1);
    }
  }
}

std::unique_ptr<ContactSystem> Model::build_contact_system(bool partial_b) {
  const double t_geometry = now();
  auto cs = std::make_unique<ContactSystem>();
  SurfaceOptions surface_options;
  surface_options.smooth = options.contact_surface == MC_SURFACE_SMOOTH;
  surface_options.feature_angle_degrees = options.feature_angle;
  // 1. The groups: the complete pairs by (non-mortar, mortar) body, in the order their first
  //    pair was made; each side's edges joined.
  for (size_t p = 0; p < pairs.size(); ++p) {
    const ContactPair &pair = pairs[p];
    if (!pair.complete()) continue;
    ContactGroup *group = nullptr;
    for (ContactGroup &g : cs->groups)
      if (g.nonmortar == pair.nonmortar && g.mortar == pair.mortar) group = &g;
    if (!group) {
      cs->groups.emplace_back();
      group = &cs->groups.back();
      group->nonmortar = pair.nonmortar, group->mortar = pair.mortar;
    }
    group->pairs.push_back(int(p));
  }
  int positions = 0, q = 0;
  for (size_t k = 0; k < cs->groups.size(); ++k) {
    ContactGroup &group = cs->groups[k];
    std::vector<SurfaceSegment> side[2];
    for (int p : group.pairs) {
      const ContactPair &pair = pairs[p];
      for (int s = 0; s < 2; ++s) side[s].insert(side[s].end(), pair.side[s].begin(), pair.side[s].end());
    }
    if (group.pairs.size() > 1) {  // a mortar edge given by two pairs is the same edge: kept once
      std::sort(side[1].begin(), side[1].end(), [](const SurfaceSegment &x, const SurfaceSegment &y) {
        return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
      });
      side[1].erase(std::unique(side[1].begin(), side[1].end(),
                                [](const SurfaceSegment &x, const SurfaceSegment &y) { return x.a == y.a && x.b == y.b; }),
                    side[1].end());
    }
    try {
      group.geometry = build_contact_geometry(body[group.nonmortar].mesh, side[0], body[group.mortar].mesh, side[1],
                                              options.contact_normal, surface_options, measure());
    } catch (const Error &e) {
      if (cs->groups.size() == 1 && pairs.size() == 1) throw;  // a two-body model: the message as it was
      fail(e.status(), "%s (non-mortar body %d, mortar body %d): %s", pair_list(group.pairs).c_str(),
           group.nonmortar + 1, group.mortar + 1, e.what());
    }
    group.rows = build_constraint_rows(group.geometry, options.method, options.multiplier, measure());
    group.first_position = positions, group.first_row = q;
    positions += group.positions(), q += group.rows.size();
  }
  // 2. Two groups whose non-mortar surfaces on one body meet at a node: a corner (the surface
  //    turns there by more than the feature angle) keeps one position per face, as inside one
  //    surface; where the surface runs on smoothly, the node would carry two multipliers for
  //    one direction (a null mode of the constraints), and is refused.
  {
    std::map<std::pair<int, int>, std::pair<int, Point>> seen;  // (body, node) -> (group, normal)
    const double cos_feature = std::cos(options.feature_angle * 3.14159265358979323846 / 180);
    for (size_t k = 0; k < cs->groups.size(); ++k) {
      const ContactGroup &group = cs->groups[k];
      for (int j = 0; j < group.positions(); ++j) {
        const auto key = std::make_pair(group.nonmortar, group.geometry.nodes[j]);
        auto [it, fresh] = seen.emplace(key, std::make_pair(int(k), group.geometry.normals[j]));
        if (fresh || it->second.first == int(k)) continue;
        const Point n = group.geometry.normals[j], m = it->second.second;
        if (n.x * m.x + n.y * m.y > cos_feature) {
          const ContactGroup &other = cs->groups[it->second.first];
          fail(MC_ERROR_CONTACT,
               "body %d's node %d is on the non-mortar surfaces of %s (mortar body %d) and %s (mortar body %d), "
               "which run on smoothly there (their normals differ by %.1f degrees, less than MC_OPTION_FEATURE_ANGLE): "
               "it would carry two multipliers; end one surface an edge earlier, or make the pairs' mortar sides one body",
               group.nonmortar + 1, group.geometry.nodes[j] + index_base, pair_list(other.pairs).c_str(), other.mortar + 1,
               pair_list(group.pairs).c_str(), group.mortar + 1,
               std::acos(std::max(-1.0, std::min(1.0, n.x * m.x + n.y * m.y))) * 180 / 3.14159265358979323846);
        }
      }
    }
  }
  // 3. The stacked rows and B per body (contact_b.cpp): a row's non-mortar part acts on its
  //    group's non-mortar body, its mortar part (-weights) on the mortar body. With friction,
  //    each row of a pair with friction also gets its tangential row (the same weights along
  //    t = (-n_y, n_x)), stacked after all normal rows.
  const int n = n_bodies();
  cs->body_rows.assign(n, {});
  std::vector<std::pair<int, int>> t_bodies;  // per tangential row: (non-mortar, mortar) body
  for (size_t k = 0; k < cs->groups.size(); ++k) {
    const ContactGroup &group = cs->groups[k];
    const ConstraintRows &rows = group.rows;
    const ContactPair &lead = group_friction(group);
    const bool friction = lead.friction_law != MC_FRICTION_NONE;
    stack_rows(cs->rows, rows, group.first_position);
    for (int j = 0; j < group.positions(); ++j) cs->position_group.push_back(int(k));
    for (int a = 0; a < rows.aux_count; ++a) cs->aux_group.push_back(int(k));
    for (int r = 0; r < rows.size(); ++r) {
      cs->row_group.push_back(int(k));
      const int row = group.first_row + r;
      cs->body_rows[group.nonmortar].push_back(row);
      if (group.mortar != group.nonmortar) cs->body_rows[group.mortar].push_back(row);
      if (!friction) continue;
      cs->tangent_of.push_back(row);
      cs->friction_law.push_back(lead.friction_law);
      cs->friction_bound.push_back(0);  // (set at every solve: refresh_friction)
      t_bodies.emplace_back(group.nonmortar, group.mortar);
    }
  }
  const int q_normal = cs->rows.size();
  for (size_t j = 0; j < cs->tangent_of.size(); ++j) {
    const int row = q_normal + int(j);
    cs->body_rows[t_bodies[j].first].push_back(row);
    if (t_bodies[j].second != t_bodies[j].first) cs->body_rows[t_bodies[j].second].push_back(row);
  }
  {
    BArrays b;
    assemble_b(*cs, !partial_b, b);
    cs->b_start = std::move(b.start), cs->b_dof = std::move(b.dof), cs->b_value = std::move(b.value);
    cs->b_partial = partial_b;
  }
  // B holds the mortar weights from here on: the groups' copies go (the stacked rows never had
  // them); a partial B keeps what completes it.
  if (!partial_b)
    for (ContactGroup &group : cs->groups) group.rows.release_mortar_weights();
  // Stacked vectors exist for every entry or for none (a group without them: its normal times
  // its weight).
  if (!cs->rows.vector1.empty() && cs->rows.vector1.size() != cs->rows.weight1.size()) {
    std::vector<Point> all;
    for (int r = 0; r < cs->rows.size(); ++r) {
      const ConstraintRows &own = cs->groups[cs->row_group[r]].rows;
      const int local = r - cs->groups[cs->row_group[r]].first_row;
      for (int p = cs->rows.start1[r]; p < cs->rows.start1[r + 1]; ++p) {
        const int p_own = own.start1[local] + (p - cs->rows.start1[r]);
        all.push_back(own.vector1.empty() ? scaled(cs->rows.normal[r], cs->rows.weight1[p]) : own.vector1[p_own]);
      }
    }
    cs->rows.vector1 = std::move(all);
  }
  // 4. Each pair's positions: those of its group on the pair's own non-mortar edges.
  cs->pair_positions.assign(pairs.size(), {});
  for (const ContactGroup &group : cs->groups)
    for (int p : group.pairs) {
      std::vector<char> on_pair(body[group.nonmortar].mesh.n_nodes(), 0);
      for (const SurfaceSegment &e : pairs[p].side[0]) {
        on_pair[e.a] = on_pair[e.b] = 1;
        if (e.mid >= 0) on_pair[e.mid] = 1;
      }
      for (int j = 0; j < group.positions(); ++j)
        if (group.pairs.size() == 1 || on_pair[group.geometry.nodes[j]])
          cs->pair_positions[p].push_back(group.first_position + j);
    }
  if (cs->groups.size() == 1)
    progress(MC_LOG_PHASE, "contact geometry and mortar operators: %zu body-%d contact nodes, %d constraint rows, %.3g s",
             cs->groups[0].geometry.nodes.size(), cs->groups[0].nonmortar + 1, cs->rows.size(), now() - t_geometry);
  else
    progress(MC_LOG_PHASE, "contact geometry and mortar operators: %zu groups of pairs, %d contact positions, %d "
             "constraint rows, %.3g s", cs->groups.size(), positions, cs->rows.size(), now() - t_geometry);
  return cs;
}

// The rigid motions no support and no pair can hold, named body by body: the null space of G =
// B R (every row of every pair taken as active), each direction split into the bodies it moves
// and each body's share fitted to (translation x, translation y, rotation about its centroid)
// and named ("body 2: translation in x"). Empty if every row together holds every mode (the
// active set at hand did not: the caller then names the free modes).
std::string Model::unheld_modes_description(const std::vector<char> &holding) const {
  const std::vector<double> g = rigid_mode_rows();
  const int q = contact_->b_rows(), k = q > 0 ? int(g.size()) / q : 0;
  if (k == 0) return "";
  std::vector<double> gram(size_t(k) * k, 0.0), eig(k);
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b)
      for (int r = 0; r < q; ++r)
        if (holding.empty() || holding[r]) gram[size_t(b) * k + a] += g[size_t(a) * q + r] * g[size_t(b) * q + r];
  int n = k, lwork = 64 + 3 * k, info = 0;
  std::vector<double> work(lwork);
  dsyev_("V", "U", &n, gram.data(), &n, eig.data(), work.data(), &lwork, &info);
  if (info != 0) return "";
  std::string text;
  for (int c = 0; c < k && eig[c] <= 1e-10 * std::max(eig[k - 1], 1e-300); ++c) {
    const double *v = &gram[size_t(c) * k];
    for (int b = 0; b < n_bodies(); ++b) {
      if (!system_[b] || system_[b]->rigid.count == 0) continue;
      const RigidModes &rm = system_[b]->rigid;
      const int ndof = system_[b]->stiffness.n, offset = mode_offset(b);
      std::vector<double> u(ndof, 0.0);
      double share = 0;
      for (int m = 0; m < rm.count; ++m) share += v[offset + m] * v[offset + m];
      if (share < 1e-12) continue;  // this direction leaves body b where it is
      for (int m = 0; m < rm.count; ++m)
        for (int i = 0; i < ndof; ++i) u[i] += v[offset + m] * rm.modes[size_t(m) * ndof + i];
      // u's rigid motion: least squares on tx, ty and a rotation scaled by the body's size.
      const Body &bd = body[b];
      std::vector<Point> point(ndof);
      std::vector<int> component(ndof, -1);
      for (int i = 0; i < ndof; ++i) {
        const int node = bd.host ? bd.host_data.node_of_equation[i] : i / 2;
        if (node < 0) continue;
        point[i] = bd.mesh.node(node), component[i] = bd.host ? bd.host_data.component_of_equation[i] : i % 2;
      }
      Point centre{0, 0}, low{0, 0}, high{0, 0};
      int counted = 0;
      for (int i = 0; i < ndof; ++i)
        if (component[i] >= 0) {
          const Point p = point[i];
          if (counted == 0) low = high = p;
          centre.x += p.x, centre.y += p.y, ++counted;
          low.x = std::min(low.x, p.x), low.y = std::min(low.y, p.y), high.x = std::max(high.x, p.x), high.y = std::max(high.y, p.y);
        }
      if (counted == 0) continue;
      centre.x /= counted, centre.y /= counted;
      const double size = std::max({high.x - low.x, high.y - low.y, 1e-300});
      double normal[9] = {0}, rhs[3] = {0};
      for (int i = 0; i < ndof; ++i) {
        if (component[i] < 0) continue;
        const double row[3] = {component[i] == 0 ? 1.0 : 0.0, component[i] == 1 ? 1.0 : 0.0,
                               component[i] == 0 ? -(point[i].y - centre.y) / size : (point[i].x - centre.x) / size};
        for (int a = 0; a < 3; ++a) {
          rhs[a] += row[a] * u[i];
          for (int bb = 0; bb < 3; ++bb) normal[3 * a + bb] += row[a] * row[bb];
        }
      }
      int three = 3, one = 1, pivots[3], fit = 0;
      dgesv_(&three, &one, normal, &three, pivots, rhs, &three, &fit);
      if (fit != 0) continue;
      const double length = std::sqrt(rhs[0] * rhs[0] + rhs[1] * rhs[1] + rhs[2] * rhs[2]);
      if (!(length > 0)) continue;
      for (double &x : rhs) x /= length;
      text += (text.empty() ? "" : "; ") + std::string("body ") + std::to_string(b + 1) + ": " + describe_rigid_motion(rhs);
    }
  }
  return text;
}

// The host's gap offsets (mc_set_gap_offset, mc_set_pair_gap_offset) per group, at every solve:
// they change without a rebuild. A node of two joined pairs takes the offset one of them gives.
void Model::merge_gap_offsets() {
  for (ContactGroup &group : contact_->groups) {
    group.gap_offset.clear();
    for (int p : group.pairs) {
      const ContactPair &pair = pairs[p];
      if (pair.gap_offset.empty()) continue;
      if (group.gap_offset.empty()) group.gap_offset.assign(body[group.nonmortar].mesh.n_nodes(), 0.0);
      for (size_t i = 0; i < pair.gap_offset.size(); ++i)
        if (pair.gap_offset[i] != 0) group.gap_offset[i] = pair.gap_offset[i];
    }
  }
}

// Contact results per position, group by group: a row's force lambda_r acts on its non-mortar
// positions with the row's weights; a position's pressure is its force over its tributary
// measure (lumped recovery), or the weak rows' own pressure field (a quadratic non-mortar side).
void Model::contact_results(const std::vector<double> &lambda) {
  contact_force.clear(), contact_gap.clear(), contact_pressure.clear();
  if (!contact_) return;
  const ContactSystem &cs = *contact_;
  size_t n = 0;
  for (const ContactGroup &group : cs.groups) n += size_t(group.positions());
  contact_force.assign(n, 0.0);
  contact_gap.assign(n, kNoGap);
  contact_pressure.assign(n, 0.0);
  for (const ContactGroup &group : cs.groups) {
    const ContactGeometry &g = group.geometry;
    const ConstraintRows &rows = group.rows;
    const int first = group.first_position;
    for (int r = 0; r < rows.size(); ++r) {
      const int row = group.first_row + r;
      const double gap = row_gap(row);
      if (rows.own_position[r] >= 0) contact_gap[first + rows.own_position[r]] = gap;
      for (int p = rows.start1[r]; p < rows.start1[r + 1]; ++p)
        contact_force[first + rows.position1[p]] += rows.weight1[p] * lambda[row];
    }
    if (g.quadratic_nonmortar)  // the middles and the ends own no row: their gaps pointwise
      for (int pos = 0; pos < group.positions(); ++pos)
        if (contact_gap[first + pos] == kNoGap && g.projection[pos].segment >= 0)
          contact_gap[first + pos] = pointwise_gap(size_t(first + pos));
    if (!rows.pressure_of_position.empty()) {
      // The weak rows' own pressure field (a quadratic non-mortar side: mortar_operators.hpp). The
      // lumped force over tributary measure would be it on straight evenly spaced edges, but a P2
      // corner's tributary measure is h/6, and on graded or curved edges the forces that the
      // neighbouring multipliers put on it make the lumped pressures alternate from corner to
      // middle (measured: 3 to 5 % of p0 on two cylinders, docs/robustness.md).
      for (int pos = 0; pos < group.positions(); ++pos)
        for (auto &[r, c] : rows.pressure_of_position[pos]) contact_pressure[first + pos] += c * lambda[group.first_row + r];
    } else {
      for (int pos = 0; pos < group.positions(); ++pos)
        // The tributary measure includes the thickness (or 2 pi r): a position whose contact edges
        // all lie on the axis stands for no area; its force is reported, its pressure as 0.
        if (g.tributary[pos] > 0) contact_pressure[first + pos] = contact_force[first + pos] / g.tributary[pos];
    }
  }
}

}  // namespace mc
