# Build-time proofs about the core library: which symbols it may not pull in,
# and how big it is.

set(KERF_SYMBOL_CHECK_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/check_symbols.cmake)

# After every build of `target`, scan its undefined symbols and fail the build
# on an allocator, an exception, stdio or a system call.
function(kerf_check_core_symbols target)
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DLIB=$<TARGET_FILE:${target}>
            -P ${KERF_SYMBOL_CHECK_SCRIPT}
    COMMENT "Checking ${target} for allocator, exception, stdio and OS symbols"
    VERBATIM)
endfunction()

# Prints the text/data/bss sizes of every object in the library.
function(kerf_print_size target)
  if(CMAKE_SIZE)
    add_custom_command(TARGET ${target} POST_BUILD
      COMMAND ${CMAKE_SIZE} -t $<TARGET_FILE:${target}>
      COMMENT "Code size of ${target}"
      VERBATIM)
  endif()
endfunction()

# After every build of the executable `target` (kerf), fail the build if it
# holds any kerf::sim:: or kerf::simulated:: symbol (check_no_sim.cmake).
function(kerf_check_no_sim target)
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DEXE=$<TARGET_FILE:${target}> -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/check_no_sim.cmake
    COMMENT "Checking ${target} for simulator symbols"
    VERBATIM)
endfunction()
