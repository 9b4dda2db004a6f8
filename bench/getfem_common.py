"""The GetFEM model pieces the peer benchmarks share (bench/getfem_hertz.py, bench/getfem_strips.py).

Two P1 elastic bodies in plane strain, and GetFEM's integral Alart-Curnier contact written in its
weak-form language: a P1 multiplier lam (the contact pressure, >= 0) on body 1's contact region,
and the gap at a body-1 surface point X, g = X_y + u1_y(X) - u2_y(X_x, 0), through the
interpolate transformation X -> (X_x, 0) onto body 2's flat top y = 0:
    - int lam (v1_y - v2_y(Pi X)) + int (1/r)(lam - pos_part(lam - r g)) mu = 0.
"""


def elastic_bodies(gf, m1, m2, young, poisson):
    """The model with u1 on m1 and u2 on m2 (P1), each with its plane-strain elasticity brick.
    Returns md, (mfu1, mfu2), (mim1, mim2)."""
    mfu1, mfu2 = gf.MeshFem(m1, 2), gf.MeshFem(m2, 2)
    mfu1.set_classical_fem(1)
    mfu2.set_classical_fem(1)
    mim1, mim2 = gf.MeshIm(m1, gf.Integ("IM_TRIANGLE(2)")), gf.MeshIm(m2, gf.Integ("IM_TRIANGLE(2)"))
    md = gf.Model("real")
    md.add_fem_variable("u1", mfu1)
    md.add_fem_variable("u2", mfu2)
    md.add_initialized_data("E", [young])
    md.add_initialized_data("nu", [poisson])
    md.add_isotropic_linearized_elasticity_pstrain_brick(mim1, "u1", "E", "nu")
    md.add_isotropic_linearized_elasticity_pstrain_brick(mim2, "u2", "E", "nu")
    return md, (mfu1, mfu2), (mim1, mim2)


def add_flat_integral_contact(gf, md, m1, m2, region, r):
    """The integral contact above on m1's `region` against body 2's flat top y = 0, with
    augmentation r. Returns the multiplier's MeshFem and the contact integration method."""
    mfl = gf.MeshFem(m1, 1)
    mfl.set_classical_fem(1)
    md.add_filtered_fem_variable("lam", mfl, region)
    # the contact integrals see kinks (pos_part) and non-matching P1 traces: use a rule
    # well beyond the polynomial degree so that quadrature is not the limiting error
    mimc = gf.MeshIm(m1, gf.Integ("IM_TRIANGLE(13)"))
    md.add_interpolate_transformation_from_expression("Pi", m1, m2, "[X(1);0]")
    md.add_initialized_data("r", [r])
    md.add_macro("gap", "X(2) + u1(2) - Interpolate(u2,Pi)(2)")
    md.add_nonlinear_term(mimc, "-lam*(Test_u1(2) - Interpolate(Test_u2,Pi)(2))", region)
    md.add_nonlinear_term(mimc, "(1/r)*(lam - pos_part(lam - r*gap))*Test_lam", region)
    return mfl, mimc
