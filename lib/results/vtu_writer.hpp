// ParaView output of a solved model (mc_write_vtu): VTK XML UnstructuredGrid files, ASCII,
// numbers written locale-independently with 17 significant digits so that they read back
// bit-exact. A path ending in ".pvd" gets a collection plus one .vtu per body
// ("<stem>_body1.vtu", "<stem>_body2.vtu" next to it); any other path one .vtu with both bodies.
//
// Arrays. Points: x y 0. Point data: "displacement" (ux uy 0: ParaView wants 3-vectors for
// Warp By Vector); "nodal_stress" (the components of "stress" at each node, Model::nodal_stresses,
// as mc_get_nodal_stress); the contact fields, nonzero only at body 1's contact-surface nodes:
// "pressure", "gap", "initial_gap" (Float64), "active" (force > 0) and "contact" (Int32: 1 at
// the nodes that carry a constraint, i.e. see body 2). A contact-surface node that sees no
// mortar surface has contact = 0, and gap = initial_gap = -1 (the API reports +infinity there;
// VTK readers choke on inf). Cell data: "stress" (xx yy xy zz), "von_mises" (with sigma_zz, so
// plane strain is right), "body" (1 or 2). Cells: VTK_TRIANGLE (5), VTK_QUAD (9),
// VTK_QUADRATIC_TRIANGLE (22, T6), VTK_QUADRATIC_QUAD (23, Q8) or VTK_BIQUADRATIC_QUAD (28, Q9),
// in the mesh's node order, which is VTK's.
#pragma once
#include <string>

namespace mc {

class Model;

// Throws mc::Error: MC_ERROR_STATE before a successful solve, MC_ERROR_ARGUMENT naming the
// path if a file cannot be opened or written (a partly written file is removed).
void write_vtu(const Model &model, const std::string &path);

}  // namespace mc
