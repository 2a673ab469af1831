// Mapping a large buffer's pages in one system call before it is filled.
#pragma once

#include <cstddef>

namespace kerf::io {

// Asks the OS to map [p, p + bytes) writable now (Linux: MADV_POPULATE_WRITE),
// where it would otherwise take a page fault per 4 KiB page as it is first
// written: on a virtual machine a fault costs ~10 us, and faults were most
// of the time `kerf weld` took to read a large file. Only whole pages inside
// the range, only for large ranges; a no-op where unsupported (the faults
// then happen as before).
void prefault(const void* p, std::size_t bytes);

// Asks the OS to back the 2 MiB-aligned whole huge pages inside [p, p +
// bytes) with huge pages as they are first written (Linux: MADV_HUGEPAGE;
// transparent huge pages in "madvise" mode or "always"): one fault and one
// zeroing per 2 MiB instead of a fault per 4 KiB. Filling 14 MB took 8 ms
// of page faults, 1.2 ms this way. For large buffers that will mostly be
// written (a whole file's blocks); a no-op elsewhere.
void prefer_huge_pages(const void* p, std::size_t bytes);

// For a short-lived program that fills a few tens of MB (kerf weld): the
// C library's heap is grown `bytes` ahead at once, large blocks come from it
// too, and all of it prefers huge pages (prefer_huge_pages). Call it first
// thing, once. A no-op outside glibc on Linux.
void use_huge_page_heap(std::size_t bytes);

}  // namespace kerf::io
