# cmake -P script: configure, build and run one consumer project and check what it prints.
#   -DMODE=install|find_package|add_subdirectory|install_all|find_package_reach
#   -DKIN5_SOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCXX_COMPILER=...
#   -DBUILD_DIR=... (install_all: kin5's own build tree, built, with the tools and kin5::reach)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(CMAKE_INSTALL_BINDIR bin)  # GNUInstallDirs' default under a prefix of one's own

# configure_fails(WHAT ARGS...): configuring must fail, with WHAT in the message.
function(configure_fails what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT "${out}${err}" MATCHES "${what}")
    message(FATAL_ERROR "expected a failure naming '${what}' (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(prefix_all ${WORK_DIR}/prefix-all)
set(common -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release)

if(MODE STREQUAL "install_all")
  # kin5's own build tree installed as a user would: headers, package files with every
  # component, the kin5 tool and kin5-gen-tables.
  file(REMOVE_RECURSE ${prefix_all})
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix_all})
  foreach(f include/kin5/reach.hpp ${CMAKE_INSTALL_BINDIR}/kin5 ${CMAKE_INSTALL_BINDIR}/kin5-gen-tables)
    if(NOT EXISTS ${prefix_all}/${f})
      message(FATAL_ERROR "install did not place ${f} under ${prefix_all}")
    endif()
  endforeach()
  file(GLOB_RECURSE reach_targets ${prefix_all}/*/kin5ReachTargets.cmake)
  if(NOT reach_targets)
    message(FATAL_ERROR "install did not place the package file of kin5::reach under ${prefix_all}")
  endif()
  run(${prefix_all}/${CMAKE_INSTALL_BINDIR}/kin5-gen-tables --help)
  # Every catalog machine's file, and the installed tool reads one as the bundled machine.
  file(GLOB bundled RELATIVE ${KIN5_SOURCE_DIR}/machines ${KIN5_SOURCE_DIR}/machines/*.toml)
  list(LENGTH bundled count)
  if(count LESS 12)
    message(FATAL_ERROR "expected the 12 catalog machine files in ${KIN5_SOURCE_DIR}/machines, found ${count}")
  endif()
  foreach(f ${bundled})
    if(NOT EXISTS ${prefix_all}/share/kin5/machines/${f})
      message(FATAL_ERROR "install did not place share/kin5/machines/${f} under ${prefix_all}")
    endif()
  endforeach()
  run(${prefix_all}/${CMAKE_INSTALL_BINDIR}/kin5 fk --machine-file ${prefix_all}/share/kin5/machines/xyzbc-trt.toml B=30 C=45)
  set(from_file "${last_output}")
  run(${prefix_all}/${CMAKE_INSTALL_BINDIR}/kin5 fk --machine xyzbc-trt B=30 C=45)
  if(NOT from_file STREQUAL last_output OR from_file STREQUAL "")
    message(FATAL_ERROR "the installed xyzbc-trt.toml is not the bundled xyzbc-trt:\n${from_file}\n${last_output}")
  endif()
  return()
endif()

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
if(MODE STREQUAL "find_package_reach")
  # Without pkg-config (so without Ipopt) the reach component is missing, and says why ...
  configure_fails("needs Ipopt" ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/find_package_reach -B ${build}-none
                  ${common} -DCMAKE_PREFIX_PATH=${prefix_all} -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=TRUE)
  # ... while the core alone is found from the same prefix without it.
  run(${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/find_package -B ${build}-core ${common}
      -DCMAKE_PREFIX_PATH=${prefix_all} -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=TRUE
      -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=TRUE)
  run(${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/find_package_reach -B ${build} ${common}
      -DCMAKE_PREFIX_PATH=${prefix_all})
  run(${CMAKE_COMMAND} --build ${build} --target consumer)
  run(${build}/consumer)
  if(NOT last_output MATCHES "dmu-80p reach about Z: 0\\.000 to 90\\.000 degrees")
    message(FATAL_ERROR "unexpected output: ${last_output}")
  endif()
  message(STATUS "${MODE}: ${last_output}")
  return()
elseif(MODE STREQUAL "find_package")
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
