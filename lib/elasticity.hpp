// Element integrals of linear elasticity on the 2D mesh: the paper's a(u, v) = integral of
// A eps(u) : eps(v) (section 2) and the load integrals of L(v), cell by cell, each carrying the
// model's measure (line_measure.hpp): the thickness t of a plane model, or 2 pi r of an
// axisymmetric one.
// Voigt order: xx, yy, engineering xy; an axisymmetric model (x = r, y = z) adds the hoop
// strain eps_theta_theta = u_r / r as a fourth component.
#pragma once
#include "line_measure.hpp"
#include "mesh.hpp"

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

// Stiffness of a P1 triangle: the integral of B^T D B w. Plane: B constant, one point, exact.
// Axisymmetric: the hoop row N_a / r varies, three interior points (degree 2). ke: 6x6 row-major.
void triangle_stiffness(const Point p[3], const PlaneLaw &law, const LineMeasure &measure, double ke[36]);
// Stiffness of a Q1 quadrilateral by 2x2 Gauss; with bbar, the dilatation is replaced by its
// cell average (Hughes' B-bar), which removes volumetric locking. ke: 8x8 row-major.
void quadrilateral_stiffness(const Point p[4], const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                             double ke[64]);

// Stress of a cell with nodal displacements ue (2 per node), averaged over the cell with the
// measure's weight (exact for plane P1): (xx, yy, xy, zz), the fourth the out-of-plane normal
// stress: sigma_zz of a plane model, the hoop stress sigma_theta_theta of an axisymmetric one.
void triangle_stress(const Point p[3], const PlaneLaw &law, const LineMeasure &measure, const double ue[6],
                     double sigma[4]);
void quadrilateral_stress(const Point p[4], const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                          const double ue[8], double sigma[4]);

// Consistent nodal forces of a uniform body force b (per unit volume): integral of N_a b w.
void triangle_body_force(const Point p[3], double bx, double by, const LineMeasure &measure, double fe[6]);
void quadrilateral_body_force(const Point p[4], double bx, double by, const LineMeasure &measure, double fe[8]);
// Consistent nodal forces of a uniform traction on a straight edge p->q (per unit area of the
// true surface): integral of N_a t w, half of the resultant to each end in a plane model.
void edge_traction_force(Point p, Point q, double tx, double ty, const LineMeasure &measure, double fe[4]);

}  // namespace mc
