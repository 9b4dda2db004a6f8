# Run by `cmake --install` (install(CODE) in cmake/Install.cmake, which sets the MC_PY_*
# variables): installs the Python package mortarcontact where the prefix's Python looks for
# packages, and records there where the library was installed, so that the package loads it
# with no environment variable.
#
#   MC_PY_DIR      MC_INSTALL_PYTHONDIR: the folder (relative to the prefix, or absolute);
#                  empty = the prefix's own layout, decided here, at install time:
#                    a virtual environment (PREFIX/pyvenv.cfg)  lib/pythonX.Y/site-packages
#                    /usr (Debian's python3 packages)            lib/python3/dist-packages
#                    any other prefix (Debian's /usr/local)      lib/pythonX.Y/dist-packages
#   MC_PY_VERSION  X.Y of the Python found at configure time (a venv's own version wins)
#   MC_PY_SOURCE   bindings/python/mortarcontact
#   MC_PY_LIBDIR   CMAKE_INSTALL_LIBDIR
#   MC_PY_SCRATCH  a build-tree folder for the generated module

# X.Y of the virtual environment at `prefix` ("version = 3.11.2" in its pyvenv.cfg).
function(mc_venv_python_version prefix out)
  file(STRINGS "${prefix}/pyvenv.cfg" _lines REGEX "^version[_a-z]* *=")
  string(REGEX MATCH "[0-9]+\\.[0-9]+" _version "${_lines}")
  set(${out} "${_version}" PARENT_SCOPE)
endfunction()

function(mc_python_package_dir out)
  set(prefix "${CMAKE_INSTALL_PREFIX}")
  set(staged "$ENV{DESTDIR}${prefix}")
  if(NOT MC_PY_DIR STREQUAL "")
    set(dir "${MC_PY_DIR}")
  elseif(EXISTS "${staged}/pyvenv.cfg")
    mc_venv_python_version("${staged}" version)
    set(dir "lib/python${version}/site-packages")
  elseif(prefix STREQUAL "/usr")
    set(dir "lib/python3/dist-packages")
  else()
    set(dir "lib/python${MC_PY_VERSION}/dist-packages")
  endif()
  if(NOT IS_ABSOLUTE "${dir}")
    set(dir "${prefix}/${dir}")
  endif()
  set(${out} "${dir}" PARENT_SCOPE)
endfunction()

mc_python_package_dir(_mc_pydir)
file(INSTALL DESTINATION "${_mc_pydir}" TYPE DIRECTORY FILES "${MC_PY_SOURCE}"
     FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)

# Relative, so that the pair still matches after DESTDIR staging or moving the whole prefix.
set(_mc_libdir "${MC_PY_LIBDIR}")
if(NOT IS_ABSOLUTE "${_mc_libdir}")
  set(_mc_libdir "${CMAKE_INSTALL_PREFIX}/${_mc_libdir}")
endif()
file(RELATIVE_PATH _mc_relative "${_mc_pydir}/mortarcontact" "${_mc_libdir}")
file(WRITE "${MC_PY_SCRATCH}/_installed_library.py"
  "\"\"\"Written by cmake --install: where the library was installed with this package.\"\"\"\n"
  "#: The library's folder, relative to this package's folder.\n"
  "LIBRARY_DIR = \"${_mc_relative}\"\n")
file(INSTALL DESTINATION "${_mc_pydir}/mortarcontact" TYPE FILE FILES "${MC_PY_SCRATCH}/_installed_library.py")
