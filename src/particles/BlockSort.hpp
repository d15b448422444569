// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "particles/Particles.hpp"

#include <cstdint>
#include <omp.h>
#include <vector>

namespace mpm {

/// Particles bucketed by 4^dim-cell grid block (a stable radix sort of indices by block,
/// docs/architecture.md), in time and memory traffic proportional to the particles and the occupied
/// blocks, not to the box: a sparse grid of 10⁸ cells costs a per-block index and flag (5 B a
/// block, touched only where the material is), nothing per step.
///
/// Blocks of one colour (block coordinates of equal parity) are two blocks apart, so their
/// kernel stencils never share a node: P2G runs the blocks of one colour in parallel and the
/// colours one after another. Every node then receives its contributions in the same order
/// whatever the thread count, which makes the output bit-identical for 1 and N threads.
template <int dim> class BlockSort {
public:
    static constexpr int NumColours = 1 << dim;

    /// Positions [begin, end) in order() of one block's particles.
    struct Range {
        Index begin = 0, end = 0;
    };

    /// Bucket all particles; returns the index of the first particle outside the grid's arrays,
    /// or -1 when all are inside.
    Index update(const Particles<dim>& p, const Grid<dim>& grid);

    /// Particle indices ordered by block (stable within a block).
    const std::vector<Index>& order() const { return order_; }
    /// The particles of block b: order()[r.begin .. r.end) (empty for an empty block).
    Range particlesOf(Index b) const {
        const std::int32_t k = slot_[b];
        return k < 0 ? Range{} : Range{begin_[k], begin_[k + 1]};
    }
    /// The particles in the order P2G visits them: colour by colour, each colour's blocks
    /// ascending, each block's particles as in order(). Stored in this order (the periodic
    /// reorder), the particles are read front to back by P2G as by every other phase.
    void visitOrder(std::vector<Index>& out) const;
    /// Non-empty blocks, ascending.
    const std::vector<Index>& occupiedBlocks() const { return blocks_; }
    /// Non-empty blocks of colour c, ascending.
    const std::vector<Index>& blocksOfColour(int c) const { return colourBlocks_[c]; }
    /// Thread t's share of colour c in a team of `team`: positions [begin, end) in
    /// blocksOfColour(c), contiguous, with about 1/team of the colour's particles.
    Range shareOf(int c, int t, int team) const;

    /// Visit every non-empty block, fn(block, particlesOf(block)): colour after colour, the
    /// blocks of one colour in parallel (with `parallel`), each thread a contiguous share of
    /// them (shareOf), which visitOrder stores contiguously. Blocks of one colour share no
    /// stencil node, so every node sees its contributions in one order for any team.
    template <class Fn> void forEachBlockByColour(bool parallel, Fn&& fn) const {
#pragma omp parallel if (parallel)
        {
            const int team = omp_get_num_threads(), t = omp_get_thread_num();
            for (int c = 0; c < NumColours; ++c) {
                const Range share = shareOf(c, t, team);
                for (Index k = share.begin; k < share.end; ++k) {
                    const Index b = colourBlocks_[c][k];
                    fn(b, particlesOf(b));
                }
#pragma omp barrier
            }
        }
    }
    /// Node blocks that can receive mass: the 3^dim neighbourhood of every non-empty block,
    /// ascending.
    const std::vector<Index>& activeNodeBlocks() const {
        return activeNodeBlocks_;
    }

private:
    /// order_ = the particles 0 … n−1 stably sorted by their block keyOf(i) (an int64, −1 for
    /// a particle outside the grid's arrays), key_ their blocks: LSD radix sort of ≤ 16 bits a
    /// pass, each pass a counting sort over the threads' slices (the same order for any thread
    /// count), the keys evaluated in the first pass's count. onePass: it took one pass, whose
    /// digits are then the blocks and digitBegin_ their first positions. Returns the first
    /// particle outside, or n.
    template <class KeyOf>
    Index sortByBlock(Index n, Index numBlocks, bool& onePass, KeyOf&& keyOf);

    std::vector<Index> order_;
    std::vector<Index> orderTmp_;
    std::vector<std::uint32_t> key_, keyTmp_; ///< the block of each particle of order_
    std::vector<Index> counts_;               ///< the radix passes' counts, per thread
    std::vector<Index> digitBegin_;  ///< the last pass's first position of each digit (+ n)
    std::vector<Index> blocks_;      ///< occupied blocks, ascending
    std::vector<Index> begin_;       ///< begin_[k]: first position of blocks_[k]; begin_.back() = n
    std::vector<std::int32_t> slot_; ///< per block of the box: k in blocks_, or -1
    std::vector<Index> colourBlocks_[NumColours];
    std::vector<Index> colourPrefix_[NumColours]; ///< particles in the first k blocks of a colour
    std::vector<char> active_;                    ///< per block of the box: in activeNodeBlocks_
    std::vector<Index> activeNodeBlocks_;
};

} // namespace mpm
