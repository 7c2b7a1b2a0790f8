# Fails when kin5/kinematics.hpp, the standard-library-only core, pulls in any header of the
# program or translation layers (or anything outside kin5 and the standard library).
# Run as: cmake -DCXX=... -DINCLUDE=.../include -P kinematics_deps.cmake
include(${CMAKE_CURRENT_LIST_DIR}/header_includes.cmake)
kin5_included_headers("${INCLUDE}/kin5/kinematics.hpp" headers)
set(bad "")
foreach(h ${headers})
  if(h MATCHES "/kin5/(program|translate|reach|paper)/" OR h MATCHES "/kin5/(eigen|reach|kin5)\\.hpp$")
    list(APPEND bad ${h})
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "kin5/kinematics.hpp must not include: ${bad}")
endif()
list(LENGTH headers n)
message(STATUS "kinematics.hpp pulls in ${n} kin5 headers, none of the program or translation layers")
