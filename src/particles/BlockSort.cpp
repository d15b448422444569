// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/BlockSort.hpp"
#include "core/Neighbourhood.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <limits>
#include <omp.h>
#include <stdexcept>

namespace mpm {

template <int dim>
template <class KeyOf>
Index BlockSort<dim>::sortByBlock(Index n, Index numBlocks, bool& onePass, KeyOf&& keyOf) {
    // Passes of at most 16 bits (a count array of ≤ 65 536 entries a thread, in L2): one pass
    // up to 65 536 blocks, two up to 2³², each a stable counting sort. The first pass takes the
    // keys from keyOf in storage order (the identity order: no order array to read) and stores
    // them for its scatter.
    int bits = 1;
    while ((Index(1) << bits) < numBlocks)
        ++bits;
    const int passes = (bits + 15) / 16;
    const int digitBits = (bits + passes - 1) / passes;
    const std::uint32_t buckets = 1u << digitBits;
    onePass = passes == 1;
    key_.resize(n);
    order_.resize(n);
    orderTmp_.resize(n);
    keyTmp_.resize(n);
    const bool threads = worthThreads(n);
    counts_.assign(static_cast<std::size_t>(omp_get_max_threads()) * buckets, 0);
    digitBegin_.resize(buckets + 1);
    Index firstOutside = n;
#pragma omp parallel if (threads) reduction(min : firstOutside)
    {
        const int team = omp_get_num_threads(), t = omp_get_thread_num();
        const Index lo = n * t / team, hi = n * (t + 1) / team; // this thread's slice
        Index* count = counts_.data() + static_cast<std::size_t>(t) * buckets;
        for (int pass = 0; pass < passes; ++pass) {
            const int shift = digitBits * pass;
            std::fill(count, count + buckets, 0);
            if (pass == 0) {
                for (Index j = lo; j < hi; ++j) {
                    const std::int64_t k = keyOf(j);
                    if (k < 0) firstOutside = std::min(firstOutside, j);
                    key_[j] = k < 0 ? 0u : static_cast<std::uint32_t>(k);
                    ++count[key_[j] & (buckets - 1)];
                }
            } else {
                for (Index j = lo; j < hi; ++j)
                    ++count[(key_[j] >> shift) & (buckets - 1)];
            }
#pragma omp barrier
#pragma omp single
            { // exclusive prefix in (digit, slice) order: the sort is stable for any team
                Index sum = 0;
                for (std::uint32_t d = 0; d < buckets; ++d) {
                    digitBegin_[d] = sum;
                    for (int u = 0; u < team; ++u) {
                        Index& c = counts_[static_cast<std::size_t>(u) * buckets + d];
                        const Index k = c;
                        c = sum;
                        sum += k;
                    }
                }
                digitBegin_[buckets] = sum;
            }
            for (Index j = lo; j < hi; ++j) {
                const Index to = count[(key_[j] >> shift) & (buckets - 1)]++;
                orderTmp_[to] = pass == 0 ? j : order_[j];
                keyTmp_[to] = key_[j];
            }
#pragma omp barrier
#pragma omp single
            {
                order_.swap(orderTmp_);
                key_.swap(keyTmp_);
            }
        }
    }
    return firstOutside;
}

template <int dim> Index BlockSort<dim>::update(const Particles<dim>& p, const Grid<dim>& grid) {
    const Index n = static_cast<Index>(p.size());
    const Index nb = grid.numBlocks();
    if (nb > std::numeric_limits<std::int32_t>::max())
        throw std::length_error("BlockSort: more than 2³¹ blocks");
    if (static_cast<Index>(slot_.size()) != nb) {
        slot_.assign(nb, -1);
        active_.assign(nb, 0);
        blocks_.clear();
        activeNodeBlocks_.clear();
    }
    const Vec<dim> origin = grid.origin();
    const double invH = grid.invH();
    bool onePass = false;
    // The block of each particle, or −1 for one outside the grid's arrays (the sort's result is
    // then not used).
    const Index firstOutside = sortByBlock(n, nb, onePass, [&](Index i) -> std::int64_t {
        const Vec<dim> xh = (p.x[i] - origin) * invH;
        return grid.insideArrays(xh) ? grid.blockOf(xh) : -1;
    });
    if (firstOutside < n) return firstOutside;

    // The occupied blocks and their ranges; last step's entries of the per-block index are
    // forgotten one by one (no pass over the box).
    for (Index b : blocks_)
        slot_[b] = -1;
    blocks_.clear();
    begin_.clear();
    auto occupied = [&](Index b, Index first) {
        slot_[b] = static_cast<std::int32_t>(blocks_.size());
        blocks_.push_back(b);
        begin_.push_back(first);
    };
    if (onePass) { // from the sort's digit counts: a pass over the blocks, not the particles
        for (Index b = 0; b < nb; ++b)
            if (digitBegin_[b + 1] > digitBegin_[b]) occupied(b, digitBegin_[b]);
    } else {
        for (Index j = 0; j < n; ++j)
            if (j == 0 || key_[j] != key_[j - 1]) occupied(key_[j], j);
    }
    begin_.push_back(n);

    for (int c = 0; c < NumColours; ++c) {
        colourBlocks_[c].clear();
        colourPrefix_[c].assign(1, 0);
    }
    for (Index b : activeNodeBlocks_)
        active_[b] = 0;
    activeNodeBlocks_.clear();
    const IVec<dim> nbDims = grid.blocks();
    for (Index b : blocks_) {
        const IVec<dim> c = grid.blockCoord(b);
        int colour = 0;
        for (int d = 0; d < dim; ++d)
            colour |= (c[d] & 1) << d;
        colourBlocks_[colour].push_back(b);
        const Range r = particlesOf(b);
        colourPrefix_[colour].push_back(colourPrefix_[colour].back() + r.end - r.begin);
        // Mark the 3^dim neighbourhood.
        forEachNeighbourOffset<dim>([&](const IVec<dim>& o) {
            bool inside = true;
            Index k = 0;
            for (int d = dim - 1; d >= 0; --d) {
                const int cd = c[d] + o[d];
                if (cd < 0 || cd >= nbDims[d]) inside = false;
                k = k * nbDims[d] + cd;
            }
            if (inside && !active_[k]) {
                active_[k] = 1;
                activeNodeBlocks_.push_back(k);
            }
        });
    }
    std::sort(activeNodeBlocks_.begin(), activeNodeBlocks_.end());
    return -1;
}

template <int dim> void BlockSort<dim>::visitOrder(std::vector<Index>& out) const {
    out.clear();
    out.reserve(order_.size());
    forEachBlockByColour(false, [&](Index, Range r) {
        out.insert(out.end(), order_.begin() + r.begin, order_.begin() + r.end);
    });
}

template <int dim>
typename BlockSort<dim>::Range BlockSort<dim>::shareOf(int c, int t, int team) const {
    // Block k goes to the thread whose slice [total t/team, total (t+1)/team) of the colour's
    // particles holds its first particle.
    const std::vector<Index>& prefix = colourPrefix_[c];
    const Index total = prefix.back();
    const Index nb = static_cast<Index>(prefix.size()) - 1;
    auto firstFrom = [&](Index rank) {
        return static_cast<Index>(std::lower_bound(prefix.begin(), prefix.begin() + nb, rank) -
                                  prefix.begin());
    };
    return Range{firstFrom(total * t / team), firstFrom(total * (t + 1) / team)};
}

template class BlockSort<2>;
template class BlockSort<3>;

} // namespace mpm
