# The consumer writes its translated program (and the source it translated) to WORK; the tool
# translates the same source for the same machines to stdout; the two must be the same bytes.
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CONSUMER} ${MACHINE_FILE} ${WORK}/from_c.h RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the C consumer failed (${rc})")
endif()
execute_process(COMMAND ${TOOL} translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 ${WORK}/from_c.h.mpf
                OUTPUT_FILE ${WORK}/from_tool.h RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "kin5 translate failed (${rc})")
endif()
file(READ ${WORK}/from_c.h from_c)
file(READ ${WORK}/from_tool.h from_tool)
if(NOT from_c STREQUAL from_tool)
  message(FATAL_ERROR "the library's translation differs from the tool's:\n--- C\n${from_c}\n--- tool\n${from_tool}")
endif()
string(LENGTH "${from_c}" n)
message(STATUS "the same ${n} bytes")
