# Output tests (included from tests/CMakeLists.txt): mc_write_vtu and mc_set_log_callback.
mc_add_check_test(test_output test_output.c)

# The written files read by meshio (Debian: python3-meshio), values compared with the getters
# through the Python binding (needs numpy). A missing module is a failing test, not a skip.
set(_mc_output_python /usr/bin/python3)
if(NOT EXISTS ${_mc_output_python})
  find_program(_mc_output_python NAMES python3)
endif()
execute_process(COMMAND ${_mc_output_python} -c "import meshio, numpy"
                RESULT_VARIABLE _mc_meshio_rc OUTPUT_QUIET ERROR_QUIET)
if(_mc_meshio_rc EQUAL 0)
  set(_mc_output_env
    "MORTARCONTACT_LIBRARY=$<TARGET_FILE:mortarcontact>"
    "PYTHONPATH=${PROJECT_SOURCE_DIR}/bindings/python"
    "PYTHONDONTWRITEBYTECODE=1")
  if(MC_SANITIZE)  # the library then needs the ASan runtime loaded first into the host process
    execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE _mc_asan
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(APPEND _mc_output_env "LD_PRELOAD=${_mc_asan}" "ASAN_OPTIONS=detect_leaks=0")
  endif()
  add_test(NAME test_output_meshio
    COMMAND ${_mc_output_python} -m unittest -v test_output_meshio
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  set_tests_properties(test_output_meshio PROPERTIES ENVIRONMENT "${_mc_output_env}" TIMEOUT 120)
else()
  message(WARNING "tests: python3 with meshio and numpy not found (Debian: python3-meshio): test_output_meshio will fail")
  add_test(NAME test_output_meshio COMMAND ${CMAKE_COMMAND} -E echo "python3 with meshio and numpy not found")
  set_tests_properties(test_output_meshio PROPERTIES WILL_FAIL ON)
endif()
