# systemd's own check of firmware/systemd/kerf.service. systemd-analyze only
# warns about a bad value (exit code 0), so any output fails the test. It
# also wants ExecStart's binary to exist: the copy checked here runs an
# executable that does (this cmake), the rest of the unit is unchanged.
# To show that the check can fail, a copy with a misspelt value must give a
# message.
#   cmake -DANALYZE=systemd-analyze -DUNIT=kerf.service -DWORK=dir -P verify_unit.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/good ${WORK}/bad)
file(READ ${UNIT} text)
string(REPLACE "/usr/bin/kerf " "${CMAKE_COMMAND} " text "${text}")
file(WRITE ${WORK}/good/kerf.service "${text}")
string(REPLACE "Restart=no" "Restart=never" bad "${text}")
file(WRITE ${WORK}/bad/kerf.service "${bad}")

function(verify dir out_var)
  execute_process(COMMAND ${ANALYZE} verify --man=no ${dir}/kerf.service
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_var} "rc=${rc}\n${out}${err}" PARENT_SCOPE)
  if(rc EQUAL 0 AND "${out}${err}" STREQUAL "")
    set(${out_var} "" PARENT_SCOPE)
  endif()
endfunction()

verify(${WORK}/good good_messages)
if(NOT good_messages STREQUAL "")
  message(FATAL_ERROR "systemd-analyze verify ${UNIT}:\n${good_messages}")
endif()
verify(${WORK}/bad bad_messages)
if(NOT bad_messages MATCHES "Restart|restart")
  message(FATAL_ERROR "systemd-analyze did not report a misspelt Restart=: '${bad_messages}'")
endif()
message(STATUS "systemd-analyze verify: ${UNIT} is clean")
