# Build settings for the test programs only (every executable that links GoogleTest), to shorten the test
# build (scripts/test.sh; CONTRIBUTING.md, "CI and its time"). The libraries, blocks and FMUs the tests
# exercise keep the build's own flags. Both settings are off by default and on in the sanitize preset.
#
# PVATT_TEST_PCH: <gtest/gtest.h> and Eigen (Dense, Geometry) are compiled once (host: pvatt_test_pch) and
# every test program reuses them (REUSE_FROM). Parsing them costs a test translation unit about 1.5 s (GoogleTest)
# and 2 s (Eigen, which half the test files include) of CPU under the sanitizers. The host is an
# executable so that its flags (-fPIE, sanitizers, standard, optimization) are the test programs' own: a
# compiler refuses a header made with other flags (clang with an error; GCC, the release build's compiler,
# with -Winvalid-pch, which -Werror makes one). The release build compiles every test without it, which keeps
# each file's includes honest.
#
# PVATT_TEST_OPTIMIZE: the optimization of the test programs' own sources (e.g. -O1 in the sanitize preset),
# and of the Google Benchmark programs' (the test build only compiles those: a benchmark that does not
# compile is a bug, but a sanitized build is no place to time one):
# GoogleTest's expanded assertions make a test file one of the costliest to optimize under ASan and UBSan
# (-O1 compiles them a quarter to a third faster), while the time a test runs is spent in the libraries and
# FMUs it calls, which stay at -O2. The checks are the same: ASan and UBSan instrument at every level, and
# without -ffast-math or FMA the arithmetic gives the same bits at -O1 and -O2.
option(PVATT_TEST_PCH "Precompile <gtest/gtest.h> once for all test programs (faster test build)" OFF)
set(PVATT_TEST_OPTIMIZE "" CACHE STRING "Optimization flag for the test programs' own sources (empty: the build type's)")

set(pvatt_test_programs)
set(pvatt_benchmark_programs)
pvatt_targets_below(${PROJECT_SOURCE_DIR} pvatt_all_targets)
foreach(target IN LISTS pvatt_all_targets)
  get_target_property(type ${target} TYPE)
  if(NOT type STREQUAL "EXECUTABLE")
    continue()
  endif()
  get_target_property(links ${target} LINK_LIBRARIES)
  if("GTest::gtest_main" IN_LIST links OR "GTest::gtest" IN_LIST links)
    list(APPEND pvatt_test_programs ${target})
  elseif("benchmark::benchmark" IN_LIST links OR "benchmark::benchmark_main" IN_LIST links)
    list(APPEND pvatt_benchmark_programs ${target})
  endif()
endforeach()

if(PVATT_TEST_PCH)
  add_executable(pvatt_test_pch ${CMAKE_CURRENT_LIST_DIR}/pch/test_pch_host.cpp)
  target_link_libraries(pvatt_test_pch PRIVATE GTest::gtest_main Eigen3::Eigen)
  target_precompile_headers(pvatt_test_pch PRIVATE <gtest/gtest.h> <Eigen/Dense> <Eigen/Geometry>)
  if(PVATT_TEST_OPTIMIZE)
    target_compile_options(pvatt_test_pch PRIVATE ${PVATT_TEST_OPTIMIZE})
  endif()
endif()
foreach(target IN LISTS pvatt_test_programs pvatt_benchmark_programs)
  if(PVATT_TEST_OPTIMIZE)
    target_compile_options(${target} PRIVATE ${PVATT_TEST_OPTIMIZE})
  endif()
  if(PVATT_TEST_PCH AND target IN_LIST pvatt_test_programs)
    target_precompile_headers(${target} REUSE_FROM pvatt_test_pch)
  endif()
endforeach()
