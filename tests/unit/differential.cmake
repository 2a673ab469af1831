# Differential and verified-output tests: core against the brute-force twin
# and the independent verifier in tests/support (kerf_test_support, which
# shares no code with core). Included from tests/unit/CMakeLists.txt.
add_executable(kerf_differential_tests
  assert_handler.cpp
  test_differential.cpp
  test_verified_outputs.cpp
  test_edge_cases.cpp
)
target_link_libraries(kerf_differential_tests PRIVATE kerf_io kerf_test_support GTest::gtest_main)
target_compile_definitions(kerf_differential_tests PRIVATE
  KERF_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/../data")
kerf_warnings(kerf_differential_tests)
kerf_gtests(kerf_differential_tests component)

# The band fitter against the band referee (checker and twin) in tests/support.
add_executable(kerf_band_tests
  assert_handler.cpp
  test_band_differential.cpp
  test_band_fit.cpp
)
target_link_libraries(kerf_band_tests PRIVATE kerf_io kerf_test_support GTest::gtest_main)
target_include_directories(kerf_band_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
target_compile_definitions(kerf_band_tests PRIVATE
  KERF_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/../data")
kerf_warnings(kerf_band_tests)
kerf_gtests(kerf_band_tests component)

# The biarc fitter against its referee (biarc checker and twin) in tests/support.
add_executable(kerf_biarc_tests
  assert_handler.cpp
  test_biarc_fit.cpp
  test_biarc_exact.cpp
)
target_link_libraries(kerf_biarc_tests PRIVATE kerf_io kerf_test_support GTest::gtest_main)
target_include_directories(kerf_biarc_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
kerf_warnings(kerf_biarc_tests)
kerf_gtests(kerf_biarc_tests component)

# The paper's biarc pair test (visibility regions, Lemmas 3.3-3.7) against
# the exact joint sets.
add_executable(kerf_biarc_paper_tests
  assert_handler.cpp
  test_biarc_paper.cpp
)
target_link_libraries(kerf_biarc_paper_tests PRIVATE kerf_io kerf_test_support GTest::gtest_main)
target_include_directories(kerf_biarc_paper_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
kerf_warnings(kerf_biarc_paper_tests)
kerf_gtests(kerf_biarc_paper_tests component)
