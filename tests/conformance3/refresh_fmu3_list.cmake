# Runs inside ctest before the gtest test list is read: drops the cached list so that every ctest run
# lists the FMI 3.0 archives afresh (as tests/conformance/refresh_fmu_list.cmake does for 2.0).
file(GLOB stale_lists "${CMAKE_CURRENT_LIST_DIR}/conformance3_tests*_tests.cmake")
if(stale_lists)
  file(REMOVE ${stale_lists})
endif()
