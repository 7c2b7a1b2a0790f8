# Fails when a header of the canonical operations, `kin5/program/canonical/*.hpp` compiled alone,
# pulls in a dialect's folder, the interpreter, the list of dialects (`program/dialect.hpp`,
# `program/io.hpp`) or the translation: the operations need the block model only, so a test or
# a program that uses them compiles no reader or writer.
# Run as: cmake -DCXX=... -DINCLUDE=.../include -P canonical_deps.cmake
cmake_minimum_required(VERSION 3.16)
include(${CMAKE_CURRENT_LIST_DIR}/header_includes.cmake)
file(GLOB headers "${INCLUDE}/kin5/program/canonical/*.hpp")
if(NOT headers)
  message(FATAL_ERROR "no kin5/program/canonical/*.hpp under ${INCLUDE}")
endif()
set(bad "")
foreach(header ${headers})
  get_filename_component(name "${header}" NAME)
  kin5_included_headers("${header}" included)
  foreach(path ${included})
    if((path MATCHES "/kin5/program/[a-z_]+/" AND NOT path MATCHES "/kin5/program/canonical/")
       OR path MATCHES "/kin5/program/(dialect|io)\\.hpp$" OR path MATCHES "/kin5/translate/")
      list(APPEND bad "${name} includes ${path}")
    endif()
  endforeach()
endforeach()
if(bad)
  list(JOIN bad "\n  " text)
  message(FATAL_ERROR "a canonical header pulls in more than the block model:\n  ${text}")
endif()
list(LENGTH headers n)
message(STATUS "${n} canonical headers, none pulling in a dialect, the interpreter or the translation")
