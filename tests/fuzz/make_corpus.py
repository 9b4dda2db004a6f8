#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz target tests/fuzz/fuzz_api.c into tests/fuzz/corpus/.

Each seed is a little program of API calls in the byte encoding fuzz_api.c reads (see its
header comment and the OP_ enum, whose order OPS below repeats). Several seeds produce a
successful solve, with and without contact, so that fuzzing starts from inputs that reach the
solver; the others start from bad input and calls out of order.

Usage: python3 tests/fuzz/make_corpus.py   (rewrites the corpus; commit the result)
"""
import os
import struct

OPS = ["NEW_MODEL", "INDEX_BASE", "PLANE", "GRID_MESH", "RAW_MESH", "MATERIAL", "CELL_LAW",
       "FIX_SIDE", "FIX_RAW", "TRACTION_SIDE", "PRESSURE_SIDE", "EDGE_LOAD_RAW", "NODAL_FORCE",
       "BODY_FORCE", "CLEAR_LOADS", "CONTACT_SIDE", "CONTACT_RAW", "OPTION_INT", "OPTION_REAL",
       "SOLVE", "QUERY", "GAP_OFFSET", "LOG", "WRITE_VTU", "NULLS",
       "HOST_BODY", "HOST_STIFFNESS", "STIFFNESS_RAW", "ELEMENTS_RAW", "LOAD_VECTOR", "CONTACT_CURVED",
       "BODY_COUNT", "ADD_PAIR", "PAIR_SURFACE", "PAIR_GAP_OFFSET",
       "FRICTION", "RESET_HISTORY"]
OP = {name: k for k, name in enumerate(OPS)}
BOTTOM, RIGHT, TOP, LEFT = 0, 1, 2, 3
SPECIAL = {"nan": 10, "inf": 11, "-inf": 12}


def op(name):
    return bytes([OP[name]])


def u8(v):
    return bytes([v & 0xFF])


def real(v):
    """A double: one byte when v is a multiple of 1/8 in [-14, 13.875], else 9 bytes."""
    if isinstance(v, str):
        return bytes([SPECIAL[v]])
    b = v * 8 + 128
    if 16 <= b < 240 and b == int(b):
        return bytes([int(b)])
    return bytes([240]) + struct.pack("<d", v)


def ident(v):
    """A node id (before the harness adds the index base): -4..235 in one byte, else 5 bytes."""
    if -4 <= v < 236:
        return bytes([v + 4])
    return bytes([246]) + struct.pack("<i", v)


def body(b):
    """A body of the older opcodes: 1, 2 as before; 0, 3, -1 (250..252) as before; 4, 5, 6 (253..255)."""
    return {1: b"\x00", 2: b"\x01", 0: b"\xfa", 3: b"\xfb", -1: b"\xfc", 4: b"\xfd", 5: b"\xfe", 6: b"\xff"}[b]


BAD = [0, -1, 6, 2**31 - 1, -2**31, 1000]  # fuzz_api.c's bad_numbers, bytes 240 ..


def any_body(b):
    """A body of the assembly opcodes (OP_ADD_PAIR, OP_PAIR_SURFACE): 1..5, or a bad one."""
    return bytes([b - 1]) if 1 <= b <= 5 else bytes([240 + BAD.index(b)])


def pair(p):
    """A pair number: 1..3, or a bad one (0, -1, 4, ...)."""
    return bytes([p - 1]) if 1 <= p <= 3 else bytes([242 if p == 4 else 240 + BAD.index(p)])


NONE, TRESCA, COULOMB = 0, 1, 2  # MC_FRICTION_*
LOAD_STEPS, FRICTION_CT, INTERFACE_SOLVER, METHOD = 14, 15, 11, 1  # MC_OPTION_*


def friction(p, law, value):
    """mc_set_friction: a law -1..3 in one byte (b % 5 - 1), or a bad number of BAD (bytes 240..)."""
    return op("FRICTION") + pair(p) + (bytes([law + 1]) if -1 <= law <= 3 else bytes([240 + BAD.index(law)])) + real(value)


def body_count(n):
    return op("BODY_COUNT") + u8(n)


def add_pair(nonmortar, mortar):
    return op("ADD_PAIR") + any_body(nonmortar) + any_body(mortar)


# mode 0 straight, 1 curved with the side's middles, 2 curved with an end and the middle
# swapped, 3 straight from extra (count n, 2n ids)
def pair_surface(p, b, side, first=0, n=0, mode=0, extra=b""):
    return op("PAIR_SURFACE") + pair(p) + any_body(b) + u8(side) + u8(first) + u8(n) + u8(mode) + extra


def pair_gap_offset(p, nodes, offsets):
    return (op("PAIR_GAP_OFFSET") + pair(p) + count(len(nodes)) + b"".join(ident(v) for v in nodes)
            + b"".join(real(v) for v in offsets))


def count(n):
    return b"\xff" if n < 0 else bytes([n])


def grid(b, npc, nx, ny, x0, y0, lx, ly, distortion=0, bow=0.0, corrupt=b"\x00"):
    # the kind byte: b % 7 picks npc from (3, 4, 4, 6, 4, 8, 9), so npc - 3 gives npc
    return (op("GRID_MESH") + body(b) + u8(npc - 3) + u8(nx - 1) + u8(ny - 1) + real(x0) + real(y0)
            + real(lx) + real(ly) + u8(distortion) + real(bow) + corrupt)


def material(b, young, poisson):
    return op("MATERIAL") + body(b) + real(young) + real(poisson)


def fix_side(b, side, mask, values=None):
    out = op("FIX_SIDE") + body(b) + u8(side) + u8(mask)
    return out + (u8(1) + real(values[0]) + real(values[1]) if values else u8(0))


def fix_raw(b, nodes, mask, values=None):
    out = op("FIX_RAW") + body(b) + count(len(nodes)) + b"".join(ident(n) for n in nodes) + u8(mask)
    return out + (u8(1) + b"".join(real(v) for v in values) if values else u8(0))


def traction_side(b, side, tx, ty):
    return op("TRACTION_SIDE") + body(b) + u8(side) + real(tx) + real(ty)


def pressure_side(b, side, p):
    return op("PRESSURE_SIDE") + body(b) + u8(side) + real(p)


def contact_side(b, side, first=0, n=0):
    return op("CONTACT_SIDE") + body(b) + u8(side) + u8(first) + u8(n)


def option_int(option, value):
    if -1 <= value <= 4:
        return op("OPTION_INT") + u8(option) + u8(value + 1)
    return op("OPTION_INT") + u8(option) + u8(200) + struct.pack("<q", value)


def option_real(option, value):
    return op("OPTION_REAL") + u8(option) + real(value)


def solve():
    return op("SOLVE")


# Host bodies: a lattice of order 1 or 2 (its sides as for grids); restrain 0 none (floating),
# 1 the bottom clamped, 2 rollers (left x, bottom y), 3 bottom y, 4 every x, 5 x of the first
# node (the bottom-left corner: a body contact holds in y); shuffle 0 keeps the
# node-by-node numbering; corrupt 0 none (1..7: see op_host_body).
FULL, TRIANGLE, ELEMENTS = 0, 1, 2


def host_body(b, order, nx, ny, x0, y0, lx, ly, restrain, shuffle=0, corrupt=b"\x00"):
    return (op("HOST_BODY") + body(b) + u8(order - 1) + u8(nx - 1) + u8(ny - 1) + real(x0) + real(y0)
            + real(lx) + real(ly) + u8(restrain) + u8(shuffle) + corrupt)


def host_stiffness(b, mode, young, poisson, corrupt=0, at=0, extra=b""):
    return op("HOST_STIFFNESS") + body(b) + u8(mode) + real(young) + real(poisson) + u8(corrupt) + u8(at) + extra


def load_vector(b, fx, fy, kind=0, extra=b""):
    return op("LOAD_VECTOR") + body(b) + u8(kind) + real(fx) + real(fy) + extra


def contact_curved(b, side, first=0, n=0, mode=0, extra=b""):
    return op("CONTACT_CURVED") + body(b) + u8(side) + u8(first) + u8(n) + u8(mode) + extra


# Two stacked blocks (as in tests/test_errors.c): body 1 = [0,1]x[0,0.5] P1 6x3 on body 2 =
# [0,1]x[-0.5,0] Q1 8x4 clamped at its bottom; body 1 held by contact and u_x = 0 at one node.
def stack(base_mid=24):  # node (3, 3) of the 6x3 grid: top middle
    return (grid(1, 3, 6, 3, 0, 0, 1, 0.5) + grid(2, 4, 8, 4, 0, -0.5, 1, 0.5)
            + material(1, 100.0, 0.3) + material(2, 200.0, 0.3) + fix_side(2, BOTTOM, 3)
            + fix_raw(1, [base_mid], 1) + traction_side(1, TOP, 0, -1)
            + contact_side(1, BOTTOM) + contact_side(2, TOP))


# Three stacked blocks (as in tests/test_contact_pairs.c): body 1 = [0,1]x[0,0.5] P1 6x3 on
# body 2 = [0,1]x[-0.5,0] Q1 8x4 on body 3 = [0,1]x[-1,-0.5] P1 5x2 clamped at its bottom;
# bodies 1 and 2 held in y by contact alone (u_x = 0 at one node each); pair 1: 1 on 2,
# pair 2: 2 on 3.
def stack3():
    return (body_count(3) + grid(1, 3, 6, 3, 0, 0, 1, 0.5) + grid(2, 4, 8, 4, 0, -0.5, 1, 0.5)
            + grid(3, 3, 5, 2, 0, -1, 1, 0.5) + material(1, 100.0, 0.3) + material(2, 200.0, 0.3)
            + material(3, 150.0, 0.25) + fix_side(3, BOTTOM, 3) + fix_raw(1, [24], 1) + fix_raw(2, [0], 1)
            + traction_side(1, TOP, 0, -1)
            + add_pair(1, 2) + pair_surface(1, 1, BOTTOM) + pair_surface(1, 2, TOP)
            + add_pair(2, 3) + pair_surface(2, 2, BOTTOM) + pair_surface(2, 3, TOP))


SEEDS = {
    "solve_cantilever": grid(1, 3, 6, 3, 0, 0, 2, 1, distortion=8) + material(1, 100.0, 0.3)
    + fix_side(1, LEFT, 3) + traction_side(1, RIGHT, 0.25, -1) + op("BODY_FORCE") + body(1) + real(0) + real(-0.5)
    + solve() + op("CLEAR_LOADS") + body(1) + pressure_side(1, TOP, 0.5) + solve(),
    "solve_two_bodies_q1_plane_stress": op("PLANE") + u8(1) + real(0.5) + grid(1, 4, 4, 2, 0, 0, 2, 1)
    + grid(2, 4, 3, 3, 5, 0, 1, 1) + material(1, 10.0, 0.25) + material(2, 20.0, 0.125)
    + fix_side(1, LEFT, 3) + fix_side(2, BOTTOM, 3, (0.0, -0.125)) + option_int(6, 1) + solve(),
    "contact_stack": stack() + solve() + traction_side(1, TOP, 0.5, -2) + solve() + op("QUERY"),
    "contact_methods": stack() + option_int(1, 1) + solve() + option_int(1, 2) + solve()
    + option_int(7, 1) + option_int(1, 0) + solve(),
    "contact_curved": grid(1, 3, 8, 3, -1, 0, 2, 1, bow=0.25) + grid(2, 4, 8, 2, -1.5, -1, 3, 1)
    + material(1, 100.0, 0.3) + material(2, 100.0, 0.3) + fix_side(1, TOP, 3, (0.0, -0.125))
    + fix_side(2, BOTTOM, 3) + contact_side(1, BOTTOM) + contact_side(2, TOP) + solve()
    + option_real(2, 1e-12) + option_int(3, 1) + solve() + option_int(3, 200) + solve(),
    "index_base_one": op("INDEX_BASE") + u8(2) + stack() + solve() + op("QUERY")
    + fix_raw(1, [0], 3) + fix_raw(1, [1000], 3) + solve(),
    "bad_mesh_then_good": op("RAW_MESH") + body(1) + count(4) + b"".join(real(v) for v in (0, 0, 1, 0, 1, 1, 0, 1))
    + count(2) + u8(1) + b"".join(ident(v) for v in (0, 2, 1, 0, 2, 3)) + u8(0)
    + op("RAW_MESH") + body(1) + count(4) + b"".join(real(v) for v in (0, 0, 1, 0, 1, 1, 0, 1))
    + count(1) + u8(2) + b"".join(ident(v) for v in (0, 1, 2, 7)) + u8(0)
    + grid(1, 3, 2, 2, 0, 0, 1, 1, corrupt=u8(2) + u8(5) + ident(-1))
    + grid(1, 3, 2, 2, 0, 0, 1, 1, corrupt=u8(1) + u8(3) + real("nan"))
    + grid(1, 4, 2, 2, 0, 0, 1, 1, corrupt=u8(3) + u8(0) + u8(0) + u8(1))
    + grid(1, 3, 2, 2, 0, 0, 1, 1) + material(1, 1.0, 0.3) + fix_side(1, BOTTOM, 3) + solve(),
    "out_of_order": op("QUERY") + solve() + material(1, 1.0, 0.3) + contact_side(1, BOTTOM)
    + grid(1, 3, 3, 2, 0, 0, 1, 1) + solve() + material(1, 0.0, 0.3) + material(1, 1.0, 0.5)
    + material(3, 1.0, 0.3) + material(1, 1.0, 0.3) + op("QUERY") + contact_side(1, BOTTOM) + solve()
    + op("NULLS") + fix_side(1, BOTTOM, 3) + grid(2, 3, 3, 2, 0, 0, 1, 1) + material(2, 1.0, 0.3)
    + contact_side(2, BOTTOM) + solve() + op("QUERY"),
    "singular_and_options": grid(1, 4, 3, 3, 0, 0, 1, 1) + material(1, 1.0, 0.3) + solve()
    + fix_side(1, LEFT, 1) + solve() + fix_side(1, BOTTOM, 2) + option_int(4, 1) + solve()
    + option_int(4, 2) + option_int(0, 1) + option_int(1, 7) + option_real(2, 0.0) + option_real(2, "nan")
    + option_real(1, 0.5) + option_int(3, 1 << 40) + solve(),
    "cell_law": grid(1, 3, 3, 2, 0, 0, 1, 1) + op("CELL_LAW") + body(1) + real(10.0) + real(0.25)
    + u8(0) + u8(9) + real(0) + u8(0) + fix_side(1, LEFT, 3) + traction_side(1, RIGHT, 1, 0) + solve()
    + op("CELL_LAW") + body(1) + real(10.0) + real(0.25) + u8(2) + u8(2) + real(3.0) + u8(0),
    "new_features": stack() + op("LOG") + u8(1) + solve() + op("GAP_OFFSET") + count(2) + ident(1) + ident(2)
    + real(0.125) + real(-0.125) + solve() + op("WRITE_VTU") + u8(0) + op("WRITE_VTU") + u8(1)
    + op("LOG") + u8(0) + op("NEW_MODEL") + op("WRITE_VTU") + u8(0),
    "edge_loads_raw": grid(1, 3, 2, 2, 0, 0, 1, 1) + material(1, 1.0, 0.3) + fix_side(1, LEFT, 3)
    + op("EDGE_LOAD_RAW") + body(1) + u8(0) + count(2) + b"".join(ident(v) for v in (2, 5, 4, 5))
    + b"".join(real(v) for v in (1, 0, 0, 1)) + u8(0)
    + op("EDGE_LOAD_RAW") + body(1) + u8(1) + count(1) + ident(2) + ident(5) + real(1) + u8(0)
    + op("NODAL_FORCE") + body(1) + count(2) + ident(8) + ident(9) + b"".join(real(v) for v in (1, 0, 0, 1))
    + op("CONTACT_RAW") + body(1) + count(2) + b"".join(ident(v) for v in (0, 1, 1, 0))
    + solve(),
    # regressions: a bow-tie body 1 whose contact surface passes twice through a node (used to
    # hang mc_solve), a fully supported body (used to give MC_ERROR_INTERNAL), overflow
    "pinched_contact": op("RAW_MESH") + body(1) + count(5)
    + b"".join(real(v) for v in (0, 0, 1, -1, 1, 1, -1, 1, -1, -1)) + count(2) + u8(1)
    + b"".join(ident(v) for v in (0, 1, 2, 0, 3, 4)) + u8(0)
    + grid(2, 4, 1, 1, -2, -3, 4, 1) + material(1, 1.0, 0.3) + material(2, 1.0, 0.3)
    + fix_side(2, BOTTOM, 3) + fix_side(2, TOP, 3) + contact_side(2, TOP)
    + op("CONTACT_RAW") + body(1) + count(4) + b"".join(ident(v) for v in (4, 0, 0, 1, 1, 2, 2, 0)) + solve()
    + op("CONTACT_RAW") + body(1) + count(2) + b"".join(ident(v) for v in (3, 4, 4, 0))
    + fix_raw(1, [0, 1, 3], 3) + op("BODY_FORCE") + body(1) + real(0) + real(-1) + solve(),
    # MC_OPTION_INTERFACE_SOLVER (11): each path forced on a contact solve and a re-solve with new
    # loads, automatic, the bad values 3 and -1, and the real-valued call
    "interface_solver": stack() + option_int(11, 2) + solve() + traction_side(1, TOP, 0.5, -2) + solve()
    + option_int(11, 1) + solve() + option_int(11, 3) + option_int(11, -1) + option_real(11, 1.0)
    + option_int(11, 0) + solve() + op("QUERY"),
    # MC_OPTION_ERROR_ESTIMATE (12): on (the default) for a contact solve, off (the indicators are
    # refused), the bad values 2 and -1 and the real-valued call, on again; NULL outputs
    "error_estimate": stack() + solve() + option_int(12, 0) + solve() + option_int(12, 2)
    + option_int(12, -1) + option_real(12, 1.0) + op("QUERY") + option_int(12, 1)
    + traction_side(1, TOP, 0.5, -2) + solve() + op("NULLS"),
    # MC_OPTION_MULTIPLIER (13): a T6 body 1 pressed on Q8 with quadratic multipliers, then linear
    # (the default) with the sparse interface solver; the bad values 2 and -1 and the real-valued call
    "multiplier": grid(1, 6, 4, 2, 0, 0, 1, 0.5) + grid(2, 8, 5, 2, 0, -0.5, 1, 0.5)
    + material(1, 100.0, 0.3) + material(2, 200.0, 0.3) + fix_side(2, BOTTOM, 3) + fix_side(1, LEFT, 1)
    + fix_side(2, LEFT, 1) + pressure_side(1, TOP, 1.0) + contact_side(1, BOTTOM) + contact_side(2, TOP)
    + option_int(13, 1) + solve() + op("QUERY") + option_int(13, 0) + option_int(11, 2) + solve()
    + option_int(13, 2) + option_int(13, -1) + option_real(13, 1.0) + option_int(13, 1) + solve(),
    # quadratic cells (issue 21): T6 pressed on Q8, then Q9 on P1 with a curved (bowed) body 1,
    # dual mortar (the quadratic dual basis), node-to-segment, both interface solvers, and a
    # corrupted Q9 grid (a swapped mid-edge node folds its cell)
    "quadratic_contact": grid(1, 6, 4, 2, 0, 0, 1, 0.5) + grid(2, 8, 5, 2, 0, -0.5, 1, 0.5)
    + material(1, 100.0, 0.3) + material(2, 200.0, 0.3) + fix_side(2, BOTTOM, 3) + fix_side(1, LEFT, 1)
    + fix_side(2, LEFT, 1) + pressure_side(1, TOP, 1.0) + contact_side(1, BOTTOM) + contact_side(2, TOP) + solve()
    + option_int(1, 1) + solve() + option_int(1, 2) + solve() + option_int(1, 0) + option_int(11, 2) + solve()
    + op("QUERY") + op("WRITE_VTU") + u8(0)
    + grid(1, 9, 4, 2, -0.5, 0, 1, 0.5, bow=0.125) + grid(2, 3, 6, 2, -1, -0.5, 2, 0.5)
    + material(1, 1.0, 0.3) + material(2, 1.0, 0.3) + fix_side(2, BOTTOM, 3)
    + fix_side(1, TOP, 3, (0.0, -0.0625)) + contact_side(1, BOTTOM) + contact_side(2, TOP) + solve()
    + grid(1, 9, 2, 2, 0, 0, 1, 1, corrupt=u8(3) + u8(0) + u8(4) + u8(0)),
    # host bodies (issue 22): body 1 a host lattice held in x, floating in y, on a Q1 mesh body 2;
    # its stiffness as coordinates (full, one triangle) and element matrices, base 0 and 1, a
    # shuffled numbering, a load vector re-solved; two host bodies. Then quadratic edges on a host
    # lattice of order 2 and on a Q8 mesh; raw entries and elements, and bad input of each call
    "host_bodies": host_body(1, 1, 6, 3, 0, 0, 1, 0.5, 5) + host_stiffness(1, FULL, 100.0, 0.3)
    + load_vector(1, 0, -1) + grid(2, 4, 8, 4, 0, -0.5, 1, 0.5) + material(2, 200.0, 0.3)
    + fix_side(2, BOTTOM, 3) + contact_side(1, BOTTOM) + contact_side(2, TOP) + solve()
    + load_vector(1, 0, -2) + solve() + option_int(11, 2) + solve() + op("QUERY")
    + op("INDEX_BASE") + u8(2) + host_body(1, 1, 6, 3, 0, 0, 1, 0.5, 5, shuffle=7)
    + host_stiffness(1, TRIANGLE, 100.0, 0.3) + load_vector(1, 0, -1) + contact_side(1, BOTTOM) + solve()
    + host_body(1, 1, 6, 3, 0, 0, 1, 0.5, 5, shuffle=9) + host_stiffness(1, ELEMENTS, 100.0, 0.3)
    + load_vector(1, 0, -1) + contact_side(1, BOTTOM) + option_int(1, 1) + solve()
    + host_body(2, 1, 8, 4, 0, -0.5, 1, 0.5, 1) + host_stiffness(2, ELEMENTS, 200.0, 0.3)
    + contact_side(2, TOP) + solve() + op("QUERY"),
    "host_curved_and_bad_input": grid(2, 4, 8, 4, 0, -0.5, 1, 0.5) + material(2, 200.0, 0.3)
    + fix_side(2, BOTTOM, 3) + contact_side(2, TOP)
    + host_body(1, 2, 4, 2, 0, 0, 1, 0.5, 5) + host_stiffness(1, FULL, 100.0, 0.3) + load_vector(1, 0, -1)
    + contact_curved(1, BOTTOM) + solve() + option_int(11, 2) + solve()
    + grid(1, 8, 4, 2, 0, 0, 1, 0.5) + material(1, 100.0, 0.3) + fix_side(1, TOP, 3, (0.0, -0.0625))
    + contact_curved(1, BOTTOM) + solve() + contact_curved(1, BOTTOM, mode=1) + contact_curved(1, LEFT, 0, 1)
    + contact_curved(1, BOTTOM, mode=2, extra=count(1) + ident(1) + ident(3) + ident(2))
    + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1, corrupt=u8(1) + u8(3))
    + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1, corrupt=u8(2) + u8(5) + ident(100))
    + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1, corrupt=u8(3) + ident(2))
    + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1, corrupt=u8(6) + u8(0) + real("nan"))
    + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1, corrupt=u8(7)) + host_stiffness(1, FULL, 1.0, 0.3, 3, 29)
    + host_stiffness(1, FULL, 1.0, 0.3, 1, 2, real("inf")) + host_stiffness(1, ELEMENTS, 1.0, 0.3, 3, 1)
    + host_stiffness(1, TRIANGLE, 1.0, 0.3, 2, 0, ident(1000)) + host_stiffness(1, ELEMENTS, 1.0, 0.3, 4)
    + host_stiffness(1, FULL, 1.0, 0.3) + load_vector(1, 1, 1, kind=3) + load_vector(1, 0, 0, kind=2)
    + load_vector(1, 0, 0, kind=1, extra=count(2) + real(1) + real(2))
    + contact_side(1, BOTTOM) + solve()  # contact nodes without equations (the bottom is clamped)
    + op("NEW_MODEL") + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1) + host_stiffness(1, FULL, 1.0, 0.3, 3, 29)
    + solve()  # an asymmetric MC_MATRIX_FULL sum, found by the solve
    + host_body(1, 1, 2, 2, 0, 0, 1, 1, 1) + host_stiffness(1, FULL, 1.0, 0.3) + load_vector(1, 0.5, 1)
    + solve() + op("QUERY")
    + op("STIFFNESS_RAW") + body(1) + count(2) + ident(0) + ident(1) + ident(1) + ident(0) + real(1) + real(2)
    + u8(1) + u8(0)
    + op("STIFFNESS_RAW") + body(1) + count(1) + ident(0) + ident(0) + real(1) + u8(3) + u8(0)
    + op("ELEMENTS_RAW") + body(1) + count(2) + count(2) + ident(0) + ident(1) + b"".join(real(v) for v in (2, -1, -1, 2))
    + count(1) + ident(-1) + real(1) + u8(0)
    + op("ELEMENTS_RAW") + body(1) + count(2) + count(2) + ident(0) + ident(1) + b"".join(real(v) for v in (2, -1, -1, 2))
    + count(1) + ident(2) + real(1) + u8(1) + u8(0)
    + op("ELEMENTS_RAW") + body(1) + count(2) + count(2) + ident(0) + ident(1) + b"".join(real(v) for v in (2, -1, -1, 2))
    + count(1) + ident(2) + real(1) + u8(2)
    + op("NULLS") + op("QUERY"),
    "fully_supported_and_overflow": grid(2, 4, 1, 1, 0, -1, 2, 1) + material(2, 1.0, 0.3)
    + fix_side(2, BOTTOM, 3) + fix_side(2, TOP, 3) + solve()
    + grid(1, 4, 2, 2, 0, 0, 1, 1) + material(1, 1.0, 0.3) + fix_side(1, TOP, 3, (0.0, -0.125))
    + contact_side(1, BOTTOM) + contact_side(2, TOP) + solve()
    + material(1, 1.7976931348623157e308, 0.3) + solve() + material(1, 1.0, 0.3)
    + op("PLANE") + u8(0) + real(1e300) + solve(),
    # A fuzz finding (docs/robustness.md): body 2's only unknown (its top-left corner's u_y) is on
    # its contact surface, so every unknown of its condensed-path analysis is an interface one;
    # CAMD read past its arrays there. Both paths, then a re-solve.
    "camd_every_unknown_on_interface": grid(1, 3, 1, 1, 0, 0, 1, 1) + grid(2, 3, 1, 1, 0, -1, 1, 1)
    + material(1, 1.0, 0.3) + material(2, 1.0, 0.3) + fix_side(1, LEFT, 1)
    + fix_raw(2, [0, 1, 3], 3) + fix_raw(2, [2], 1) + pressure_side(1, TOP, 0.125)
    + contact_side(1, BOTTOM) + contact_side(2, TOP) + option_int(11, 1) + solve()
    + option_int(11, 2) + solve() + option_int(11, 0) + solve(),
    # assemblies (issue 32): three stacked blocks with two pairs, solved on both paths and both
    # mortar methods, a pair's gap offset, a re-solve with new loads, every pair result queried
    "pairs_stack3": stack3() + solve() + op("QUERY") + option_int(11, 2) + solve() + option_int(1, 1)
    + traction_side(1, TOP, 0.5, -2) + solve() + option_int(1, 0) + option_int(11, 0)
    + pair_gap_offset(2, [0, 1, 2], [0.0078125, 0.0078125, 0.0078125]) + solve() + op("WRITE_VTU") + u8(0),
    # five bodies: a quadratic T6 block on Q8 with curved pair surfaces, a host lattice body 3
    # under it; bodies 4 and 5 without a mesh (refused by the solve), then the count shrunk to 3
    "pairs_quadratic_host": body_count(5) + grid(1, 6, 4, 2, 0, 0, 1, 0.5) + grid(2, 8, 5, 2, 0, -0.5, 1, 0.5)
    + material(1, 100.0, 0.3) + material(2, 200.0, 0.3) + fix_side(1, LEFT, 1) + fix_side(2, LEFT, 1)
    + pressure_side(1, TOP, 1.0) + host_body(3, 1, 6, 2, 0, -1, 1, 0.5, 1) + host_stiffness(3, FULL, 150.0, 0.3)
    + add_pair(1, 2) + pair_surface(1, 1, BOTTOM, mode=1) + pair_surface(1, 2, TOP, mode=1)
    + add_pair(2, 3) + pair_surface(2, 2, BOTTOM, mode=1) + pair_surface(2, 3, TOP) + solve()
    + body_count(3) + solve() + op("QUERY") + option_int(11, 2) + solve(),
    # bad assembly input: body counts 0, 1 and 6 (past the harness's 5); pairs of a body with
    # itself, with bodies that do not exist; surfaces of pairs that do not exist, of a body not
    # in the pair, on a body without a mesh, raw edges that are not boundary edges; a count
    # that would drop a body a pair uses; gap offsets of bad pairs and nodes; the two-body calls
    # on a model whose pair 1 joins other bodies; two pairs whose non-mortar surfaces share a
    # node with different mortar bodies; a pair with one side only
    "pairs_bad_input": body_count(0) + body_count(1) + body_count(3) + grid(1, 4, 3, 2, 0, 0, 1, 1)
    + grid(2, 4, 3, 2, 0, -1, 1, 1) + grid(3, 4, 3, 2, 1, 0, 1, 1) + material(1, 1.0, 0.3) + material(2, 1.0, 0.3)
    + material(3, 1.0, 0.3) + add_pair(1, 1) + add_pair(1, 6) + add_pair(0, 2) + add_pair(-1, 2)
    + add_pair(2**31 - 1, 1) + pair_surface(1, 1, BOTTOM) + pair_surface(0, 1, BOTTOM) + pair_surface(4, 1, BOTTOM)
    + add_pair(2, 1) + pair_surface(1, 3, TOP) + pair_surface(1, 5, TOP) + pair_surface(1, 2, TOP)
    + pair_surface(1, 1, TOP, mode=3, extra=count(2) + b"".join(ident(v) for v in (0, 5, 5, 6)))
    + pair_surface(1, 2, TOP, mode=2) + pair_gap_offset(0, [0], [0.125]) + pair_gap_offset(4, [0], [0.125])
    + pair_gap_offset(1, [1000, -1], [0.125, "nan"]) + pair_gap_offset(1, [0, 1], ["inf", 0.125])
    + op("CONTACT_SIDE") + body(1) + u8(BOTTOM) + u8(0) + u8(0)
    + op("GAP_OFFSET") + count(1) + ident(0) + real(0.125)
    + add_pair(3, 1) + pair_surface(2, 3, LEFT) + pair_surface(2, 1, RIGHT) + body_count(2)
    + add_pair(2, 3) + pair_surface(3, 2, TOP) + pair_surface(3, 3, LEFT, 0, 1)
    + fix_side(2, BOTTOM, 3) + fix_side(3, RIGHT, 3) + fix_side(1, TOP, 3, (0.0, -0.125)) + solve()
    + pair_surface(1, 2, TOP) + pair_surface(1, 1, BOTTOM) + solve() + op("QUERY") + op("NULLS")
    + body_count(5) + solve() + op("NEW_MODEL") + add_pair(1, 2) + solve() + op("QUERY"),
}


# Friction (issue 33): two blocks, body 1 = [0,1]x[0,0.5] P1 4x2 on body 2 = [0,1]x[-0.5,0] Q1
# 5x2 clamped at its bottom; body 1 held along x by friction alone (no support), pressed down and
# sheared (traction (0.125, -1) on its top: below mu = 0.5 times the pressure, so it sticks).
def friction_blocks():
    return (grid(1, 3, 4, 2, 0, 0, 1, 0.5) + grid(2, 4, 5, 2, 0, -0.5, 1, 0.5) + material(1, 1.0, 0.3)
            + material(2, 1.0, 0.3) + fix_side(2, BOTTOM, 3) + traction_side(1, TOP, 0.125, -1)
            + contact_side(1, BOTTOM) + contact_side(2, TOP))


SEEDS.update({
    # Coulomb in 3 load steps, the loads doubled (a step from the converged state), the history
    # forgotten with another complementarity parameter, Tresca; then the sparse path forced (it
    # refused friction until session 14; now it solves it) and the friction removed (nothing
    # holds body 1 along x: singular)
    "friction_stick": friction_blocks() + friction(1, COULOMB, 0.5) + option_int(LOAD_STEPS, 3) + solve()
    + traction_side(1, TOP, 0.125, -1) + solve() + op("RESET_HISTORY") + option_real(FRICTION_CT, 10.0) + solve()
    + friction(1, TRESCA, 0.25) + solve() + option_int(INTERFACE_SOLVER, 2) + solve() + option_int(INTERFACE_SOLVER, 0)
    + friction(1, NONE, 0) + solve() + op("QUERY"),
    # the dual mortar and node-to-segment methods with friction, a slip (the top moved sideways),
    # then every bad input: friction before any contact pair, bad laws, values and pairs, bad
    # load steps and complementarity parameters (and each option through the other type's call)
    "friction_bad_input": op("RESET_HISTORY") + friction(1, COULOMB, 0.3) + friction_blocks()
    + option_int(METHOD, 1) + friction(1, COULOMB, 0.5) + solve() + option_int(METHOD, 2)
    + fix_side(1, TOP, 1, (0.5, 0.0)) + solve() + op("QUERY")
    + friction(1, -1, 0.3) + friction(1, 3, 0.3) + friction(1, 2**31 - 1, 0.3) + friction(1, -2**31, 0.3)
    + friction(1, COULOMB, -0.5) + friction(1, TRESCA, "nan") + friction(1, COULOMB, "inf") + friction(1, TRESCA, 1e300)
    + friction(0, COULOMB, 0.3) + friction(4, COULOMB, 0.3) + friction(-1, TRESCA, 0.3) + friction(1000, NONE, 0)
    + option_int(LOAD_STEPS, 0) + option_int(LOAD_STEPS, -1) + option_int(LOAD_STEPS, 2**40)
    + option_int(LOAD_STEPS, 10**6 + 1) + option_int(FRICTION_CT, 1) + option_real(LOAD_STEPS, 2)
    + option_real(FRICTION_CT, "nan") + option_real(FRICTION_CT, -1) + option_real(FRICTION_CT, "inf")
    + op("NULLS") + solve() + op("RESET_HISTORY") + op("RESET_HISTORY") + solve() + op("WRITE_VTU") + u8(0),
    # assemblies with friction: Tresca on pair 1, Coulomb on pair 2 of the three-block stack, in
    # two load steps, then a reset and the pairs' laws swapped
    # friction on the sparse interface path: Coulomb sticking, then the top moved sideways (every
    # row slips: the nonsymmetric systems, GMRES), Tresca, and the stack's two pairs
    "friction_sparse": friction_blocks() + option_int(INTERFACE_SOLVER, 2) + friction(1, COULOMB, 0.5) + solve()
    + fix_side(1, TOP, 1, (0.5, 0.0)) + solve() + friction(1, TRESCA, 0.25) + solve() + op("QUERY")
    + op("NEW_MODEL") + stack3() + option_int(INTERFACE_SOLVER, 2) + friction(1, COULOMB, 0.3)
    + friction(2, TRESCA, 0.5) + option_int(LOAD_STEPS, 2) + solve() + op("QUERY"),
    "friction_pairs": stack3() + friction(1, TRESCA, 0.5) + friction(2, COULOMB, 0.3) + option_int(LOAD_STEPS, 2)
    + solve() + op("QUERY") + op("RESET_HISTORY") + friction(1, COULOMB, 0.3) + friction(2, TRESCA, 0.5) + solve()
    + friction(3, COULOMB, 0.3) + solve(),
})


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
    print(f"wrote {len(SEEDS)} seeds to {out}")


if __name__ == "__main__":
    main()
