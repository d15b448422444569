// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Parallel.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mpm {

/// Σ_i f(i) for i in [0, n), bit-identical for any thread count: partial sums over fixed
/// chunks of 4096 items, then added in chunk order.
template <class Fn> double deterministicSum(Index n, Fn&& f) {
    constexpr Index chunk = 4096;
    const Index nChunks = (n + chunk - 1) / chunk;
    std::vector<double> partial(nChunks, 0.0);
#pragma omp parallel for if (worthThreads(n)) schedule(static)
    for (Index c = 0; c < nChunks; ++c) {
        double s = 0.0;
        const Index end = std::min(n, (c + 1) * chunk);
        for (Index i = c * chunk; i < end; ++i)
            s += f(i);
        partial[c] = s;
    }
    double total = 0.0;
    for (double s : partial)
        total += s;
    return total;
}

} // namespace mpm
