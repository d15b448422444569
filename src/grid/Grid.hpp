// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "grid/GridLayout.hpp"
#include "grid/NodeArray.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace mpm {

/// Eight doubles in one 64-byte line: a node's packed transfer data (Grid::lines).
struct alignas(64) NodeLine {
    double v[8];
};

/// The background grid (GridLayout) with its node fields.
template <int dim> class Grid : public GridLayout<dim> {
public:
    using GridLayout<dim>::NodesPerBlock;
    /// Bytes of the node fields per node (mass, momentum, force, vOld, v, lines).
    static constexpr int BytesPerNode = sizeof(double) + 4 * sizeof(Vec<dim>) + sizeof(NodeLine);

    explicit Grid(const Dictionary& dict);

    /// The blocks of this step's material (sorted): zeroes their node fields (and the scratch
    /// lines of those newly active) and hands the pages of the blocks the material has left
    /// back to the system.
    void activate(std::vector<Index>&& blocks);

    // Node fields (SoA). vOld is the P2G velocity, v the updated one.
    NodeArray<double> mass;
    NodeArray<Vec<dim>> momentum;
    NodeArray<Vec<dim>> force;
    NodeArray<Vec<dim>> vOld;
    NodeArray<Vec<dim>> v;
    /// Scratch of the transfers, one cache line per node (P2G sums, G2P velocities): defined
    /// only within one transfer phase, so activate zeroes it only in newly active blocks (to
    /// commit their pages by a write); its pages are released with the blocks the material
    /// leaves, like the other fields'.
    NodeArray<NodeLine> lines;

private:
    using GridLayout<dim>::active_;
    using GridLayout<dim>::activeFlag_;
};

} // namespace mpm
