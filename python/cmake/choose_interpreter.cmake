# Which Python the module is built and tested for, said in one sentence at configure.
#
# FindPython alone takes the first python3 it meets, and on a machine whose python3 on PATH is
# not Debian's (pyenv, conda, an activated venv) that one usually lacks what
# packaging/install-deps.sh installed for Debian's: the module then builds against its headers,
# `import linkwright` fails for want of NumPy and python.pytest for want of pytest. So each
# candidate is asked (interpreter_probe.py) whether it has NumPy, pytest and Dask's distributed
# (these two only when the tests are built) and its headers, and the first that has them all
# is taken: the python3 on PATH, else Debian's /usr/bin/python3. A -DPython_EXECUTABLE=... the
# user gave is kept whatever it lacks, and what it lacks is said. The choice is made again at
# every configure (the probe looks modules up without importing them: well under a second), so
# a build folder follows a changed PATH. Sets Python_EXECUTABLE (a normal variable, never the
# cache entry, which stays the user's) for find_package(Python).

set(linkwright_python_needs numpy)
if(LINKWRIGHT_BUILD_TESTS)
  list(APPEND linkwright_python_needs pytest distributed)
endif()

# "numpy, pytest and distributed": a list as a phrase.
function(linkwright_phrase out)
  set(items ${ARGN})
  list(LENGTH items n)
  if(n GREATER 1)
    list(POP_BACK items last)
    list(JOIN items ", " head)
    set(${out} "${head} and ${last}" PARENT_SCOPE)
  else()
    set(${out} "${items}" PARENT_SCOPE)
  endif()
endfunction()

# Runs the probe with `candidate`: sets <prefix>_executable (its sys.executable, a pyenv shim
# resolved, a venv's own path kept), <prefix>_version and <prefix>_lacks (a phrase, empty when
# it lacks nothing).
function(linkwright_probe_python candidate prefix)
  execute_process(
    COMMAND "${candidate}" "${CMAKE_CURRENT_LIST_DIR}/interpreter_probe.py" ${linkwright_python_needs}
    OUTPUT_VARIABLE out RESULT_VARIABLE status ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE TIMEOUT 60)
  if(NOT status EQUAL 0 OR NOT out MATCHES "^([^;]+);([0-9]+\\.[0-9]+);(.*)$")
    set(${prefix}_executable "${candidate}" PARENT_SCOPE)
    set(${prefix}_version "?" PARENT_SCOPE)
    set(${prefix}_lacks "a working Python 3 (it did not run the probe)" PARENT_SCOPE)
    return()
  endif()
  set(${prefix}_executable "${CMAKE_MATCH_1}" PARENT_SCOPE)
  set(${prefix}_version "${CMAKE_MATCH_2}" PARENT_SCOPE)
  string(REPLACE "," ";" lacks "${CMAKE_MATCH_3}")
  list(TRANSFORM lacks REPLACE "^headers$" "its headers (Python.h)")
  linkwright_phrase(phrase ${lacks})
  set(${prefix}_lacks "${phrase}" PARENT_SCOPE)
endfunction()

linkwright_phrase(linkwright_python_needs_phrase ${linkwright_python_needs} "its headers")
set(linkwright_python_other "-DPython_EXECUTABLE=/path/to/python3 chooses another")

if(DEFINED CACHE{Python_EXECUTABLE})
  linkwright_probe_python("${Python_EXECUTABLE}" chosen)
  if(chosen_lacks)
    message(WARNING "Python module: built for ${Python_EXECUTABLE} (Python ${chosen_version}) as -DPython_EXECUTABLE "
                    "asks, though it lacks ${chosen_lacks}, so `import linkwright` or the python.pytest test fails "
                    "until it has them (packaging/install-deps.sh installs them for Debian's /usr/bin/python3).")
  else()
    message(STATUS "Python module: built for ${Python_EXECUTABLE} (Python ${chosen_version}) as -DPython_EXECUTABLE "
                   "asks; it has ${linkwright_python_needs_phrase}.")
  endif()
  return()
endif()

# The candidates, in order: the python3 on PATH (only PATH: "the python3 you would run"), then
# Debian's, unless that is the same interpreter.
find_program(linkwright_path_python3 NAMES python3 NO_CACHE NO_PACKAGE_ROOT_PATH NO_CMAKE_PATH
             NO_CMAKE_ENVIRONMENT_PATH NO_CMAKE_SYSTEM_PATH NO_CMAKE_INSTALL_PREFIX)
set(linkwright_candidates)
set(linkwright_reasons)
if(linkwright_path_python3)
  linkwright_probe_python("${linkwright_path_python3}" path)
  if(NOT path_lacks)
    set(Python_EXECUTABLE "${path_executable}")
    message(STATUS "Python module: built for ${path_executable} (Python ${path_version}), the python3 on PATH, "
                   "which has ${linkwright_python_needs_phrase}; ${linkwright_python_other}.")
    return()
  endif()
  list(APPEND linkwright_reasons "the python3 on PATH, ${path_executable}, lacks ${path_lacks}")
  list(APPEND linkwright_candidates "${path_executable}")
endif()
if(EXISTS /usr/bin/python3 AND NOT path_executable STREQUAL "/usr/bin/python3")
  linkwright_probe_python(/usr/bin/python3 debian)
  if(NOT debian_lacks)
    set(Python_EXECUTABLE /usr/bin/python3)
    message(STATUS "Python module: built for Debian's /usr/bin/python3 (Python ${debian_version}), which has "
                   "${linkwright_python_needs_phrase}, because ${linkwright_reasons}; ${linkwright_python_other}.")
    return()
  endif()
  list(APPEND linkwright_reasons "/usr/bin/python3 lacks ${debian_lacks}")
  list(APPEND linkwright_candidates /usr/bin/python3)
endif()

if(NOT linkwright_candidates)
  message(FATAL_ERROR "Python module: there is no python3 on PATH nor at /usr/bin/python3: run "
                      "packaging/install-deps.sh, pass -DPython_EXECUTABLE=/path/to/python3, or leave the "
                      "module out with -DLINKWRIGHT_BUILD_PYTHON=OFF.")
endif()
# None has everything: the build at least succeeds with one that has its headers.
set(Python_EXECUTABLE)
foreach(who IN ITEMS path debian)
  if(NOT Python_EXECUTABLE AND ${who}_executable AND NOT ${who}_lacks MATCHES "headers|working")
    set(Python_EXECUTABLE "${${who}_executable}")
  endif()
endforeach()
if(NOT Python_EXECUTABLE)
  list(GET linkwright_candidates 0 Python_EXECUTABLE)
endif()
string(REPLACE ";" ", and " linkwright_reasons "${linkwright_reasons}")
message(WARNING "Python module: no interpreter has ${linkwright_python_needs_phrase} (${linkwright_reasons}), so "
                "it is built for ${Python_EXECUTABLE}, where `import linkwright` or the python.pytest test fails: run "
                "packaging/install-deps.sh, or pass -DPython_EXECUTABLE=/path/to/python3 naming one that has them.")
