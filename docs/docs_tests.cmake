# Tests that keep the user documentation honest, included from examples/CMakeLists.txt (which
# builds the C tutorial and registers tutorial_c) when MC_BUILD_TESTS is on. Label "docs".
#   tutorial_python      examples/python/tutorial_hertz.py runs and passes its checks
#   docs_tutorial_sync   the code blocks of docs/tutorial_{c,python,axisymmetric,assembly,friction}.md are verbatim
#                        excerpts of the programs, and their "Step N" headings match the programs'
#                        steps; the .geo, .json and Python blocks of docs/tutorial_quadratic.md are
#                        excerpts of examples/runner/hertz_quadratic/, the .json blocks of
#                        docs/tutorial_adaptive.md of examples/runner/hertz_adaptive/; the Fortran blocks of
#                        docs/tutorial_legacy.md are excerpts of examples/legacy/contact_blocks.f90
#                        (its program runs as tutorial_legacy, examples/legacy/CMakeLists.txt)
#   docs_api             docs/api.md declares every header function exactly as the header does;
#                        its example program compiles and runs
#   docs_theory_names    the lib/ functions and files docs/theory.md names exist
#   docs_links           relative links between the docs resolve
set(_mc_docs ${PROJECT_SOURCE_DIR}/docs)
set(_mc_check_docs ${PROJECT_SOURCE_DIR}/tools/check_docs.py)

# A Python 3 with numpy for the Python tutorial: MC_PYTHON (cmake/PythonWithNumpy.cmake).
if(MC_PYTHON)
  set(_mc_tutorial_env "MORTARCONTACT_LIBRARY=$<TARGET_FILE:mortarcontact>"
      "PYTHONPATH=${PROJECT_SOURCE_DIR}/bindings/python" "PYTHONDONTWRITEBYTECODE=1")
  if(MC_SANITIZE)  # the library then needs the ASan runtime loaded first into the host process
    execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE _mc_asan
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(APPEND _mc_tutorial_env "LD_PRELOAD=${_mc_asan}" "ASAN_OPTIONS=detect_leaks=0")
  endif()
  add_test(NAME tutorial_python
    COMMAND ${MC_PYTHON} ${PROJECT_SOURCE_DIR}/examples/python/tutorial_hertz.py 0.01
            ${CMAKE_CURRENT_BINARY_DIR}/tutorial_hertz_python.pvd)
  set_tests_properties(tutorial_python PROPERTIES ENVIRONMENT "${_mc_tutorial_env}"
    LABELS "docs;python;contact" TIMEOUT 600)
else()
  message(WARNING "docs: no Python 3 with numpy (Debian: python3-numpy): tutorial_python will fail")
  add_test(NAME tutorial_python COMMAND ${CMAKE_COMMAND} -E echo "a Python 3 with numpy was not found")
  set_tests_properties(tutorial_python PROPERTIES WILL_FAIL ON LABELS "docs;python")
endif()

# The checks need only a plain Python 3.
find_program(MC_DOCS_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT MC_DOCS_PYTHON)
  find_program(MC_DOCS_PYTHON NAMES python3)
endif()
if(MC_DOCS_PYTHON)
  add_test(NAME docs_tutorial_sync
    COMMAND ${MC_DOCS_PYTHON} ${_mc_check_docs} sync
            ${_mc_docs}/tutorial_c.md ${PROJECT_SOURCE_DIR}/examples/tutorial_hertz.c
            ${_mc_docs}/tutorial_python.md ${PROJECT_SOURCE_DIR}/examples/python/tutorial_hertz.py
            ${_mc_docs}/tutorial_axisymmetric.md ${PROJECT_SOURCE_DIR}/examples/tutorial_shrink_fit.c
            ${_mc_docs}/tutorial_assembly.md ${PROJECT_SOURCE_DIR}/examples/tutorial_assembly.c
            ${_mc_docs}/tutorial_friction.md ${PROJECT_SOURCE_DIR}/examples/tutorial_push_out.c
            ${_mc_docs}/tutorial_quadratic.md ${PROJECT_SOURCE_DIR}/examples/runner/hertz_quadratic/hertz_quadratic.geo
            ${_mc_docs}/tutorial_quadratic.md ${PROJECT_SOURCE_DIR}/examples/runner/hertz_quadratic/hertz_quadratic.json
            ${_mc_docs}/tutorial_quadratic.md ${PROJECT_SOURCE_DIR}/examples/runner/hertz_quadratic/read_results.py
            ${_mc_docs}/tutorial_adaptive.md ${PROJECT_SOURCE_DIR}/examples/runner/hertz_adaptive/hertz_adaptive.json
            ${_mc_docs}/tutorial_legacy.md ${PROJECT_SOURCE_DIR}/examples/legacy/contact_blocks.f90)
  set(_mc_docs_cflags -std=c99 -Wall -Wextra -Werror -I${PROJECT_SOURCE_DIR}/include)
  if(MC_SANITIZE)
    list(APPEND _mc_docs_cflags -fsanitize=address,undefined)
  endif()
  add_test(NAME docs_api
    COMMAND ${MC_DOCS_PYTHON} ${_mc_check_docs} api ${PROJECT_SOURCE_DIR}/include/mortarcontact.h
            ${_mc_docs}/api.md ${CMAKE_CURRENT_BINARY_DIR}/docs_api ${CMAKE_C_COMPILER} ${_mc_docs_cflags}
            -- $<TARGET_FILE:mortarcontact> -Wl,-rpath,$<TARGET_FILE_DIR:mortarcontact>)
  add_test(NAME docs_theory_names
    COMMAND ${MC_DOCS_PYTHON} ${_mc_check_docs} names ${_mc_docs}/theory.md ${PROJECT_SOURCE_DIR}/lib)
  add_test(NAME docs_links
    COMMAND ${MC_DOCS_PYTHON} ${_mc_check_docs} links ${_mc_docs}/README.md ${_mc_docs}/theory.md
            ${_mc_docs}/api.md ${_mc_docs}/tutorial_c.md ${_mc_docs}/tutorial_python.md
            ${_mc_docs}/tutorial_axisymmetric.md ${_mc_docs}/tutorial_quadratic.md ${_mc_docs}/tutorial_legacy.md
            ${_mc_docs}/tutorial_adaptive.md ${_mc_docs}/tutorial_assembly.md ${_mc_docs}/tutorial_friction.md
            ${_mc_docs}/scene_format.md)
  set_tests_properties(docs_tutorial_sync docs_api docs_theory_names docs_links PROPERTIES LABELS "docs")
else()
  message(WARNING "docs: python3 not found: the docs_* tests will fail")
  add_test(NAME docs_tutorial_sync COMMAND ${CMAKE_COMMAND} -E echo "python3 not found")
  set_tests_properties(docs_tutorial_sync PROPERTIES WILL_FAIL ON LABELS "docs")
endif()
