// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "particles/Particles.hpp"

#include <vector>

namespace mpm {

/// Particles bucketed by 4^dim-cell grid block (a stable counting sort of indices, DESIGN §4).
///
/// Blocks of one colour (block coordinates of equal parity) are two blocks apart, so their
/// kernel stencils never share a node: P2G runs the blocks of one colour in parallel and the
/// colours one after another. Every node then receives its contributions in the same order
/// whatever the thread count, which makes the output bit-identical for 1 and N threads.
template <int dim> class BlockSort {
public:
    static constexpr int NumColours = 1 << dim;

    /// Bucket all particles; returns the index of the first particle outside the grid's arrays,
    /// or -1 when all are inside.
    Index update(const Particles<dim>& p, const Grid<dim>& grid);

    /// Particle indices ordered by block (stable within a block).
    const std::vector<Index>& order() const { return order_; }
    /// Particles of block b are order()[start(b) .. start(b+1)).
    Index start(Index b) const { return start_[b]; }
    /// Non-empty blocks of colour c.
    const std::vector<Index>& blocksOfColour(int c) const { return colourBlocks_[c]; }
    /// Node blocks that can receive mass: the 3^dim neighbourhood of every non-empty block.
    const std::vector<Index>& activeNodeBlocks() const { return activeNodeBlocks_; }

private:
    std::vector<Index> block_;
    std::vector<Index> order_;
    std::vector<Index> start_;
    std::vector<Index> colourBlocks_[NumColours];
    std::vector<char> active_;
    std::vector<Index> activeNodeBlocks_;
};

} // namespace mpm
