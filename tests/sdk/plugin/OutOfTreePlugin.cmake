# SPDX-License-Identifier: MIT
# Installs volpost to a temporary prefix, builds examples/hello_reader against it with
# find_package(volpost), and has the installed volpost read a file through that plugin.
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P OutOfTreePlugin.cmake
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}${err}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/hello_reader -B ${WORK_DIR}/build -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${CMAKE_COMMAND} -E env VOLPOST_PLUGIN_PATH=${WORK_DIR}/build
    ${WORK_DIR}/prefix/bin/volpost info ${SOURCE_DIR}/examples/hello_reader/sample.tetra)
foreach(expected "format:   Example tetra text" "tet4      2" "temperature" "[20, 40]")
  string(FIND "${out}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "volpost info through the example plugin lacks '${expected}':\n${out}")
  endif()
endforeach()
# The installed volpost also finds its bundled plugins next to itself.
run(${WORK_DIR}/prefix/bin/volpost plugins)
string(FIND "${out}" "loaded   meshio" at)
if(at EQUAL -1)
  message(FATAL_ERROR "installed volpost does not load its bundled meshio plugin:\n${out}")
endif()
message(STATUS "out-of-tree plugin built and used: OK")
