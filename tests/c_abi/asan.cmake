# Configures and builds c_abi/asan (the library and the consumer with AddressSanitizer and
# UBSan) in WORK, then runs the consumer; any report of the sanitizers fails it. The build
# compiles the library's one source once more (a minute or two); later runs reuse it.
foreach(v SOURCE WORK GENERATOR CC CXX MACHINE_FILE)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "asan.cmake needs -D${v}=...")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/tests/c_abi/asan -B ${WORK} -G ${GENERATOR}
                        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=${CC} -DCMAKE_CXX_COMPILER=${CXX}
                        -DKIN5_SOURCE=${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the ASan build failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the ASan build failed:\n${out}")
endif()
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0:halt_on_error=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
execute_process(COMMAND ${WORK}/kin5_c_consumer ${MACHINE_FILE} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the C consumer under AddressSanitizer failed (${rc})")
endif()
