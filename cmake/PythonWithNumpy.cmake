# MC_PYTHON: a Python 3 with numpy and ctypes (Debian: /usr/bin/python3 + python3-numpy), for
# the Python bindings' tests and the Python tutorial. /usr/bin/python3 first: a python3 earlier
# on PATH (pyenv, venv) may lack numpy. Unset if none is found; the users of MC_PYTHON say what
# they then leave out.
if(NOT MC_PYTHON)
  find_program(_mc_path_python3 NAMES python3)
  foreach(_py /usr/bin/python3 ${_mc_path_python3})
    if(EXISTS ${_py})
      execute_process(COMMAND ${_py} -c "import numpy, ctypes" RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
      if(_rc EQUAL 0)
        set(MC_PYTHON ${_py} CACHE FILEPATH "Python 3 interpreter with numpy for the bindings' tests")
        break()
      endif()
    endif()
  endforeach()
endif()
