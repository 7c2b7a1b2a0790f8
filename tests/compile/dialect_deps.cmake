# Fails when a dialect's header, `kin5/program/<name>/dialect.hpp` compiled alone, pulls in
# another dialect's header or the list of all of them (`kin5/program/dialect.hpp`): a test or a
# program that uses one dialect then compiles that one only. A folder may use another folder's
# reader or writer (Haas and LinuxCNC build on ISO's), not its `dialect`.
# The exception, named here: APT's CL writer asks the source dialect's controller and kept words
# (`controller_from`, `lost_from`), which the list defines, so `apt/dialect.hpp` includes it.
# Run as: cmake -DCXX=... -DINCLUDE=.../include -P dialect_deps.cmake
cmake_minimum_required(VERSION 3.16)
include(${CMAKE_CURRENT_LIST_DIR}/header_includes.cmake)
set(needs_the_list apt)
file(GLOB headers "${INCLUDE}/kin5/program/*/dialect.hpp")
if(NOT headers)
  message(FATAL_ERROR "no kin5/program/<name>/dialect.hpp under ${INCLUDE}")
endif()
set(bad "")
foreach(header ${headers})
  get_filename_component(folder "${header}" DIRECTORY)
  get_filename_component(name "${folder}" NAME)
  if(name IN_LIST needs_the_list)
    continue()
  endif()
  kin5_included_headers("${header}" included)
  foreach(path ${included})
    if(path MATCHES "/kin5/program/([a-z0-9_]+/)?dialect\\.hpp$"
       AND NOT path MATCHES "/kin5/program/${name}/dialect\\.hpp$")
      string(REGEX REPLACE ".*/(kin5/program/)" "\\1" shown "${path}")
      list(APPEND bad "kin5/program/${name}/dialect.hpp includes ${shown}")
    endif()
  endforeach()
endforeach()
list(LENGTH headers n)
if(bad)
  list(REMOVE_DUPLICATES bad)
  string(REPLACE ";" "\n  " bad "${bad}")
  message(FATAL_ERROR "a dialect's header pulls in another dialect (its id is `id_named(\"name\")`, "
                      "program/dialect_id.hpp):\n  ${bad}")
endif()
message(STATUS "${n} dialect headers; none but ${needs_the_list} pulls in another dialect or the list")
