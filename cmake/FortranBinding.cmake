# The Fortran binding as installed libraries: the module bindings/fortran/mortarcontact.f90
# compiled once into
#   mortarcontact_fortran         libmortarcontact_fortran.so (exported as mortarcontact::fortran)
#   mortarcontact_fortran_static  libmortarcontact_fortran.a  (mortarcontact::fortran_static)
# and the compiled module mortarcontact.mod, installed to MC_INSTALL_FORTRAN_MODDIR: a folder
# named after the compiler, since a .mod file is only readable by the compiler (and version
# family) that wrote it. Users of another compiler compile the installed source instead.
# Included from the top-level CMakeLists.txt after lib/; without a Fortran compiler it defines
# nothing (bindings/CMakeLists.txt then registers failing placeholder tests).
if(MC_BUILD_FUZZ)  # the fuzzing build's compile options are clang's, and it needs no Fortran
  return()
endif()
include(CheckLanguage)
check_language(Fortran)
if(NOT CMAKE_Fortran_COMPILER)
  message(STATUS "No Fortran compiler: the Fortran binding's libraries are not built")
  return()
endif()
enable_language(Fortran)

set(MC_FORTRAN_SOURCE ${PROJECT_SOURCE_DIR}/bindings/fortran/mortarcontact.f90)
set(MC_FORTRAN_MODULE_DIR ${PROJECT_BINARY_DIR}/fortran-modules)
string(TOLOWER "${CMAKE_Fortran_COMPILER_ID}" _mc_fc_id)
string(REGEX MATCH "^[0-9]+" _mc_fc_major "${CMAKE_Fortran_COMPILER_VERSION}")
set(MC_INSTALL_FORTRAN_MODDIR "${CMAKE_INSTALL_INCLUDEDIR}/mortarcontact/fortran/${_mc_fc_id}-${_mc_fc_major}"
    CACHE STRING "Where mortarcontact.mod is installed (relative to the prefix): one folder per compiler")

# One compilation (position-independent) for both libraries: two targets compiling the same
# module into one module folder would race on mortarcontact.mod.
add_library(mc_fortran_objects OBJECT ${MC_FORTRAN_SOURCE})
set_target_properties(mc_fortran_objects PROPERTIES
  POSITION_INDEPENDENT_CODE ON
  Fortran_MODULE_DIRECTORY ${MC_FORTRAN_MODULE_DIR})
if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  # the standard the module claims (its header, docs/bindings.md, mortarcontact-fortran.pc)
  target_compile_options(mc_fortran_objects PRIVATE -std=f2008 -Wall -Wextra)
endif()

add_library(mortarcontact_fortran SHARED $<TARGET_OBJECTS:mc_fortran_objects>)
set_target_properties(mortarcontact_fortran PROPERTIES
  EXPORT_NAME fortran
  VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
  # libmortarcontact.so.0 is installed next to it: found without LD_LIBRARY_PATH.
  INSTALL_RPATH "$ORIGIN")
target_link_libraries(mortarcontact_fortran PUBLIC mortarcontact)

add_library(mortarcontact_fortran_static STATIC $<TARGET_OBJECTS:mc_fortran_objects>)
set_target_properties(mortarcontact_fortran_static PROPERTIES
  EXPORT_NAME fortran_static
  OUTPUT_NAME mortarcontact_fortran)
target_link_libraries(mortarcontact_fortran_static PUBLIC mortarcontact_static)

foreach(_mc_target mortarcontact_fortran mortarcontact_fortran_static)
  add_dependencies(${_mc_target} mc_fortran_objects)
  target_include_directories(${_mc_target} PUBLIC
    $<BUILD_INTERFACE:${MC_FORTRAN_MODULE_DIR}> $<INSTALL_INTERFACE:${MC_INSTALL_FORTRAN_MODDIR}>)
endforeach()
