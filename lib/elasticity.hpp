// Element integrals of plane linear elasticity: the paper's a(u, v) = integral of A eps(u) : eps(v)
// (section 2) and the load integrals of L(v), cell by cell. Voigt order: xx, yy, engineering xy.
#pragma once
#include "mesh.hpp"

namespace mc {

// The 3x3 in-plane law sigma = D eps (row-major), and what gives sigma_zz from it.
struct PlaneLaw {
  double d[9];
  double zz_factor;  // sigma_zz = zz_factor * (sigma_xx + sigma_yy): nu in plane strain, else 0
};

PlaneLaw isotropic_plane_law(double young, double poisson, bool plane_stress);
PlaneLaw general_plane_law(const double d[9]);

// Stiffness of a P1 triangle: thickness * area * B^T D B, B constant (exact). ke: 6x6 row-major.
void triangle_stiffness(const Point p[3], const PlaneLaw &law, double thickness, double ke[36]);
// Stiffness of a Q1 quadrilateral by 2x2 Gauss; with bbar, the dilatation is replaced by its
// cell average (Hughes' B-bar), which removes volumetric locking. ke: 8x8 row-major.
void quadrilateral_stiffness(const Point p[4], const PlaneLaw &law, double thickness, bool bbar,
                             double ke[64]);

// Cell-averaged stress (xx, yy, xy, zz) of a cell with nodal displacements ue (2 per node).
void triangle_stress(const Point p[3], const PlaneLaw &law, const double ue[6], double sigma[4]);
void quadrilateral_stress(const Point p[4], const PlaneLaw &law, bool bbar, const double ue[8],
                          double sigma[4]);

// Consistent nodal forces of a uniform body force b (per unit area) times thickness.
void triangle_body_force(const Point p[3], double bx, double by, double thickness, double fe[6]);
void quadrilateral_body_force(const Point p[4], double bx, double by, double thickness, double fe[8]);
// Consistent nodal forces of a uniform traction on a straight edge p->q (per unit length) times
// thickness: half of the resultant to each end.
void edge_traction_force(Point p, Point q, double tx, double ty, double thickness, double fe[4]);

}  // namespace mc
