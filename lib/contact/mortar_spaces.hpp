// What the two kinds of constraint rows share (mortar_operators.cpp: the paper's rows of a linear
// body 1; weak_mortar_rows.cpp: the weak rows of a quadratic one). Internal to the library.
#pragma once
#include "contact/mortar_operators.hpp"

namespace mc {

// The body-2 trace at a surface point: its nodes (2, or 3 on a quadratic edge: ends, middle) and
// their shape functions there. Returns the count.
int mortar_trace(const ContactGeometry &g, SurfacePoint at, int node[3], double shape[3]);

// The paper's multiplier space M_h^1 on a run (section 3): the hats of the run's trace points,
// merged at an open run's two ends (constant on the end elements: psi_1 = phi_0 + phi_1,
// psi_{n-2} = phi_{n-2} + phi_{n-1}); a closed run keeps all its hats. When an end element is only
// a fraction theta of its body-1 segment (Gamma_c ends inside it), the neighbouring node's hat
// on the next element is shared between the end multiplier (w = theta^2) and the next one
// (1 - w): at theta = 1 this is the paper's space, and as theta -> 0 it becomes the paper's
// space of the run that ends at that node, with the vanishing element's multiplier (whose
// integrals are O(theta), the shared part O(theta^2)) pinning the constraint to the end value
// there. So the cone changes continuously as body 2's end crosses a body-1 node, because the
// paper's rows hold that end value pointwise anyway. The dual basis shares the same way (its
// hats' dual functions; D is then no longer diagonal in the two rows next to a partly covered
// end): unshared, dual mortar's displacements jumped by 0.56 % between body 2 ending 1e-5 of an
// edge before a body-1 node and at it (test_quadratic, P1 on P1). The weak rows of a quadratic
// body 1 have no pointwise end row: they take the space unshared and blend its end multipliers
// instead (weak_mortar_rows.cpp).
struct MultiplierSpace {
  int n;
  bool closed, share;
  double theta_start = 1, theta_end = 1;

  MultiplierSpace(const ContactRun &run, bool share_ends) : n(int(run.trace.size())), closed(run.closed) {
    auto share_of = [](double theta) { return theta * theta; };
    theta_start = share_of(run.trace.front().is_position() ? 1 : 1 - run.trace.front().xi);
    theta_end = share_of(run.trace.back().is_position() ? 1 : run.trace.back().xi);
    share = !closed && n >= 4 && share_ends;
  }
  // The multipliers that trace point k's hat on element e feeds, with their shares of `value`.
  template <class Add> void feed(int e, int k, double value, Add &&add) const {
    if (closed) return add(k % n, value);
    if (k == 0) return add(1, value);
    if (k == n - 1) return add(n - 2, value);
    if (share && k == 1 && e == 1) return add(1, theta_start * value), add(2, (1 - theta_start) * value);
    if (share && k == n - 2 && e == n - 3) return add(n - 2, theta_end * value), add(n - 3, (1 - theta_end) * value);
    add(k, value);
  }
};

// The rows of one run of a body 1 with quadratic cells (weak_mortar_rows.cpp); quadratic: the
// quadratic multiplier space (MC_MULTIPLIER_QUADRATIC), else the paper's linear one; dual: its
// dual basis instead (MC_METHOD_DUAL_MORTAR; the quadratic space whatever `quadratic` says).
void weak_mortar_rows(const ContactGeometry &g, const ContactRun &run, bool quadratic, bool dual, ConstraintRows &rows);

}  // namespace mc
