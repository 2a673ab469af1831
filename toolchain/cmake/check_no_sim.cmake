# cmake -DNM=<nm> -DEXE=<executable> -P check_no_sim.cmake
# Fails (exit 1, naming them) when the executable holds any symbol of the
# simulator (kerf::sim::, kerf::simulated::): what ships as `kerf` must not be
# able to run on scripted lines or a simulated board.
if(NOT NM OR NOT EXE)
  message(FATAL_ERROR "usage: cmake -DNM=<nm> -DEXE=<executable> -P check_no_sim.cmake")
endif()
execute_process(COMMAND ${NM} -C ${EXE} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} -C ${EXE} failed (${rc})")
endif()
string(REGEX MATCHALL "[^\n]*kerf::sim(ulated)?::[^\n]*" found "${out}")
if(found)
  list(LENGTH found n)
  list(SUBLIST found 0 10 first)
  foreach(line IN LISTS first)
    message("sim symbol: ${line}")
  endforeach()
  message(FATAL_ERROR "${EXE} holds ${n} simulator symbols (the first listed above): it must link no kerf_sim*, no firmware/simulated")
endif()
message(STATUS "${EXE}: no simulator symbols")
