// Counts the allocator calls of the test program that includes this header (in ONE source file of that
// program), so a test can assert that a piece of code never allocates: read allocation_count() before and
// after. Every allocation of the process is seen, those of an FMU's shared library included.
// - A plain build replaces the C allocator by counting wrappers around glibc's own functions.
// - Under AddressSanitizer, which owns malloc, the sanitizer's allocation hook counts instead
//   (__sanitizer_install_malloc_and_free_hooks, exported by the ASan runtime; GCC ships no header for it).
#pragma once

#include <atomic>
#include <cstddef>

#define PVATT_COUNT_MALLOC 1
namespace malloc_counter {
inline std::atomic<long> allocations{0};
}

// GCC says AddressSanitizer with __SANITIZE_ADDRESS__, clang with __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define PVATT_MALLOC_COUNTER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PVATT_MALLOC_COUNTER_ASAN 1
#endif
#endif

#if defined(PVATT_MALLOC_COUNTER_ASAN)
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));
namespace malloc_counter {
inline void count_allocation(const volatile void*, std::size_t) {
    allocations.fetch_add(1, std::memory_order_relaxed);
}
inline void ignore_free(const volatile void*) {}
// Installed before main(): the sanitizer allows a few hook pairs per process.
inline const int hooks_installed = __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_free);
}  // namespace malloc_counter
#else
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

// Allocator calls so far.
inline long allocation_count() {
    return malloc_counter::allocations.load(std::memory_order_relaxed);
}
