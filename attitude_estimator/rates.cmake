# Rate estimation (project issue 8), included at the end of attitude_estimator/CMakeLists.txt.
#  - attitude_estimator_angular_rate: mean |ω| from successive estimates (004 eq. 4–5). Core style: float
#    and double, no heap, no exceptions (checked on the object code below), so it can go to the DSP.
#  - attitude_estimator_rates: spin frequencies from the FFT of the acquired sun vector (000 §4), on FFTW3.
#    Allocates once, in its constructor; push() and analyze() do not allocate. Links the one above too.
# The heap-free attitude_estimator_core is not touched.

pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
# attitude_estimator.fmu links this library, and an FMU binary may need nothing but the C runtime: link
# FFTW's static archive (Debian's is position-independent) when there is one, the shared library otherwise.
find_library(FFTW3_STATIC_LIBRARY NAMES libfftw3.a HINTS ${FFTW3_LIBRARY_DIRS})

add_library(attitude_estimator_angular_rate STATIC core/src/angular_rate.cpp)
target_include_directories(attitude_estimator_angular_rate PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/core/include)
target_compile_options(attitude_estimator_angular_rate PRIVATE -fno-exceptions)

add_library(attitude_estimator_rates STATIC core/src/spin_spectrum.cpp)
target_include_directories(attitude_estimator_rates PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/core/include)
target_link_libraries(attitude_estimator_rates PUBLIC attitude_estimator_angular_rate)
if(FFTW3_STATIC_LIBRARY)
  target_include_directories(attitude_estimator_rates PRIVATE ${FFTW3_INCLUDE_DIRS})
  target_link_libraries(attitude_estimator_rates PRIVATE ${FFTW3_STATIC_LIBRARY} m)
else()
  target_link_libraries(attitude_estimator_rates PRIVATE PkgConfig::FFTW3)
endif()

add_executable(attitude_estimator_rates_tests tests/spin_spectrum_test.cpp tests/angular_rate_test.cpp)
target_link_libraries(attitude_estimator_rates_tests PRIVATE attitude_estimator_rates
                      Eigen3::Eigen GTest::gtest_main)
target_include_directories(attitude_estimator_rates_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)  # malloc_counter.hpp, ordered_draws.hpp
gtest_discover_tests(attitude_estimator_rates_tests DISCOVERY_TIMEOUT 60)

add_test(NAME Rates.AngularRateNoHeapNoThrowSymbols
  COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DLIB=$<TARGET_FILE:attitude_estimator_angular_rate>
          -P ${CMAKE_CURRENT_SOURCE_DIR}/tests/check_no_heap_no_throw.cmake)

if(PVATT_BENCHMARKS)
  add_executable(attitude_estimator_rates_bench bench/rates_bench.cpp)
  target_link_libraries(attitude_estimator_rates_bench PRIVATE attitude_estimator_rates benchmark::benchmark)
endif()
