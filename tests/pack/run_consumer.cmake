# Checks the output of the consumer program (tests/pack/consumer/main.cpp):
# it ran, exited 0, and printed the one-arc fit.
#   run_consumer.cmake is included by check_consumer.cmake and check_pkgconfig.cmake
function(kerf_run_consumer exe emulator)
  execute_process(COMMAND ${emulator} ${exe} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${exe} failed (${rc}):\n${out}${err}")
  endif()
  if(NOT out MATCHES "Number of arcs is Narc = 1\nA \\(10,0\\) ")
    message(FATAL_ERROR "${exe}: unexpected output:\n${out}")
  endif()
endfunction()
