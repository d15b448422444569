// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace mpm {

/// Non-temporal ("streaming") stores for arrays a phase overwrites without reading: a plain
/// store first reads the line it writes into the cache (write-allocate), a streaming store does
/// not, and consecutive stores fill whole lines in the write-combining buffers. For arrays much
/// larger than the caches this removes one read per written byte (docs/benchmarks.md, "Stores
/// that do not read"). A thread that streamed calls sfence() before other threads read the data.
/// Without AVX (a portable build) they are plain stores.

/// to = from for an object of whole 32-byte chunks, 32-byte aligned.
template <class T> inline void streamStore(T& to, const T& from) {
    static_assert(sizeof(T) % 32 == 0 && alignof(T) >= 32);
#if defined(__AVX__)
    const double* src = reinterpret_cast<const double*>(&from);
    double* dst = reinterpret_cast<double*>(&to);
    for (std::size_t k = 0; k < sizeof(T) / sizeof(double); k += 4)
        _mm256_stream_pd(dst + k, _mm256_loadu_pd(src + k));
#else
    to = from;
#endif
}

/// to = from for a matrix or vector: by 16-byte streaming stores where T allows them (Mat2,
/// 16-byte aligned), else a plain store (a 3×3 is 8-byte aligned, and eight-byte streaming
/// stores cost G2P more than the reads they save: block3D G2P +5–10 %).
template <class T> inline void streamValue(T& to, const T& from) {
#if defined(__AVX__)
    if constexpr (alignof(T) >= 16 && sizeof(T) % 16 == 0) {
        const double* src = reinterpret_cast<const double*>(&from);
        double* dst = reinterpret_cast<double*>(&to);
        for (std::size_t k = 0; k < sizeof(T) / sizeof(double); k += 2)
            _mm_stream_pd(dst + k, _mm_loadu_pd(src + k));
        return;
    }
#endif
    to = from;
}

/// Order this thread's streaming stores before its later stores (and so before a barrier).
inline void sfence() {
#if defined(__AVX__)
    _mm_sfence();
#endif
}

} // namespace mpm
