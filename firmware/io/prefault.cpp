#include "io/prefault.hpp"

#include <algorithm>
#include <cstdint>

#if defined(__linux__) && __has_include(<sys/mman.h>)
#include <sys/mman.h>
#endif
#if defined(__GLIBC__) && __has_include(<malloc.h>)
#include <malloc.h>
#include <unistd.h>

#include <cstdlib>
#define KERF_GLIBC_HEAP 1
#endif

namespace kerf::io {

void prefault(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::size_t kPage = 4096;
  constexpr std::size_t kWorthIt = 16 * kPage;
  if (p == nullptr || bytes < kWorthIt) return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kPage - 1) / kPage * kPage;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) / kPage * kPage;
  if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)p;
  (void)bytes;
#endif
}

void prefer_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (p == nullptr || bytes < kHuge) return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) / kHuge * kHuge;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) / kHuge * kHuge;
  if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

void use_huge_page_heap(std::size_t bytes) {
#if defined(KERF_GLIBC_HEAP) && defined(MADV_HUGEPAGE)
  const int size = static_cast<int>(std::min<std::size_t>(bytes, std::size_t{1} << 30));
  // Blocks up to 32 MiB (glibc's largest threshold on 64 bits) from the
  // heap, not a mapping each; the heap grown `size` ahead and not given back
  // as it shrinks. Each is a hint: one refused leaves the others.
  (void)mallopt(M_MMAP_THRESHOLD, std::min(size, 32 << 20));
  if (mallopt(M_TOP_PAD, size) == 0) return;
  (void)mallopt(M_TRIM_THRESHOLD, 2 * size);
  char* const before = static_cast<char*>(sbrk(0));
  void* grow = std::malloc(std::size_t{256} << 10);  // more than the heap has free: it grows
  char* const after = static_cast<char*>(sbrk(0));
  if (grow != nullptr && before != reinterpret_cast<char*>(-1) && after > before)
    prefer_huge_pages(before, static_cast<std::size_t>(after - before));
  std::free(grow);
#else
  (void)bytes;
#endif
}

}  // namespace kerf::io
