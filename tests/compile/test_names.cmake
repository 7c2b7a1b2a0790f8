# Fails when a Catch2 test name holds a `;`. catch_discover_tests reads the names as a CMake
# list, so such a name is cut at the `;` and its CTest entry runs a filter that matches no test
# case: the test would never run and always pass.
# Run as: cmake -DROOT=<source dir> -P test_names.cmake
cmake_minimum_required(VERSION 3.16)
file(GLOB_RECURSE sources "${ROOT}/tests/*.cpp")
set(bad "")
foreach(f ${sources})
  file(STRINGS "${f}" lines REGEX "TEST_CASE\\(\"")
  foreach(line IN LISTS lines)
    if(line MATCHES "TEST_CASE\\(\"[^\"]*;")
      file(RELATIVE_PATH rel "${ROOT}" "${f}")
      list(APPEND bad "${rel}")
    endif()
  endforeach()
endforeach()
if(bad)
  list(REMOVE_DUPLICATES bad)
  string(REPLACE ";" "\n  " bad "${bad}")
  message(FATAL_ERROR "a test name holds ';' (CTest would never run it) in:\n  ${bad}")
endif()
