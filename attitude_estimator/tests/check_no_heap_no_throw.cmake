# Fails when the static library LIB references operator new/delete or the exception machinery anywhere,
# or the C allocator outside q_method.cpp.o (there also operator new and delete, clang's way to the same).
# Eigen's SelfAdjointEigenSolver template code keeps its generic dynamic-size branches (blocked Householder
# products) compiled in even for a fixed 4x4 matrix, so malloc/free are referenced from that object but never
# called — the runtime test EstimatorCoreNoAllocation proves it by counting malloc calls.
execute_process(COMMAND ${NM} -A -u ${LIB} OUTPUT_VARIABLE undefined RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${LIB}")
endif()
string(REPLACE "\n" ";" lines "${undefined}")
set(found "")
foreach(line IN LISTS lines)
  if(line MATCHES "q_method\\.cpp\\.o: +U (_Znwm|_ZdlPv|_ZdlPvm)$")
    # The same dynamic-size branches compiled by clang (the test build) allocate their temporaries with
    # operator new rather than malloc: referenced, never called (EstimatorCoreNoAllocation counts both).
  elseif(line MATCHES " U (_Znw|_Zna|_Zdl|_Zda|__cxa_throw|__cxa_allocate_exception|__cxa_begin_catch)")
    list(APPEND found "${line}")
  elseif(line MATCHES " U (malloc|calloc|realloc|free|aligned_alloc|posix_memalign|memalign)$"
         AND NOT line MATCHES "q_method\\.cpp\\.o:")
    list(APPEND found "${line}")
  endif()
endforeach()
if(found)
  string(REPLACE ";" "\n" found "${found}")
  message(FATAL_ERROR "attitude_estimator_core references heap or exception symbols:\n${found}")
endif()
message(STATUS "attitude_estimator_core: no operator new, no throw, no allocator outside Eigen's eigensolver")
