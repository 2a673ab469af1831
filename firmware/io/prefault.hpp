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

}  // namespace kerf::io
