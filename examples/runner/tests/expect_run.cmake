# expect_run.cmake - runs a program and checks its exit code, pieces of its output (stdout and
# stderr together, literal substrings) and, optionally, a file it must write.
#
#   cmake -DPROGRAM=<path> [-DARGS=a|b|c] -DEXPECT_CODE=<n> [-DEXPECT_OUTPUT=piece1|piece2]
#         [-DEXPECT_FILE=<path>] -P expect_run.cmake
#
# Lists use "|" as separator (";" would be split by add_test). EXPECT_FILE must exist after the
# run and be non-empty; it is removed first so an old file cannot pass.
if(DEFINED EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}")
endif()
string(REPLACE "|" ";" _args "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${_args} RESULT_VARIABLE _code OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
set(_all "${_out}${_err}")
message("${_all}")
if(NOT _code STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "exit code ${_code}, expected ${EXPECT_CODE}")
endif()
if(DEFINED EXPECT_OUTPUT)
  string(REPLACE "|" ";" _pieces "${EXPECT_OUTPUT}")
  foreach(_piece IN LISTS _pieces)
    string(FIND "${_all}" "${_piece}" _at)
    if(_at EQUAL -1)
      message(FATAL_ERROR "the output does not contain: ${_piece}")
    endif()
  endforeach()
endif()
if(DEFINED EXPECT_FILE)
  if(NOT EXISTS "${EXPECT_FILE}")
    message(FATAL_ERROR "${EXPECT_FILE} was not written")
  endif()
  file(SIZE "${EXPECT_FILE}" _size)
  if(_size EQUAL 0)
    message(FATAL_ERROR "${EXPECT_FILE} is empty")
  endif()
  message("${EXPECT_FILE}: ${_size} bytes")
endif()
