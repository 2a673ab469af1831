# Test tiers: every ctest test carries exactly one tier label, so that a preset
# can pick what it runs (ctest -L). Configuration fails on a test without one.
#
#   unit       one library, in-process
#   component  several pieces together, or one run of one kerf command
#   system     whole jobs, simulator runs, HIL, golden corpora, install and .deb
#   fuzz       the libFuzzer targets (preset fuzz)
#
# A second label, `target`, marks tests whose result can differ by target
# (core arithmetic, fixed point, the links, the journal, packaging): the cross
# presets run only those. Other labels (cli, pack, hil, ...) may stay alongside.
set(KERF_TEST_TIERS unit component system fuzz)

function(kerf_check_tier_name tier)
  if(NOT tier IN_LIST KERF_TEST_TIERS)
    message(FATAL_ERROR "kerf: unknown test tier \"${tier}\" (expected one of ${KERF_TEST_TIERS})")
  endif()
endfunction()

# What the `target` tests need. A cross build makes it part of `all` and
# leaves the other test programs out of `all` (tests/CMakeLists.txt): its
# presets run only the `target` tests.
if(CMAKE_CROSSCOMPILING)
  add_custom_target(kerf_target_tests ALL)
else()
  add_custom_target(kerf_target_tests)
endif()

# kerf_test_tier(<tier> [TARGET] <test>... [NEEDS <build target>...]): labels
# tests made with add_test. NEEDS names what a `target` test runs.
function(kerf_test_tier tier)
  cmake_parse_arguments(PARSE_ARGV 1 arg "TARGET" "" "NEEDS")
  kerf_check_tier_name(${tier})
  set(labels ${tier})
  set(tests ${arg_UNPARSED_ARGUMENTS})
  if(arg_TARGET)
    list(APPEND labels target)
    if(arg_NEEDS)
      add_dependencies(kerf_target_tests ${arg_NEEDS})
    endif()
  endif()
  set_property(TEST ${tests} APPEND PROPERTY LABELS ${labels})
  foreach(test IN LISTS tests)
    set_property(GLOBAL APPEND PROPERTY "kerf_tier:${CMAKE_CURRENT_SOURCE_DIR}|${test}" ${tier})
  endforeach()
endfunction()

# kerf_gtests(<executable> <tier> [TARGET] [FILTER <gtest filter>] [TIMEOUT <s>]
#             [TEST_PREFIX <prefix>] [THREADS <regex>] [LABELS <label>...]): gtest_discover_tests
# (at test time, so that cross builds list the tests under their emulator)
# with the tier's labels. Call it once per filter to give parts of one binary
# different tiers. THREADS: the tests whose name matches run threads and get
# the label `threads` too (the tsan preset runs those, and builds only their
# executables: KERF_THREAD_TEST_TARGETS in CMakePresets.json's tsan build).
# LABELS: more labels for every test, e.g. `corpus` (whole real files) or
# `scale` (generated jobs of 1e5 lines and more, for memory bounds): the
# debug-asan preset leaves those out, see tests/README.md).
function(kerf_gtests exe tier)
  cmake_parse_arguments(PARSE_ARGV 2 arg "TARGET" "FILTER;TIMEOUT;TEST_PREFIX;THREADS" "LABELS")
  kerf_check_tier_name(${tier})
  set(labels ${tier} ${arg_LABELS})
  if(arg_TARGET)
    list(APPEND labels target)
    add_dependencies(kerf_target_tests ${exe})
  endif()
  get_property(calls TARGET ${exe} PROPERTY KERF_TEST_TIER)
  list(LENGTH calls n)
  set(list_var ${exe}_tier${n}_tests)
  set(extra TEST_LIST ${list_var})
  if(arg_FILTER)
    list(APPEND extra TEST_FILTER ${arg_FILTER})
  endif()
  if(arg_TEST_PREFIX)
    list(APPEND extra TEST_PREFIX ${arg_TEST_PREFIX})
  endif()
  if(arg_TIMEOUT)
    list(APPEND extra PROPERTIES TIMEOUT ${arg_TIMEOUT})
  endif()
  gtest_discover_tests(${exe} DISCOVERY_MODE PRE_TEST ${extra})
  # The labels go on in a file ctest reads after the discovered list: a list
  # value (unit;target) does not survive gtest_discover_tests' PROPERTIES.
  set(labels_file ${CMAKE_CURRENT_BINARY_DIR}/${list_var}_labels.cmake)
  # (A test program a cross build leaves out is listed as <exe>_NOT_BUILT, unlabelled.)
  file(WRITE ${labels_file} "if(DEFINED ${list_var})\n"
       "  set_tests_properties(\${${list_var}} PROPERTIES LABELS \"${labels}\")\n")
  if(arg_THREADS)
    file(APPEND ${labels_file} "  foreach(t IN LISTS ${list_var})\n"
         "    if(t MATCHES \"${arg_THREADS}\")\n"
         "      set_tests_properties(\${t} PROPERTIES LABELS \"${labels};threads\")\n"
         "    endif()\n  endforeach()\n")
  endif()
  file(APPEND ${labels_file} "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${labels_file})
  set_property(TARGET ${exe} APPEND PROPERTY KERF_TEST_TIER ${tier})
endfunction()

# Fails configuration on a test that did not get exactly one tier through
# kerf_test_tier, walking every directory under `dir`. Tests that
# gtest_discover_tests finds at test time are checked through their
# executable: it must have gone through kerf_gtests.
function(kerf_require_test_tiers dir)
  get_property(tests DIRECTORY ${dir} PROPERTY TESTS)
  foreach(test IN LISTS tests)
    get_property(tiers GLOBAL PROPERTY "kerf_tier:${dir}|${test}")
    list(LENGTH tiers n)
    if(NOT n EQUAL 1)
      message(FATAL_ERROR "kerf: test ${test} (${dir}) has ${n} tiers (${tiers}): give it exactly one "
                          "with kerf_test_tier() (toolchain/cmake/KerfTestTiers.cmake)")
    endif()
  endforeach()
  get_property(includes DIRECTORY ${dir} PROPERTY TEST_INCLUDE_FILES)
  foreach(file IN LISTS includes)
    if(file MATCHES "/([^/]+)\\[[0-9]+\\]_include\\.cmake$")
      get_property(tier TARGET ${CMAKE_MATCH_1} PROPERTY KERF_TEST_TIER)
      if(NOT tier)
        message(FATAL_ERROR "kerf: the gtests of ${CMAKE_MATCH_1} (${dir}) have no tier: "
                            "discover them with kerf_gtests(), not gtest_discover_tests()")
      endif()
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    kerf_require_test_tiers(${sub})
  endforeach()
endfunction()
