// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <cstddef>
#include <type_traits>
#include <utility>

namespace mpm {

/// Reserve `bytes` of zero-filled address space that the operating system commits page by page
/// on first write (anonymous private mapping, no swap reservation, no huge pages); throws
/// std::bad_alloc when the address space is refused.
void* reserveZeroed(std::size_t bytes);
/// Give back the mapping of reserveZeroed.
void releaseMapping(void* p, std::size_t bytes);
/// Zero the bytes [p, p + bytes) of a reserveZeroed mapping: the pages wholly inside are handed
/// back to the system (they read as zero and cost no memory until written again), the partial
/// pages at the ends are written with zeros.
void zeroAndRelease(void* p, std::size_t bytes);

/// A field of the sparse grid (docs/sparseGrid.md): one T per node of the whole
/// box, zero-initialised, whose memory follows the material. The array is reserved for every
/// node of the box but only the pages written are committed, so a box of 10⁸ cells costs
/// address space, not memory, where no material is; release() hands the pages of blocks the
/// material has left back to the system. T must be plain data, with all-zero bytes
/// meaning zero and no destructor (double, fixed-size Eigen vectors of double, char).
template <class T> class NodeArray {
public:
    static_assert(std::is_trivially_destructible_v<T>, "node fields are plain data");

    NodeArray() = default;
    explicit NodeArray(Index n) { reset(n); }
    ~NodeArray() { releaseMapping(data_, bytes()); }
    NodeArray(NodeArray&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
    NodeArray& operator=(NodeArray&& o) noexcept {
        std::swap(data_, o.data_);
        std::swap(size_, o.size_);
        return *this;
    }
    NodeArray(const NodeArray&) = delete;
    NodeArray& operator=(const NodeArray&) = delete;

    /// A fresh array of n zeros (the old contents are discarded).
    void reset(Index n) {
        releaseMapping(data_, bytes());
        data_ = nullptr;
        size_ = 0;
        if (n > 0) data_ = static_cast<T*>(reserveZeroed(static_cast<std::size_t>(n) * sizeof(T)));
        size_ = n;
    }
    /// Zero the entries [first, first + count), handing whole pages back to the system.
    void release(Index first, Index count) {
        zeroAndRelease(data_ + first, static_cast<std::size_t>(count) * sizeof(T));
    }

    Index size() const { return size_; }
    T& operator[](Index i) { return data_[i]; }
    const T& operator[](Index i) const { return data_[i]; }
    T* data() { return data_; }
    const T* data() const { return data_; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }

private:
    std::size_t bytes() const { return static_cast<std::size_t>(size_) * sizeof(T); }

    T* data_ = nullptr;
    Index size_ = 0;
};

} // namespace mpm
