// SPDX-License-Identifier: GPL-3.0-or-later
#include "grid/NodeArray.hpp"

#include <cstdint>
#include <cstring>
#include <new>
#include <sys/mman.h>
#include <unistd.h>

namespace mpm {

namespace {

std::size_t pageSize() {
    static const std::size_t size = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return size;
}

} // namespace

void* reserveZeroed(std::size_t bytes) {
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    // Huge pages would commit 2 MiB at the first write of any node of it: sparsity wants 4 KiB.
    madvise(p, bytes, MADV_NOHUGEPAGE);
    return p;
}

void releaseMapping(void* p, std::size_t bytes) {
    if (p) munmap(p, bytes);
}

void zeroAndRelease(void* p, std::size_t bytes) {
    if (bytes == 0) return;
    const std::size_t page = pageSize();
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t end = begin + bytes;
    const std::uintptr_t first = (begin + page - 1) / page * page; // first whole page
    const std::uintptr_t last = end / page * page;                 // end of the last whole page
    if (first >= last) {
        std::memset(p, 0, bytes);
        return;
    }
    std::memset(p, 0, first - begin);
    std::memset(reinterpret_cast<void*>(last), 0, end - last);
    // Private anonymous pages read as zero after MADV_DONTNEED.
    madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
}

} // namespace mpm
