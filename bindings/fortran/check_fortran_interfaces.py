#!/usr/bin/env python3
"""Static check of bindings/fortran/mortarcontact.f90 against include/mortarcontact.h.

gfortran cannot check a bind(C) interface against a C prototype, so this does: every mc_
function of the header must have exactly one interface `... bind(C, name="mc_name")` whose
dummy arguments match the C parameters position by position, and a public Fortran wrapper of
the same name; the module's MC_ constants must equal the header's. C -> Fortran:
    mc_model * (any const)   type(c_ptr), value        mc_model **  type(c_ptr), not value
    int, mc_status           integer(c_int), value     mc_int       integer(c_int32_t), value
    double                   real(c_double), value     int64_t      integer(c_int64_t), value
    T * (any const)          the same type, not value  (array or scalar by reference)
    void *                   type(c_ptr), value        mc_log_fn    type(c_funptr), value
    const char *             character(kind=c_char) (or character(c_char)), not value
    returns: mc_status/int -> integer(c_int) function, const char * -> type(c_ptr) function,
             void -> subroutine
Also: the module's conveniences without a C function of their own (CONVENIENCES below) exist as
public module functions.
usage: check_fortran_interfaces.py HEADER MODULE_F90
"""
import re
import sys

BASE = {"mc_model": "type(c_ptr)", "int": "integer(c_int)", "mc_status": "integer(c_int)",
        "mc_int": "integer(c_int32_t)", "double": "real(c_double)", "int64_t": "integer(c_int64_t)",
        "char": "character(c_char)", "mc_log_fn": "type(c_funptr)"}
# Module functions beyond the one-to-one wrappers, and the C function each one calls.
CONVENIENCES = {"mc_add_element_matrices_sg": "mc_add_element_matrices"}  # Smith and Griffiths' g_g, storkm
RET = {"mc_status": "integer(c_int)", "int": "integer(c_int)", "const char *": "type(c_ptr)", "void": None}


def header_functions(path):
    text = re.sub(r"/\*.*?\*/", " ", open(path).read(), flags=re.S)
    out = {}
    for m in re.finditer(r"MC_API\s+([^;]*?)\b(mc_\w+)\s*\(([^)]*)\)\s*;", text, flags=re.S):
        ret, name, args = " ".join(m.group(1).split()), m.group(2), m.group(3).strip()
        params = []
        if args and args != "void":
            for a in args.split(","):
                t = re.match(r"(.*?)\w+$", " ".join(a.split())).group(1)
                params.append(t.replace("const", "").replace(" ", ""))
        out[name] = (ret, params)
    consts = {k: int(v) for k, v in re.findall(r"\b(MC_[A-Z0-9_]+)\s*=\s*(-?\d+)", text)}
    for k, v in re.findall(r"#define\s+(MC_VERSION_(?:MAJOR|MINOR|PATCH))\s+(\d+)", text):
        consts[k] = int(v)
    return out, consts


def expected_arg(ctype):
    stars = ctype.count("*")
    if ctype == "void*":
        return ("type(c_ptr)", True)  # an opaque pointer passed as is
    base = BASE[ctype.replace("*", "")]
    if ctype.startswith("mc_model"):
        return (base, stars == 1)  # the handle by value; mc_model** by reference
    return (base, stars == 0)


def fortran_interfaces(path):
    text = open(path).read().lower()
    text = re.sub(r"!.*", "", text)
    text = re.sub(r"&\s*\n\s*", " ", text)  # join continuation lines
    found = {}
    pat = re.compile(r"^\s*(?:(\S+\(\w+\))\s+)?(function|subroutine)\s+(\w+)\s*\(([^)]*)\)\s*bind\(c,\s*name=\"(\w+)\"\)"
                     r"(.*?)^\s*end\s+(?:function|subroutine)", re.M | re.S)
    for m in pat.finditer(text):
        ret, kind, cname, args, name, body = m.groups()
        decl = {}
        for line in body.splitlines():
            d = re.match(r"\s*(type\(c_\w+\)|integer\(\w+\)|real\(\w+\)|character\((?:kind=)?\w+\))\s*(,[^:]*)?::\s*(.*)",
                         line)
            if not d:
                continue
            ftype = d.group(1).replace("kind=", "")
            attrs = d.group(2) or ""
            for var in re.findall(r"(\w+)(?:\([^)]*\))?", d.group(3)):
                decl[var] = (ftype, "value" in attrs)
        arglist = [a.strip() for a in args.split(",") if a.strip()]
        found.setdefault(name, []).append((kind, ret, [(a, decl.get(a)) for a in arglist]))
    return found, text


def main():
    funcs, hconsts = header_functions(sys.argv[1])
    ifaces, text = fortran_interfaces(sys.argv[2])
    public = set()
    for m in re.finditer(r"^\s*public\s*::\s*(.*)$", text, flags=re.M):
        public.update(x.strip() for x in m.group(1).split(","))
    errors = []
    if len(funcs) < 30:
        errors.append("parsed only %d functions from the header" % len(funcs))
    for name, (ret, params) in sorted(funcs.items()):
        if name not in ifaces:
            errors.append("%s: no bind(C) interface" % name)
            continue
        if len(ifaces[name]) != 1:
            errors.append("%s: %d interfaces" % (name, len(ifaces[name])))
        kind, fret, args = ifaces[name][0]
        want_ret = RET[ret]
        if (want_ret is None) != (kind == "subroutine") or (want_ret and fret != want_ret):
            errors.append("%s: C returns %s, Fortran %s %s" % (name, ret, fret or "", kind))
        if len(args) != len(params):
            errors.append("%s: %d dummy arguments, C has %d" % (name, len(args), len(params)))
        for i, ((arg, got), ctype) in enumerate(zip(args, params)):
            want = expected_arg(ctype)
            if got != want:
                errors.append("%s: argument %d (%s) is %s, C type %s wants %s" % (name, i + 1, arg, got, ctype, want))
        if name not in public:
            errors.append("%s: no public Fortran wrapper" % name)
    for name, c_name in sorted(CONVENIENCES.items()):
        body = re.search(r"^\s*integer\s+function\s+%s\s*\((.*?)^\s*end\s+function" % name, text, flags=re.M | re.S)
        if not body:
            errors.append("%s: no module function (a convenience over %s)" % (name, c_name))
        elif "c_" + c_name + "(" not in body.group(1).replace(" ", ""):
            errors.append("%s: does not call %s" % (name, c_name))
        if name not in public:
            errors.append("%s: not public" % name)
    for name in sorted(set(ifaces) - set(funcs) - {"strlen"}):
        errors.append("%s: interface to a function the header does not declare" % name)
    fconsts = {k.upper(): int(v) for k, v in re.findall(r"\b(mc_[a-z0-9_]+)\s*=\s*(-?\d+)\s*[,\n]", text)}
    for k in sorted(set(hconsts) | set(fconsts)):
        if hconsts.get(k) != fconsts.get(k):
            errors.append("constant %s: header %s, Fortran %s" % (k, hconsts.get(k), fconsts.get(k)))
    if errors:
        print("mortarcontact.f90 does not match mortarcontact.h:")
        for e in errors:
            print("  " + e)
        return 1
    print("mortarcontact.f90: %d bind(C) interfaces with public wrappers and %d constants match the header"
          % (len(funcs), len(hconsts)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
