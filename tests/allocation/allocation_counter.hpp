#pragma once
// Counts every heap allocation the process makes while `counting` is set: operator new and the C
// allocator alike (Eigen's dynamic matrices call malloc and throw std::bad_alloc when it fails, so
// they are a throwing allocation too). Under AddressSanitizer, which owns malloc, through its
// allocation hook; otherwise by taking the C allocator's names in this executable (glibc lets a
// program replace them) and forwarding to glibc's own. Include this header from one file only: it
// defines the replacements.
#include <cstddef>

namespace stride::allocation_counter {
// Test-only counters: the allocator has nowhere else to report to.
inline thread_local bool counting = false;
inline thread_local long allocations = 0;
}  // namespace stride::allocation_counter

#if defined(__SANITIZE_ADDRESS__)
// sanitizer/allocator_interface.h, which the compiler's package does not always ship.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*,
                                                                             std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace stride::allocation_counter {
inline void on_malloc(const volatile void*, std::size_t) {
  if (counting) ++allocations;
}
inline void on_free(const volatile void*) {}
// Non-zero once installed (both hooks are required).
inline const int hook_installed = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
}  // namespace stride::allocation_counter

#else
extern "C" {
void* __libc_malloc(std::size_t) noexcept;
void* __libc_calloc(std::size_t, std::size_t) noexcept;
void* __libc_realloc(void*, std::size_t) noexcept;
void __libc_free(void*) noexcept;

void* malloc(std::size_t n) noexcept {
  if (stride::allocation_counter::counting) ++stride::allocation_counter::allocations;
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) noexcept {
  if (stride::allocation_counter::counting) ++stride::allocation_counter::allocations;
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) noexcept {
  if (stride::allocation_counter::counting) ++stride::allocation_counter::allocations;
  return __libc_realloc(p, n);
}
void free(void* p) noexcept {
  __libc_free(p);
}
}
#endif
