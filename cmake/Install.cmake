# Install rules: shared + static library, header, pkg-config file, CMake package, and the
# language bindings' sources. Included from the top-level CMakeLists.txt after lib/.
#
#   cmake --install <build> --prefix <prefix>
#
# installs (libdir = CMAKE_INSTALL_LIBDIR, e.g. lib or lib/x86_64-linux-gnu):
#   <libdir>/libmortarcontact.so.0.1.0, .so.0, .so      shared library (soname .so.0)
#   <libdir>/libmortarcontact.a                           static library
#   include/mortarcontact.h, include/mortarcontact.hpp    C header, header-only C++ wrapper
#   <libdir>/pkgconfig/mortarcontact.pc
#   <libdir>/cmake/mortarcontact/mortarcontact{Config,ConfigVersion,Targets*}.cmake
#   with a Fortran compiler (cmake/FortranBinding.cmake):
#     <libdir>/libmortarcontact_fortran.{so*,a}           the Fortran module's wrappers
#     MC_INSTALL_FORTRAN_MODDIR/mortarcontact.mod          e.g. include/mortarcontact/fortran/gnu-12
#     <libdir>/pkgconfig/mortarcontact-fortran.pc
#   MC_INSTALL_PYTHONDIR/mortarcontact/                     the Python package, by default where
#                                                         the prefix's Python looks (see below)
#   share/mortarcontact/fortran/mortarcontact.f90         the module's source, for other compilers
#   share/mortarcontact/julia/MortarContact/              the Julia package (Project.toml, src/)
#   share/doc/mortarcontact/{abi,bindings}.md
include(CMakePackageConfigHelpers)

set(MC_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/mortarcontact"
    CACHE STRING "Where the CMake package files of mortarcontact are installed")
set(MC_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/mortarcontact")

# ---- the static library's link interface, as seen by an installed consumer ----------
# lib/ links mortarcontact_static PUBLIC to ${CHOLMOD_LIBRARY} ${UMFPACK_LIBRARY} ${SUITESPARSECONFIG_LIBRARY}
# (absolute paths of this machine) and PkgConfig::LAPACK / PkgConfig::OPENBLAS (imported
# targets that only exist in this build). Exported as they are, they would either pin the
# build machine's paths or name targets a consumer does not have. So the build keeps them
# ($<BUILD_INTERFACE:...>) and the installed package sees its own imported targets
# mortarcontact::deps_*, which mortarcontactConfig.cmake creates by finding the
# dependencies again on the consumer's machine.
get_target_property(_mc_static_iface mortarcontact_static INTERFACE_LINK_LIBRARIES)
set(_mc_static_new_iface "")
foreach(_mc_item IN LISTS _mc_static_iface)
  if(_mc_item STREQUAL "${CHOLMOD_LIBRARY}")
    list(APPEND _mc_static_new_iface "$<BUILD_INTERFACE:${_mc_item}>" "$<INSTALL_INTERFACE:mortarcontact::deps_cholmod>")
  elseif(_mc_item STREQUAL "${UMFPACK_LIBRARY}")
    list(APPEND _mc_static_new_iface "$<BUILD_INTERFACE:${_mc_item}>" "$<INSTALL_INTERFACE:mortarcontact::deps_umfpack>")
  elseif(_mc_item STREQUAL "${SUITESPARSECONFIG_LIBRARY}")
    list(APPEND _mc_static_new_iface "$<BUILD_INTERFACE:${_mc_item}>" "$<INSTALL_INTERFACE:mortarcontact::deps_suitesparseconfig>")
  elseif(_mc_item STREQUAL "PkgConfig::OPENBLAS")
    list(APPEND _mc_static_new_iface "$<BUILD_INTERFACE:${_mc_item}>" "$<INSTALL_INTERFACE:mortarcontact::deps_openblas>")
  elseif(_mc_item STREQUAL "PkgConfig::LAPACK")
    list(APPEND _mc_static_new_iface "$<BUILD_INTERFACE:${_mc_item}>" "$<INSTALL_INTERFACE:mortarcontact::deps_lapack>")
  elseif(_mc_item MATCHES "^PkgConfig::" OR IS_ABSOLUTE "${_mc_item}")
    message(FATAL_ERROR "cmake/Install.cmake: mortarcontact_static links to '${_mc_item}', which the "
                        "installed CMake package does not know how to find; add it to cmake/Install.cmake "
                        "and cmake/mortarcontactConfig.cmake.in (and to Libs.private in mortarcontact.pc).")
  else()
    list(APPEND _mc_static_new_iface "${_mc_item}")   # stdc++, m, generator expressions
  endif()
endforeach()
set_property(TARGET mortarcontact_static PROPERTY INTERFACE_LINK_LIBRARIES "${_mc_static_new_iface}")

# ---- libraries and header --------------------------------------------------------------
set(_mc_library_targets mortarcontact mortarcontact_static)
if(TARGET mortarcontact_fortran)
  list(APPEND _mc_library_targets mortarcontact_fortran mortarcontact_fortran_static)
  install(FILES ${MC_FORTRAN_MODULE_DIR}/mortarcontact.mod DESTINATION ${MC_INSTALL_FORTRAN_MODDIR})
endif()
install(TARGETS ${_mc_library_targets}
  EXPORT mortarcontactTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# (lib/ already gives both targets $<INSTALL_INTERFACE:include> as their include directory.)
install(FILES ${PROJECT_SOURCE_DIR}/include/mortarcontact.h ${PROJECT_SOURCE_DIR}/include/mortarcontact.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# ---- CMake package -------------------------------------------------------------------
install(EXPORT mortarcontactTargets
  NAMESPACE mortarcontact::
  DESTINATION ${MC_INSTALL_CMAKEDIR})
configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/mortarcontactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/mortarcontactConfig.cmake
  INSTALL_DESTINATION ${MC_INSTALL_CMAKEDIR})
# The ABI promise (docs/abi.md) holds within a major version.
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/cmake/mortarcontactConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMajorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/cmake/mortarcontactConfig.cmake
  ${PROJECT_BINARY_DIR}/cmake/mortarcontactConfigVersion.cmake
  DESTINATION ${MC_INSTALL_CMAKEDIR})

# ---- pkg-config ----------------------------------------------------------------------
# Written at install time, so that `cmake --install --prefix P` gets P (not the configure-time
# CMAKE_INSTALL_PREFIX) in the files.
set(_mc_pc_files mortarcontact)
if(TARGET mortarcontact_fortran)
  list(APPEND _mc_pc_files mortarcontact-fortran)
endif()
install(CODE "
  set(_mc_prefix \"\${CMAKE_INSTALL_PREFIX}\")
  set(_mc_libdir \"${CMAKE_INSTALL_LIBDIR}\")
  set(_mc_includedir \"${CMAKE_INSTALL_INCLUDEDIR}\")
  set(_mc_fmoddir \"${MC_INSTALL_FORTRAN_MODDIR}\")
  if(NOT IS_ABSOLUTE \"\${_mc_libdir}\")
    set(_mc_libdir \"\\\${exec_prefix}/\${_mc_libdir}\")
  endif()
  if(NOT IS_ABSOLUTE \"\${_mc_includedir}\")
    set(_mc_includedir \"\\\${prefix}/\${_mc_includedir}\")
  endif()
  if(NOT IS_ABSOLUTE \"\${_mc_fmoddir}\")
    set(_mc_fmoddir \"\\\${prefix}/\${_mc_fmoddir}\")
  endif()
  set(MC_PC_PREFIX \"\${_mc_prefix}\")
  set(MC_PC_LIBDIR \"\${_mc_libdir}\")
  set(MC_PC_INCLUDEDIR \"\${_mc_includedir}\")
  set(MC_PC_FMODDIR \"\${_mc_fmoddir}\")
  set(MC_PC_FORTRAN_COMPILER \"${CMAKE_Fortran_COMPILER_ID} ${CMAKE_Fortran_COMPILER_VERSION}\")
  set(MC_PC_VERSION \"${PROJECT_VERSION}\")
  foreach(_mc_pc ${_mc_pc_files})
    configure_file(\"${CMAKE_CURRENT_LIST_DIR}/\${_mc_pc}.pc.in\" \"${PROJECT_BINARY_DIR}/cmake/\${_mc_pc}.pc\" @ONLY)
    file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig\"
         TYPE FILE FILES \"${PROJECT_BINARY_DIR}/cmake/\${_mc_pc}.pc\")
  endforeach()
")

# ---- the Python package, where the prefix's Python looks for packages -------------------
# At install time (the prefix is only known then): cmake/InstallPythonPackage.cmake.
set(MC_INSTALL_PYTHONDIR "" CACHE STRING
    "Folder of the Python package mortarcontact (relative to the prefix, or absolute); empty: \
the prefix's layout (a venv's site-packages, else Debian's lib/python3/dist-packages for /usr, \
lib/pythonX.Y/dist-packages for other prefixes)")
set(_mc_py_version 3)  # no Python at configure time: lib/python3/dist-packages
find_program(MC_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT MC_PYTHON3)
  find_program(MC_PYTHON3 NAMES python3)
endif()
if(MC_PYTHON3)
  execute_process(COMMAND ${MC_PYTHON3} -c "import sys; print('%d.%d' % sys.version_info[:2])"
                  OUTPUT_VARIABLE _mc_py_version OUTPUT_STRIP_TRAILING_WHITESPACE)
endif()
install(CODE "
  set(MC_PY_DIR \"${MC_INSTALL_PYTHONDIR}\")
  set(MC_PY_VERSION \"${_mc_py_version}\")
  set(MC_PY_SOURCE \"${PROJECT_SOURCE_DIR}/bindings/python/mortarcontact\")
  set(MC_PY_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
  set(MC_PY_SCRATCH \"${PROJECT_BINARY_DIR}/cmake\")
  include(\"${CMAKE_CURRENT_LIST_DIR}/InstallPythonPackage.cmake\")
")

# ---- binding sources and docs -----------------------------------------------------------
if(EXISTS ${PROJECT_SOURCE_DIR}/bindings/fortran/mortarcontact.f90)
  install(FILES ${PROJECT_SOURCE_DIR}/bindings/fortran/mortarcontact.f90
          DESTINATION ${MC_INSTALL_DATADIR}/fortran)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/bindings/julia/Project.toml
        DESTINATION ${MC_INSTALL_DATADIR}/julia/MortarContact)
install(FILES ${PROJECT_SOURCE_DIR}/bindings/julia/src/MortarContact.jl
        DESTINATION ${MC_INSTALL_DATADIR}/julia/MortarContact/src)
foreach(_mc_doc abi.md bindings.md)
  if(EXISTS ${PROJECT_SOURCE_DIR}/docs/${_mc_doc})
    install(FILES ${PROJECT_SOURCE_DIR}/docs/${_mc_doc} DESTINATION ${CMAKE_INSTALL_DOCDIR})
  endif()
endforeach()
