#!/usr/bin/env python3
"""Keeps the user documentation honest (ctest: docs_tutorial_sync, docs_api, docs_theory_names,
docs_links; registered in docs/docs_tests.cmake).

    check_docs.py sync DOC SOURCE [DOC SOURCE ...]
        Every ```c / ```python block of DOC is a verbatim run of lines of SOURCE (trailing
        blanks ignored), and the "---- step N: title ----" markers of SOURCE are exactly the
        "## Step N: Title" headings of DOC (case ignored). The block language follows SOURCE:
        python for .py, json for .json, geo for a Gmsh .geo, fortran for .f90, c otherwise.
    check_docs.py api HEADER DOC WORKDIR CC [CFLAGS ...] -- LINK ...
        Every MC_API function of HEADER is declared in a ```c block of DOC exactly as in the
        header (whitespace and comments ignored), and every declaration or typedef there is
        the header's. Every ```c block of DOC containing "int main" is compiled
        (CC CFLAGS file LINK) and run; it must exit 0.
    check_docs.py names DOC LIBDIR
        Every `name()` / `Class::name()` in DOC is defined or declared in LIBDIR's sources, and
        every `lib/...` path exists.
    check_docs.py links DOC [DOC ...]
        Every relative Markdown link [text](path) of each DOC points to an existing file.

Plain Python 3, no third-party modules. Exits non-zero with one line per problem.
"""

import os
import re
import subprocess
import sys

FENCE = re.compile(r"^```(\w*)\s*\n(.*?)^```\s*$", re.M | re.S)


def blocks(text, languages):
    """The fenced code blocks of a Markdown text in one of `languages`, as (line, code)."""
    out = []
    for m in FENCE.finditer(text):
        if m.group(1) in languages:
            out.append((text.count("\n", 0, m.start()) + 1, m.group(2)))
    return out


def check_sync(pairs):
    problems = []
    for doc, source in pairs:
        text = open(doc, encoding="utf-8").read()
        src = [line.rstrip() for line in open(source, encoding="utf-8").read().split("\n")]
        language = {".py": "python", ".json": "json", ".geo": "geo", ".f90": "fortran"}.get(
            os.path.splitext(source)[1], "c")
        found = blocks(text, {language})
        if not found:
            problems.append("%s: no ```%s block quotes %s" % (doc, language, source))
        for line, code in found:
            lines = [x.rstrip() for x in code.rstrip("\n").split("\n")]
            n = len(lines)
            if not any(src[i:i + n] == lines for i in range(len(src) - n + 1)):
                problems.append("%s:%d: this ```%s block is not a verbatim excerpt of %s (first line: %r)"
                                % (doc, line, language, source, lines[0]))
        markers = {(int(n), t.strip().lower()) for n, t in re.findall(r"---- step (\d+): (.*?) ----", "\n".join(src))}
        headings = {(int(n), t.strip().lower()) for n, t in re.findall(r"^## Step (\d+): (.*)$", text, re.M)}
        for n, t in sorted(markers - headings):
            problems.append("%s: step %d of %s (%r) has no heading '## Step %d: ...' with that title" % (doc, n, source, t, n))
        for n, t in sorted(headings - markers):
            problems.append("%s: heading 'Step %d: %s' matches no step marker of %s" % (doc, n, t, source))
    return problems


def normalize(code):
    """Declarations without comments, with single spaces, without spaces inside brackets."""
    code = re.sub(r"/\*.*?\*/", " ", code, flags=re.S)
    code = re.sub(r"//[^\n]*", " ", code)
    code = re.sub(r"\s+", " ", code).strip()
    return re.sub(r"\s*([(),;*{}=])\s*", r"\1", code)


def statements(code):
    """Top-level statements ending in ';' of a C fragment (braces kept together)."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(code):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch == ";" and depth == 0:
            out.append(code[start:i + 1].strip())
            start = i + 1
    return [s for s in out if s]


def check_api(header, doc, workdir, cc, cflags, link):
    problems = []
    header_text = normalize(open(header, encoding="utf-8").read())
    functions = {}
    for decl in re.findall(r"MC_API [^;]*?\bmc_\w+\([^;]*?\);", header_text):
        functions[re.search(r"\b(mc_\w+)\(", decl).group(1)] = decl
    text = open(doc, encoding="utf-8").read()
    documented = {}
    programs = []
    for line, code in blocks(text, {"c"}):
        if "int main" in code:
            programs.append((line, code))
            continue
        for stmt in statements(normalize(code)):
            name = re.search(r"\b(mc_\w+)\(", stmt)
            if stmt.startswith("MC_API") and name:
                name = name.group(1)
                documented[name] = line
                if name not in functions:
                    problems.append("%s:%d: %s is not a function of the header" % (doc, line, name))
                elif stmt != functions[name]:
                    problems.append("%s:%d: %s differs from the header:\n    doc:    %s\n    header: %s"
                                    % (doc, line, name, stmt, functions[name]))
            elif stmt not in header_text:
                problems.append("%s:%d: not in the header: %s" % (doc, line, stmt))
    for name in sorted(set(functions) - set(documented)):
        problems.append("%s: the header's %s is not documented (no ```c block declares it)" % (doc, name))
    os.makedirs(workdir, exist_ok=True)
    for line, code in programs:
        source = os.path.join(workdir, "example_line%d.c" % line)
        binary = source[:-2]
        with open(source, "w", encoding="utf-8") as f:
            f.write(code)
        build = subprocess.run([cc] + cflags + [source, "-o", binary] + link, capture_output=True, text=True)
        if build.returncode != 0:
            problems.append("%s:%d: the example does not compile:\n%s" % (doc, line, build.stderr))
            continue
        run = subprocess.run([binary], capture_output=True, text=True, cwd=workdir)
        sys.stdout.write(run.stdout)
        if run.returncode != 0:
            problems.append("%s:%d: the example exits with %d:\n%s%s" % (doc, line, run.returncode, run.stdout, run.stderr))
    print("%d header functions, %d documented, %d example programs run" % (len(functions), len(documented), len(programs)))
    return problems


def check_names(doc, libdir):
    problems = []
    text = open(doc, encoding="utf-8").read()
    sources = ""
    for folder, _, files in sorted(os.walk(libdir)):  # lib/ and its layers' folders
        for name in sorted(files):
            if name.endswith((".cpp", ".hpp", ".h")):
                sources += open(os.path.join(folder, name), encoding="utf-8").read()
    names = set(re.findall(r"`((?:\w+::)*\w+)\(\)`", text))
    for name in sorted(names):
        if name.startswith("mc_"):
            continue  # C API functions: checked against the header by docs_api
        parts = name.split("::")
        if not re.search(r"\b%s\s*\(" % re.escape(parts[-1]), sources):
            problems.append("%s: `%s()` is not a function in %s" % (doc, name, libdir))
        if len(parts) > 1 and not re.search(r"\b(class|struct)\s+%s\b" % re.escape(parts[-2]), sources):
            problems.append("%s: `%s()`: no class %s in %s" % (doc, name, parts[-2], libdir))
    root = os.path.dirname(os.path.abspath(libdir))
    for path in sorted(set(re.findall(r"`(lib/[\w./]+)`", text))):
        if not os.path.exists(os.path.join(root, path)):
            problems.append("%s: `%s` does not exist" % (doc, path))
    print("%s: %d function names checked" % (doc, len(names)))
    return problems


def check_links(docs):
    problems = []
    for doc in docs:
        text = open(doc, encoding="utf-8").read()
        text = FENCE.sub("", text)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            path = os.path.normpath(os.path.join(os.path.dirname(doc), target.split("#")[0]))
            if not os.path.exists(path):
                problems.append("%s: broken link (%s)" % (doc, target))
    return problems


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    mode, args = argv[1], argv[2:]
    if mode == "sync" and args and len(args) % 2 == 0:
        problems = check_sync(list(zip(args[0::2], args[1::2])))
    elif mode == "api" and len(args) >= 4 and "--" in args:
        cut = args.index("--")
        header, doc, workdir, cc = args[:4]
        problems = check_api(header, doc, workdir, cc, args[4:cut], args[cut + 1:])
    elif mode == "names" and len(args) == 2:
        problems = check_names(*args)
    elif mode == "links" and args:
        problems = check_links(args)
    else:
        sys.exit(__doc__)
    for p in problems:
        print("FAIL:", p)
    print("%s: %s" % (mode, "%d problems" % len(problems) if problems else "ok"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
