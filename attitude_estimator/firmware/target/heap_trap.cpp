// There is no heap. The link wraps the allocator (--wrap=malloc ...) onto these, which stop the processor:
// a call would be a bug, and the board would stop answering (the PIL test times out). The only references
// are Eigen's, in q_method.cpp: SelfAdjointEigenSolver keeps a heap branch for temporaries larger than
// EIGEN_STACK_ALLOCATION_LIMIT, which a 4x4 problem never reaches (its temporaries are 4 values, on the
// stack). check_heap_references.cmake holds the link map to exactly that after every build.
#include <cstddef>

extern "C" {
[[noreturn]] void fault_handler();
[[noreturn]] void* __wrap_malloc(std::size_t) {
    fault_handler();
}
[[noreturn]] void __wrap_free(void*) {
    fault_handler();
}
}
