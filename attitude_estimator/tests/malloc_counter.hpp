// Replaces the C allocator of the test program that includes this header (in ONE source file of that
// program) by counting wrappers around glibc's own functions, so a test can assert that a piece of code
// never allocates: read allocation_count() before and after. Under AddressSanitizer, which owns malloc
// itself, nothing is replaced and PVATT_COUNT_MALLOC is 0: such tests skip.
#pragma once

#include <atomic>
#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
#define PVATT_COUNT_MALLOC 0
#else
#define PVATT_COUNT_MALLOC 1
namespace malloc_counter {
inline std::atomic<long> allocations{0};
}
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);
void* malloc(std::size_t n) {
    malloc_counter::allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t s) {
    malloc_counter::allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_calloc(n, s);
}
void* realloc(void* p, std::size_t n) {
    malloc_counter::allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_realloc(p, n);
}
void free(void* p) {
    __libc_free(p);
}
}
#endif

// Allocator calls so far (0 when not counting).
inline long allocation_count() {
#if PVATT_COUNT_MALLOC
    return malloc_counter::allocations.load(std::memory_order_relaxed);
#else
    return 0;
#endif
}
