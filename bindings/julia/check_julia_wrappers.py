#!/usr/bin/env python3
"""Static check of bindings/julia/src/MortarContact.jl against include/mortarcontact.h.

Julia is not installed where this project is tested, so this test does what it can without it:
every public mc_ function of the header must have exactly one
    ccall((:mc_name, libmortarcontact), RetType, (ArgTypes...,), args...)
in the Julia file, with the same number of arguments and, position by position, a Julia type
that matches the C type:
    mc_int -> Int32, int / mc_status / enum -> Cint, double -> Cdouble, int64_t -> Int64,
    void (return) -> Cvoid, const char * (return) -> Cstring, mc_log_fn -> Ptr{Cvoid},
    T * / const T * -> Ptr{J(T)} or Ref{J(T)}, mc_model * -> Ptr{Cvoid}, mc_model ** -> Ref/Ptr{Ptr{Cvoid}}.
The Julia constants MC_* must equal the header's. Also checked: no ccall names a function the
header lacks. With the package's Project.toml: its name is the module's, its version the
header's, and every package the module loads with `using` is one of its [deps] (what
`Pkg.develop(path=...)` needs). Exits 1 with a list of the mismatches.

usage: check_julia_wrappers.py HEADER JULIA_FILE [PROJECT_TOML]
"""
import re
import sys

SCALAR = {"mc_int": ["Int32"], "int": ["Cint", "Int32"], "mc_status": ["Cint", "Int32"],
          "double": ["Cdouble", "Float64"], "int64_t": ["Int64"], "int32_t": ["Int32"],
          "char": ["Cchar", "UInt8"], "mc_model": ["Cvoid"], "void": ["Cvoid"],
          "mc_log_fn": ["Ptr{Cvoid}"]}  # a function pointer: @cfunction gives a Ptr{Cvoid}


def julia_types(ctype):
    """The Julia spellings accepted for a C type (of an argument or a return value)."""
    t = re.sub(r"\bconst\b", "", ctype).strip()
    stars = t.count("*")
    base = t.replace("*", "").strip()
    if base not in SCALAR:
        raise SystemExit("unknown C type %r: extend SCALAR in %s" % (ctype, sys.argv[0]))
    types = list(SCALAR[base])
    if stars == 0:
        return types
    if base == "char" and stars == 1:
        return ["Cstring", "Ptr{UInt8}", "Ptr{Cchar}"]
    for level in range(stars):
        wrappers = ["Ptr", "Ref"] if level == stars - 1 else ["Ptr"]  # Ref only outermost
        types = ["%s{%s}" % (w, t) for w in wrappers for t in types]
    return types


def strip_c_comments(text):
    return re.sub(r"/\*.*?\*/", " ", text, flags=re.S)


def header_functions(path):
    text = strip_c_comments(open(path).read())
    out = {}
    for m in re.finditer(r"MC_API\s+([^;]*?)\b(mc_\w+)\s*\(([^)]*)\)\s*;", text, flags=re.S):
        ret, name, args = m.group(1).strip(), m.group(2), m.group(3).strip()
        params = []
        if args and args != "void":
            for a in args.split(","):
                a = " ".join(a.split())
                pm = re.match(r"(.*?)(\w+)$", a)  # type, then parameter name
                params.append(pm.group(1).strip())
        out[name] = (ret, params)
    return out


def header_constants(path):
    text = strip_c_comments(open(path).read())
    consts = {k: int(v) for k, v in re.findall(r"\b(MC_[A-Z0-9_]+)\s*=\s*(-?\d+)", text)}
    for k, v in re.findall(r"#define\s+(MC_VERSION_(?:MAJOR|MINOR|PATCH))\s+(\d+)", text):
        consts[k] = int(v)
    return consts


def split_top(s):
    """Splits on commas not nested in (), {} or []."""
    parts, depth, cur = [], 0, ""
    for ch in s:
        if ch in "({[":
            depth += 1
        elif ch in ")}]":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur.strip())
    return parts


def matching_paren(s, i):
    depth = 0
    for j in range(i, len(s)):
        if s[j] == "(":
            depth += 1
        elif s[j] == ")":
            depth -= 1
            if depth == 0:
                return j
    raise ValueError("unbalanced parentheses")


def julia_ccalls(path):
    text = re.sub(r"#.*", "", open(path).read())  # line comments (no '#' inside strings used here)
    calls = {}
    for m in re.finditer(r"\bccall\s*\(", text):
        start = m.end() - 1
        body = text[start + 1:matching_paren(text, start)]
        parts = split_top(body)
        target = re.match(r"\(\s*:(\w+)\s*,\s*libmortarcontact\s*\)$", parts[0])
        if not target:
            raise SystemExit("ccall target %r is not (:mc_name, libmortarcontact)" % parts[0])
        ret = parts[1].replace(" ", "")
        tup = parts[2].strip()
        assert tup.startswith("(") and tup.endswith(")"), tup
        args = [a.replace(" ", "") for a in split_top(tup[1:-1])]
        calls.setdefault(target.group(1), []).append((ret, args, len(parts) - 3))
    return calls


def julia_constants(path):
    text = open(path).read()
    return {k: int(v) for k, v in re.findall(r"^const\s+(MC_[A-Z0-9_]+)\s*=\s*(?:Cint\()?(-?\d+)\)?\s*$",
                                               text, flags=re.M)}


def project_errors(project_toml, julia, header_consts):
    """Mismatches between Project.toml and the module it describes."""
    text = open(project_toml).read()
    fields = dict(re.findall(r'^(\w+)\s*=\s*"([^"]*)"', text, flags=re.M))
    module = re.search(r"^module\s+(\w+)", open(julia).read(), flags=re.M).group(1)
    version = "%d.%d.%d" % tuple(header_consts["MC_VERSION_" + k] for k in ("MAJOR", "MINOR", "PATCH"))
    deps_section = re.search(r"^\[deps\]\n(.*?)(?:^\[|\Z)", text, flags=re.M | re.S)
    deps = set(re.findall(r"^(\w+)\s*=", deps_section.group(1), flags=re.M)) if deps_section else set()
    used = set(re.findall(r"^using\s+(\w+)", strip_julia_docstrings(open(julia).read()), flags=re.M))
    errors = []
    if fields.get("name") != module:
        errors.append("Project.toml: name %r, the module is %r" % (fields.get("name"), module))
    if fields.get("version") != version:
        errors.append("Project.toml: version %r, the header is %s" % (fields.get("version"), version))
    if not re.fullmatch(r"[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}", fields.get("uuid", "")):
        errors.append("Project.toml: no valid uuid")
    errors += ["Project.toml: the module uses %s, which [deps] lacks" % d for d in sorted(used - deps)]
    return errors


def strip_julia_docstrings(text):
    return re.sub(r'"""(.*?)"""', " ", text, flags=re.S)


def main():
    header, julia = sys.argv[1], sys.argv[2]
    funcs = header_functions(header)
    calls = julia_ccalls(julia)
    errors = []
    if len(funcs) < 30:
        errors.append("parsed only %d functions from %s" % (len(funcs), header))
    for name, (ret, params) in sorted(funcs.items()):
        if name not in calls:
            errors.append("%s: no ccall" % name)
            continue
        if len(calls[name]) != 1:
            errors.append("%s: %d ccalls (want exactly one wrapper)" % (name, len(calls[name])))
        jret, jargs, nvalues = calls[name][0]
        if jret not in julia_types(ret):
            errors.append("%s: returns %s, C returns %s (want one of %s)" % (name, jret, ret, julia_types(ret)))
        if len(jargs) != len(params):
            errors.append("%s: %d argument types, C has %d" % (name, len(jargs), len(params)))
        if nvalues != len(params):
            errors.append("%s: passes %d values, C has %d parameters" % (name, nvalues, len(params)))
        for i, (jt, ct) in enumerate(zip(jargs, params)):
            if jt not in julia_types(ct):
                errors.append("%s: argument %d is %s, C type %s (want one of %s)" % (name, i + 1, jt, ct, julia_types(ct)))
    for name in sorted(set(calls) - set(funcs)):
        errors.append("%s: ccall of a function the header does not declare" % name)
    hc, jc = header_constants(header), julia_constants(julia)
    for k in sorted(set(hc) | set(jc)):
        if hc.get(k) != jc.get(k):
            errors.append("constant %s: header %s, Julia %s" % (k, hc.get(k), jc.get(k)))
    if len(sys.argv) > 3:
        errors += project_errors(sys.argv[3], julia, hc)
    if errors:
        print("MortarContact.jl does not match mortarcontact.h:")
        for e in errors:
            print("  " + e)
        return 1
    print("MortarContact.jl: %d ccall wrappers and %d constants match %s" % (len(funcs), len(hc), header))
    return 0


if __name__ == "__main__":
    sys.exit(main())
