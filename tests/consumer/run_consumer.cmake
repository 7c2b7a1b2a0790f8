# cmake -P script: configure, build and run one consumer project and check what it prints.
#   -DMODE=install|find_package|add_subdirectory -DKIN5_SOURCE_DIR=... -DWORK_DIR=...
#   -DGENERATOR=... -DCXX_COMPILER=...
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(common -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release)

if(MODE STREQUAL "install")
  # A fresh core-only configuration of kin5, installed into a prefix under the build tree.
  file(REMOVE_RECURSE ${WORK_DIR}/kin5-build ${prefix})
  run(${CMAKE_COMMAND} -S ${KIN5_SOURCE_DIR} -B ${WORK_DIR}/kin5-build ${common}
      -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_TOOLS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_INSTALL=ON)
  run(${CMAKE_COMMAND} --install ${WORK_DIR}/kin5-build --prefix ${prefix})
  if(NOT EXISTS ${prefix}/include/kin5/kin5.hpp)
    message(FATAL_ERROR "install did not place include/kin5/kin5.hpp under ${prefix}")
  endif()
  return()
endif()

set(build ${WORK_DIR}/${MODE}-build)
file(REMOVE_RECURSE ${build})
if(MODE STREQUAL "find_package")
  # Eigen is made unfindable: find_package(kin5) must succeed without it.
  run(${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/find_package -B ${build} ${common}
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=TRUE)
else()
  run(${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/add_subdirectory -B ${build} ${common}
      -DKIN5_SOURCE_DIR=${KIN5_SOURCE_DIR})
endif()
run(${CMAKE_COMMAND} --build ${build} --target consumer)
run(${build}/consumer)
if(NOT last_output MATCHES "dmu-80p tool axis: 0\\.707107 0\\.500000 0\\.500000")
  message(FATAL_ERROR "unexpected output: ${last_output}")
endif()
message(STATUS "${MODE}: ${last_output}")
