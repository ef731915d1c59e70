// No heap on the target.
//
// The link redirects every allocator entry point (malloc, free, calloc, realloc, their
// reentrant _r forms, _sbrk, operator new) here with -Wl,--wrap (cmake/facet.cmake). These
// stand-ins live in section .facet_heap_forbidden; with --gc-sections that section is empty
// unless something calls one of them, and the linker script refuses a non-empty one:
//   "facet: heap use (malloc/new/_sbrk) is forbidden on the target"
// So a heap allocation anywhere in the firmware, ours or a library's, fails the link.
#include <cstddef>

#define FORBIDDEN __attribute__((section(".facet_heap_forbidden"), noinline))

extern "C" {
FORBIDDEN void* __wrap_malloc(size_t) { return nullptr; }
FORBIDDEN void __wrap_free(void*) {}
FORBIDDEN void* __wrap_calloc(size_t, size_t) { return nullptr; }
FORBIDDEN void* __wrap_realloc(void*, size_t) { return nullptr; }
FORBIDDEN void* __wrap__malloc_r(void*, size_t) { return nullptr; }
FORBIDDEN void __wrap__free_r(void*, void*) {}
FORBIDDEN void* __wrap__calloc_r(void*, size_t, size_t) { return nullptr; }
FORBIDDEN void* __wrap__realloc_r(void*, void*, size_t) { return nullptr; }
FORBIDDEN void* __wrap__sbrk(ptrdiff_t) { return reinterpret_cast<void*>(-1); }
FORBIDDEN void* __wrap__sbrk_r(void*, ptrdiff_t) { return reinterpret_cast<void*>(-1); }
FORBIDDEN void* __wrap__Znwj(size_t) { return nullptr; }
FORBIDDEN void* __wrap__Znaj(size_t) { return nullptr; }
FORBIDDEN void* __wrap__ZnwjRKSt9nothrow_t(size_t, const void*) { return nullptr; }
FORBIDDEN void* __wrap__ZnajRKSt9nothrow_t(size_t, const void*) { return nullptr; }
}
