#!/bin/sh
# Installs the build tree to a scratch prefix, then builds and runs bindings/consumer/main.c
# against the installed copy only: with pkg-config (shared, and static with --static) and with
# CMake's find_package (mortarcontact::mortarcontact and mortarcontact::mortarcontact_static).
# Also imports the installed Python package (library found relative to the package) when a
# Python with numpy is given.
#
# usage: run_consumer_test.sh BUILD_DIR WORK_DIR [PYTHON]
#   env CMAKE (default cmake), CC (default cc), PKG_CONFIG (default pkg-config)
set -eu

build_dir=$1
work=$2
python=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
CMAKE=${CMAKE:-cmake}
CC=${CC:-cc}
PKG_CONFIG=${PKG_CONFIG:-pkg-config}

fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo; echo "=== $*"; }

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

step "cmake --install $build_dir --prefix $prefix"
"$CMAKE" --install "$build_dir" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "install"; }

libdir=
for d in "$prefix"/lib*/ "$prefix"/lib/*/; do
  [ -f "$d/pkgconfig/mortarcontact.pc" ] && { libdir=${d%/}; break; }
done
[ -n "$libdir" ] || fail "no <libdir>/pkgconfig/mortarcontact.pc under $prefix"
for f in "$prefix/include/mortarcontact.h" "$libdir/libmortarcontact.a" "$libdir/libmortarcontact.so" \
         "$libdir/libmortarcontact.so.0" "$libdir/cmake/mortarcontact/mortarcontactConfig.cmake" \
         "$prefix/share/mortarcontact/python/mortarcontact/__init__.py" \
         "$prefix/share/mortarcontact/fortran/mortarcontact.f90" \
         "$prefix/share/mortarcontact/julia/MortarContact.jl"; do
  [ -e "$f" ] || fail "not installed: $f"
done
soname=$(readelf -d "$libdir/libmortarcontact.so" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
[ "$soname" = libmortarcontact.so.0 ] || fail "soname is '$soname', expected libmortarcontact.so.0"
echo "installed to $prefix (libdir $libdir, soname $soname)"

# needs BINARY yes|no: whether BINARY has libmortarcontact.so.0 in DT_NEEDED
needs() {
  if readelf -d "$1" | grep -q 'NEEDED.*\[libmortarcontact\.so\.0\]'; then has=yes; else has=no; fi
  [ "$has" = "$2" ] || fail "$1: NEEDED libmortarcontact.so.0 is '$has', expected '$2'"
}

export PKG_CONFIG_PATH="$libdir/pkgconfig"
# Never let a copy outside the prefix satisfy the test.
unset LD_LIBRARY_PATH MORTARCONTACT_LIBRARY 2>/dev/null || true

step "pkg-config, shared"
"$PKG_CONFIG" --modversion mortarcontact
cflags=$("$PKG_CONFIG" --cflags mortarcontact)
libs=$("$PKG_CONFIG" --libs mortarcontact)
echo "cflags: $cflags"; echo "libs: $libs"
# shellcheck disable=SC2086
"$CC" -o "$work/pc_shared" "$here/main.c" $cflags $libs -lm
needs "$work/pc_shared" yes
LD_LIBRARY_PATH=$libdir "$work/pc_shared"

step "pkg-config --static"
slibs=$("$PKG_CONFIG" --static --libs mortarcontact)
echo "static libs: $slibs"
for want in -lcholmod -lsuitesparseconfig -lstdc++ -lm -lopenblas -llapack; do
  case " $slibs " in *" $want "*) ;; *) fail "pkg-config --static --libs lacks $want" ;; esac
done
# -lmortarcontact would pick the .so next to the .a; ask GNU ld for the archive explicitly.
slibs=$(echo "$slibs" | sed 's/-lmortarcontact\([[:space:]]\|$\)/-l:libmortarcontact.a\1/')
# shellcheck disable=SC2086
"$CC" -o "$work/pc_static" "$here/main.c" $cflags $slibs
needs "$work/pc_static" no
"$work/pc_static"

step "CMake find_package, shared and static"
"$CMAKE" -S "$here" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$CC" >"$work/cmake-configure.log" 2>&1 || { cat "$work/cmake-configure.log"; fail "consumer configure"; }
"$CMAKE" --build "$work/cmake-build" >"$work/cmake-build.log" 2>&1 || { cat "$work/cmake-build.log"; fail "consumer build"; }
grep -q "mortarcontact_DIR:PATH=$libdir/cmake/mortarcontact" "$work/cmake-build/CMakeCache.txt" \
  || fail "find_package did not find the installed copy: $(grep mortarcontact_DIR "$work/cmake-build/CMakeCache.txt")"
needs "$work/cmake-build/consumer_shared" yes
needs "$work/cmake-build/consumer_static" no
"$work/cmake-build/consumer_shared"   # runs through the RUNPATH CMake sets for imported targets
"$work/cmake-build/consumer_static"

if [ -n "$python" ]; then
  step "installed Python package finds the installed library"
  (cd "$work" && PYTHONPATH="$prefix/share/mortarcontact/python" "$python" -c "
import os, sys, mortarcontact
lib = os.path.realpath(mortarcontact.library_path())
want = os.path.realpath('$libdir')
print('mortarcontact', mortarcontact.__version__, 'from', lib)
assert os.path.dirname(lib) == want, (lib, want)
assert mortarcontact.version_string() == mortarcontact.MC_VERSION_STRING
with mortarcontact.Model() as m:
    pass
")
fi

echo
echo "consumer test OK"
