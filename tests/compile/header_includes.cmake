# kin5_included_headers(HEADER OUT): the `.hpp` files HEADER pulls in when compiled alone
# (`${CXX} -M`), each as an absolute path without `..` (`program/siemens/../dialect.hpp` is
# `program/dialect.hpp`). Stops the script when HEADER does not compile alone. For the `*_deps`
# scripts, run with -DCXX=... -DINCLUDE=.../include.
function(kin5_included_headers header out)
  execute_process(
    COMMAND ${CXX} -std=c++20 -M -I ${INCLUDE} ${header}
    OUTPUT_VARIABLE deps RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    file(RELATIVE_PATH shown "${INCLUDE}" "${header}")
    message(FATAL_ERROR "${shown} does not compile alone: ${err}")
  endif()
  string(REPLACE "\\\n" " " deps "${deps}")
  string(REGEX MATCHALL "[^ \t\n]+\\.hpp" included "${deps}")
  set(paths "")
  foreach(path ${included})
    get_filename_component(path "${path}" ABSOLUTE)
    list(APPEND paths "${path}")
  endforeach()
  set(${out} "${paths}" PARENT_SCOPE)
endfunction()
