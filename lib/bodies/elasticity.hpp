// Element integrals of linear elasticity on the 2D mesh: the paper's a(u, v) = integral of
// A eps(u) : eps(v) (section 2) and the load integrals of L(v), cell by cell, each carrying the
// model's measure (line_measure.hpp): the thickness t of a plane model, or 2 pi r of an
// axisymmetric one.
// Voigt order: xx, yy, engineering xy; an axisymmetric model (x = r, y = z) adds the hoop
// strain eps_theta_theta = u_r / r as a fourth component.
#pragma once
#include "bodies/line_measure.hpp"
#include "bodies/mesh.hpp"

namespace mc {

// The law sigma = D eps and what gives the out-of-plane stress.
struct PlaneLaw {
  int n_strain = 3;  // 3: plane (xx, yy, xy); 4: axisymmetric (rr, zz, rz, theta theta)
  double d[16];      // row-major, stride 4: d[4 * row + column]; rows/columns past n_strain unused
  double zz_factor;  // plane models: sigma_zz = zz_factor * (sigma_xx + sigma_yy), nu in plane strain, else 0
};

PlaneLaw isotropic_plane_law(double young, double poisson, bool plane_stress);
// The isotropic 3D law restricted to (rr, zz, rz, theta theta): no strain component vanishes.
PlaneLaw isotropic_axisymmetric_law(double young, double poisson);
PlaneLaw general_plane_law(const double d[9]);

// Stiffness of a cell of any kind (cell_shapes.hpp: P1, Q1, T6, Q8, Q9; npc nodes at p): the
// integral of B^T D B w by the cell's quadrature rule. With bbar (Q1 only), the dilatation is
// replaced by its cell average (Hughes' B-bar), which removes volumetric locking.
// ke: (2 npc) x (2 npc) row-major.
void cell_stiffness(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar, double *ke);

// Stress of a cell with nodal displacements ue (2 per node), averaged over the cell with the
// measure's weight (exact for plane P1): (xx, yy, xy, zz), the fourth the out-of-plane normal
// stress: sigma_zz of a plane model, the hoop stress sigma_theta_theta of an axisymmetric one.
void cell_stress(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar, const double *ue,
                 double sigma[4]);
// The same stress evaluated at each of the cell's nodes: 4 per node. On the axis of an
// axisymmetric model the hoop strain u_r / r is taken as its limit du_r / dr.
void cell_nodal_stresses(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                         const double *ue, double *sigma);

// The stresses of a cell at its sampling points, the points where they are most accurate
// (stress_recovery.hpp): its quadrature points for P1 and Q1, the 3 interior points (2/3, 1/6,
// 1/6) of a T6, the 2x2 Gauss points of a Q8 or Q9. Fills x (where) and sigma (4 per point);
// returns the count (at most kMaxCellPoints).
// weight (optional): for P1 and Q1, whose sampling points are their quadrature points, each
// point's quadrature weight (the measure included), so that a caller can integrate with them.
int cell_sampled_stresses(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                          const double *ue, Point *x, double *sigma, double *weight = nullptr);

// The recovery (Zienkiewicz-Zhu) error of a cell: the integral over the cell of
// (sigma* - sigma_h)^T D^-1 (sigma* - sigma_h) w, where sigma_h is the cell's own stress and
// sigma* = sum_a N_a sigma_a interpolates the recovered stresses at its nodes (4 per node, as
// cell_nodal_stresses; the plane models' fourth, sigma_zz, is not an independent component and
// is left out). The energy of the stress error, in the units of the strain energy. Integrated
// by error_quadrature_rule (a T6: 6 points, not its stiffness's 3, where sigma* was fitted).
// compliance: D^-1 of the law (law_compliance), computed once per law by the caller.
double cell_recovery_error(const Point *p, int npc, const PlaneLaw &law, const double compliance[16],
                           const LineMeasure &measure, bool bbar, const double *ue, const double *nodal_sigma);
// D^-1 of the law's n_strain x n_strain block (row-major, stride 4).
void law_compliance(const PlaneLaw &law, double c[16]);

// Consistent nodal forces of a uniform body force b (per unit volume): integral of N_a b w.
void cell_body_force(const Point *p, int npc, double bx, double by, const LineMeasure &measure, double *fe);

// Consistent nodal forces of a uniform traction on a straight edge p->q (per unit area of the
// true surface): integral of N_a t w, half of the resultant to each end in a plane model.
void edge_traction_force(Point p, Point q, double tx, double ty, const LineMeasure &measure, double fe[4]);
// The same on a quadratic edge from p to q through its mid-edge node m (a parabola, curved when m
// is off the chord): fe holds p's, q's and m's forces (6). With is_pressure, tx is a pressure
// that pushes against the curve's own outward normal wherever it points along the edge
// (body on the left of p -> q); otherwise (tx, ty) is a traction in global axes. A uniform
// pressure on a straight edge gives 1/6, 1/6 and 2/3 of its resultant.
void quadratic_edge_force(Point p, Point q, Point m, double tx, double ty, bool is_pressure,
                          const LineMeasure &measure, double fe[6]);

}  // namespace mc
