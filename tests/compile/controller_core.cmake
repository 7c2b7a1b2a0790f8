# Fails when the controller-grade kinematics calls (controller_core.cpp: forward, the inverses,
# the machine lookup, kin5kins' LinuxCNC mapping), compiled as a realtime module is, with
# -fno-exceptions -fno-rtti, need any symbol of the C++ library: an allocation (_Znw, _Znam),
# an exception or guard helper (__cxa_*, __gxx_*, _Unwind_*) or any other C++ function that is
# not compiled into the object itself (an undefined _Z symbol). The same source with
# KIN5_CONTROLLER_NEGATIVE (one std::string) must be caught, or the check proves nothing.
# Run as: cmake -DCXX=... -DINCLUDE=.../include -DSOURCE=controller_core.cpp -DKINS=.../tools/kin5kins
#         -DNM=nm -DWORK=<dir> -P controller_core.cmake
set(flags -std=c++20 -Os -fPIC -fno-exceptions -fno-rtti -fno-threadsafe-statics -Wall -Werror -I${INCLUDE} -I${KINS})

function(undefined_cxx_symbols out_var object)
  execute_process(COMMAND ${NM} -u ${object} OUTPUT_VARIABLE syms RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nm -u ${object} failed: ${err}")
  endif()
  string(REGEX MATCHALL "[ \t](_Z[^ \t\n]*|__cxa_[^ \t\n]*|__gxx_[^ \t\n]*|_Unwind_[^ \t\n]*)" found "${syms}")
  set(${out_var} "${found}" PARENT_SCOPE)
endfunction()

function(compile object)
  execute_process(COMMAND ${CXX} ${flags} ${ARGN} -c ${SOURCE} -o ${object} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "controller_core.cpp does not compile with -fno-exceptions -fno-rtti: ${err}")
  endif()
endfunction()

file(MAKE_DIRECTORY ${WORK})
compile(${WORK}/controller_core.o)
undefined_cxx_symbols(found ${WORK}/controller_core.o)
if(found)
  message(FATAL_ERROR "the controller-grade kinematics calls need the C++ library:${found}")
endif()
compile(${WORK}/controller_core_negative.o -DKIN5_CONTROLLER_NEGATIVE)
undefined_cxx_symbols(found ${WORK}/controller_core_negative.o)
if(NOT found)
  message(FATAL_ERROR "the check missed the std::string of KIN5_CONTROLLER_NEGATIVE: it would miss any other")
endif()
message(STATUS "the controller-grade calls need no C++ library symbol (the negative control needs:${found})")
