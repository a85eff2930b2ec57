# Runs inside ctest before the gtest test list is read. gtest_discover_tests (PRE_TEST) caches the
# list until the executable changes, but the list of FMUs changes without it (another FMU built, or
# PVATT_FMU_DIR pointed elsewhere): drop the cache so every ctest run lists the FMUs afresh.
file(GLOB stale_lists "${CMAKE_CURRENT_LIST_DIR}/conformance_tests*_tests.cmake")
if(stale_lists)
  file(REMOVE ${stale_lists})
endif()
