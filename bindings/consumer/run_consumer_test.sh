#!/bin/sh
# Installs the build tree to a fresh prefix, then uses the installed copy only, as each
# language's users would, with no environment variable pointing at it:
#   C        bindings/consumer/main.c with pkg-config (shared, --static) and find_package
#            (mortarcontact::mortarcontact, mortarcontact::mortarcontact_static)
#   C++      examples/cxx/readme_example.cpp, #include <mortarcontact.hpp>, -Wall -Wextra -Werror
#   Fortran  examples/fortran/patch_test.f90 against the compiled module: pkg-config
#            mortarcontact-fortran, and find_package (mortarcontact::fortran, ::fortran_static);
#            examples/legacy/contact_blocks.f90 with the tutorial's line (an rpath instead of
#            LD_LIBRARY_PATH)
#   Python   the prefix is a virtual environment: its python imports the installed package,
#            which loads the installed library, and solves examples/python/readme_example.py;
#            MORTARCONTACT_LIBRARY still overrides; a DESTDIR install for /usr gets Debian's
#            layout; `pip install --no-index --no-build-isolation` of bindings/python into
#            another venv, whose package passes the binding's tests against the installed library.
#
# usage: run_consumer_test.sh BUILD_DIR WORK_DIR [PYTHON]
#   PYTHON: a Python 3 with numpy and venv (Debian: python3-numpy, python3-venv,
#           python3-setuptools, python3-wheel); without it the Python steps fail.
#   env CMAKE (default cmake), CC (cc), CXX (c++), FC (gfortran), PKG_CONFIG (pkg-config);
#       MC_SKIP_FORTRAN=1 when the build has no Fortran binding (configured without gfortran)
set -eu

build_dir=$1
work=$2
python=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
CMAKE=${CMAKE:-cmake}
CC=${CC:-cc}
CXX=${CXX:-c++}
FC=${FC:-gfortran}
PKG_CONFIG=${PKG_CONFIG:-pkg-config}

fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo; echo "=== $*"; }
# needs BINARY LIBRARY yes|no: whether BINARY has LIBRARY in DT_NEEDED
needs() {
  if readelf -d "$1" | grep -q "NEEDED.*\[$2\]"; then has=yes; else has=no; fi
  [ "$has" = "$3" ] || fail "$1: NEEDED $2 is '$has', expected '$3'"
}
# run_logged NAME COMMAND...: runs quietly, shows the log on failure
run_logged() {
  log="$work/$1.log"; shift
  "$@" >"$log" 2>&1 || { cat "$log"; fail "$*"; }
}

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
# Never let a copy outside the prefix satisfy the test.
unset LD_LIBRARY_PATH MORTARCONTACT_LIBRARY PYTHONPATH 2>/dev/null || true

install_prefix() {
  if [ -n "$python" ]; then
    step "fresh prefix: a virtual environment that sees the system's numpy"
    "$python" -m venv --without-pip --system-site-packages "$prefix" || fail "python3 -m venv (Debian: python3-venv)"
  fi
  step "cmake --install $build_dir --prefix $prefix"
  run_logged install "$CMAKE" --install "$build_dir" --prefix "$prefix"

  libdir=
  for d in "$prefix"/lib*/ "$prefix"/lib/*/; do
    [ -f "$d/pkgconfig/mortarcontact.pc" ] && { libdir=${d%/}; break; }
  done
  [ -n "$libdir" ] || fail "no <libdir>/pkgconfig/mortarcontact.pc under $prefix"
  for f in "$prefix/include/mortarcontact.h" "$prefix/include/mortarcontact.hpp" \
           "$libdir/libmortarcontact.a" "$libdir/libmortarcontact.so" "$libdir/libmortarcontact.so.0" \
           "$libdir/cmake/mortarcontact/mortarcontactConfig.cmake" \
           "$prefix/share/mortarcontact/fortran/mortarcontact.f90" \
           "$prefix/share/mortarcontact/julia/MortarContact/Project.toml" \
           "$prefix/share/mortarcontact/julia/MortarContact/src/MortarContact.jl"; do
    [ -e "$f" ] || fail "not installed: $f"
  done
  soname=$(readelf -d "$libdir/libmortarcontact.so" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
  [ "$soname" = libmortarcontact.so.0 ] || fail "soname is '$soname', expected libmortarcontact.so.0"
  echo "installed to $prefix (libdir $libdir, soname $soname)"
  export PKG_CONFIG_PATH="$libdir/pkgconfig"
}

c_consumers() {
  step "C: pkg-config, shared"
  "$PKG_CONFIG" --modversion mortarcontact
  cflags=$("$PKG_CONFIG" --cflags mortarcontact)
  libs=$("$PKG_CONFIG" --libs mortarcontact)
  echo "cflags: $cflags"; echo "libs: $libs"
  # shellcheck disable=SC2086
  "$CC" -o "$work/pc_shared" "$here/main.c" $cflags $libs -lm
  needs "$work/pc_shared" libmortarcontact.so.0 yes
  LD_LIBRARY_PATH=$libdir "$work/pc_shared"

  step "C: pkg-config --static"
  slibs=$("$PKG_CONFIG" --static --libs mortarcontact)
  echo "static libs: $slibs"
  for want in -lcholmod -lumfpack -lsuitesparseconfig -lstdc++ -lm -lopenblas -llapack; do
    case " $slibs " in *" $want "*) ;; *) fail "pkg-config --static --libs lacks $want" ;; esac
  done
  # -lmortarcontact would pick the .so next to the .a; ask GNU ld for the archive explicitly.
  slibs=$(echo "$slibs" | sed 's/-lmortarcontact\([[:space:]]\|$\)/-l:libmortarcontact.a\1/')
  # shellcheck disable=SC2086
  "$CC" -o "$work/pc_static" "$here/main.c" $cflags $slibs
  needs "$work/pc_static" libmortarcontact.so.0 no
  "$work/pc_static"

  step "C: CMake find_package, shared and static"
  run_logged cmake-configure "$CMAKE" -S "$here" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="$CC"
  run_logged cmake-build "$CMAKE" --build "$work/cmake-build"
  grep -q "mortarcontact_DIR:PATH=$libdir/cmake/mortarcontact" "$work/cmake-build/CMakeCache.txt" \
    || fail "find_package did not find the installed copy: $(grep mortarcontact_DIR "$work/cmake-build/CMakeCache.txt")"
  needs "$work/cmake-build/consumer_shared" libmortarcontact.so.0 yes
  needs "$work/cmake-build/consumer_static" libmortarcontact.so.0 no
  "$work/cmake-build/consumer_shared"   # runs through the RUNPATH CMake sets for imported targets
  "$work/cmake-build/consumer_static"
}

# The README's example prints the uniform contact pressure 0.1 at both nodes.
expect_readme_output() {
  printf 'p[0] = 0.1\np[1] = 0.1\n' | cmp -s - "$1" || { cat "$1"; fail "$2: not the README's output"; }
  echo "$2: README example OK"
}

cxx_consumer() {
  step "C++: #include <mortarcontact.hpp>, -Wall -Wextra -Werror, pkg-config"
  # shellcheck disable=SC2046
  "$CXX" -std=c++17 -Wall -Wextra -Werror -o "$work/cxx_readme" "$repo/examples/cxx/readme_example.cpp" \
    $("$PKG_CONFIG" --cflags --libs mortarcontact)
  LD_LIBRARY_PATH=$libdir "$work/cxx_readme" >"$work/cxx_readme.out"
  expect_readme_output "$work/cxx_readme.out" "C++"
}

fortran_consumers() {
  if [ "${MC_SKIP_FORTRAN:-}" = 1 ]; then
    echo; echo "=== Fortran: SKIPPED (the build has no Fortran binding)"; return
  fi
  step "Fortran: compiled module, pkg-config mortarcontact-fortran"
  fflags=$("$PKG_CONFIG" --cflags --libs mortarcontact-fortran) || fail "no mortarcontact-fortran.pc"
  echo "flags: $fflags"
  mod=$(find "$prefix/include" -name mortarcontact.mod)
  [ -n "$mod" ] || fail "mortarcontact.mod not installed under $prefix/include"
  echo "module: $mod"
  # shellcheck disable=SC2086
  (cd "$work" && "$FC" -o "$work/f_pc_shared" "$repo/examples/fortran/patch_test.f90" $fflags)
  needs "$work/f_pc_shared" libmortarcontact_fortran.so.0 yes
  LD_LIBRARY_PATH=$libdir "$work/f_pc_shared"

  step "Fortran: the legacy program with docs/tutorial_legacy.md's line (pkg-config and an rpath, no LD_LIBRARY_PATH)"
  # shellcheck disable=SC2046
  (cd "$work" && "$FC" -O2 -o "$work/f_legacy" "$repo/examples/legacy/fe_library.f90" \
     "$repo/examples/legacy/contact_blocks.f90" $("$PKG_CONFIG" --cflags --libs mortarcontact-fortran) \
     -Wl,-rpath,"$("$PKG_CONFIG" --variable=libdir mortarcontact-fortran)")
  run_logged f_legacy "$work/f_legacy"

  step "Fortran: CMake find_package(mortarcontact COMPONENTS fortran), shared and static"
  run_logged fortran-configure "$CMAKE" -S "$here/fortran" -B "$work/fortran-build" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release -DCMAKE_Fortran_COMPILER="$FC"
  run_logged fortran-build "$CMAKE" --build "$work/fortran-build"
  needs "$work/fortran-build/patch_test_shared" libmortarcontact_fortran.so.0 yes
  needs "$work/fortran-build/patch_test_static" libmortarcontact_fortran.so.0 no
  needs "$work/fortran-build/patch_test_static" libmortarcontact.so.0 no
  "$work/fortran-build/patch_test_shared"
  "$work/fortran-build/patch_test_static"
}

python_installed() {
  [ -n "$python" ] || fail "no Python 3 with numpy given: the Python package is untested"
  step "Python: the prefix's python imports the installed package, which finds the installed library"
  (cd "$work" && "$prefix/bin/python" -c "
import os, mortarcontact
package, lib = os.path.realpath(mortarcontact.__file__), os.path.realpath(mortarcontact.library_path())
print('mortarcontact', mortarcontact.__version__, 'from', package, 'library', lib)
assert package.startswith(os.path.realpath('$prefix') + '/lib/python'), package
assert os.path.dirname(lib) == os.path.realpath('$libdir'), lib
assert mortarcontact.version_string() == mortarcontact.MC_VERSION_STRING
")
  (cd "$work" && "$prefix/bin/python" "$repo/examples/python/readme_example.py" >"$work/py_readme.out")
  expect_readme_output "$work/py_readme.out" "Python"
  build_lib=$(ls "$build_dir"/lib/libmortarcontact.so.0)
  (cd "$work" && MORTARCONTACT_LIBRARY=$build_lib "$prefix/bin/python" -c "
import mortarcontact
assert mortarcontact.library_path() == '$build_lib', mortarcontact.library_path()
print('MORTARCONTACT_LIBRARY overrides:', mortarcontact.library_path())
")

  step "Python: DESTDIR install for /usr: Debian's layout, the library found from the package"
  run_logged install-usr env DESTDIR="$work/destdir" "$CMAKE" --install "$build_dir" --prefix /usr
  dist="$work/destdir/usr/lib/python3/dist-packages"
  [ -f "$dist/mortarcontact/_installed_library.py" ] || fail "no package in $dist"
  (cd "$work" && PYTHONPATH=$dist "$python" -c "
import os, mortarcontact
lib = os.path.realpath(mortarcontact.library_path())
assert lib.startswith(os.path.realpath('$work/destdir/usr/lib') + '/'), lib
print('Debian layout: package in $dist, library', lib)
")
}

python_pip() {
  step "Python: pip install --no-index --no-build-isolation bindings/python into a venv"
  # A copy: pip builds in the source folder (build/, *.egg-info).
  cp -r "$repo/bindings/python" "$work/python-src"
  rm -rf "$work/python-src/build" "$work/python-src"/*.egg-info
  venv=$work/pip-venv
  run_logged pip-venv "$python" -m venv --system-site-packages "$venv"
  run_logged pip-install env PIP_DISABLE_PIP_VERSION_CHECK=1 "$venv/bin/python" -m pip install \
    --no-index --no-build-isolation --no-cache-dir "$work/python-src"
  grep -q "Successfully installed mortarcontact" "$work/pip-install.log" || fail "pip did not install mortarcontact"
  installed_lib=$(ls "$libdir/libmortarcontact.so.0")
  (cd "$repo/bindings/python/tests" && MORTARCONTACT_LIBRARY=$installed_lib "$venv/bin/python" -c "
import os, mortarcontact
assert os.path.realpath(mortarcontact.__file__).startswith(os.path.realpath('$venv') + '/'), mortarcontact.__file__
print('pip-installed package', mortarcontact.__file__)
" && MORTARCONTACT_LIBRARY=$installed_lib "$venv/bin/python" -m unittest test_api test_contact.TestPatch) \
    || fail "the binding's tests with the pip-installed package"
}

install_prefix
c_consumers
cxx_consumer
fortran_consumers
python_installed
python_pip

echo
echo "consumer test OK"
