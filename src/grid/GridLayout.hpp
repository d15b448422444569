// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Parallel.hpp"
#include "core/Types.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace mpm {

/// Uniform background grid over the box [lo, hi], padded by `Pad` cells of ghost nodes on each
/// side so that every kernel's stencil stays inside the arrays for points within one cell of the
/// box. Nodes are grouped in blocks of 4^dim (the race-free P2G of docs/architecture.md) and
/// numbered block by block: node (i, j, k) is entry 4^dim b + (i mod 4) + 4 (j mod 4)
/// + 16 (k mod 4) of block b = (i/4) + nb_x ((j/4) + nb_y (k/4)). The numbering is a sum of one
/// offset per axis (axisOffset), so a stencil costs dim·W offsets, and a block's nodes are
/// contiguous, so the node fields (NodeArray) commit memory block by block where the material
/// is: the grid is sparse (docs/sparseGrid.md). Only the active blocks, those the material's
/// stencils reach (activate), hold non-zero values.
///
/// GridLayout is the grid without its node fields (Grid adds them): the numbering, faces and
/// active blocks that a compute backend needs to find the nodes of a stencil
/// (docs/architecture.md, "A compute backend").
template <int dim> class GridLayout {
public:
    static constexpr int Pad = 3;
    static constexpr int BlockSize = 4;
    static constexpr int NodesPerBlock = dim == 2 ? 16 : 64;
    static constexpr int NumFaces = 2 * dim;

    explicit GridLayout(const Dictionary& dict);

    double h() const { return h_; }
    double invH() const { return invH_; }
    const Vec<dim>& lo() const { return lo_; }
    const Vec<dim>& hi() const { return hi_; }
    /// Position of node (0, …, 0), Pad cells below lo.
    const Vec<dim>& origin() const { return origin_; }
    /// Nodes along each axis (Pad ghost layers on each side included).
    const IVec<dim>& nodes() const { return n_; }
    /// Length of the node fields: every node of every block, the padding of the last blocks
    /// beyond nodes() included (those entries stay zero).
    Index numNodes() const { return numNodes_; }
    const IVec<dim>& blocks() const { return nb_; }
    Index numBlocks() const { return numBlocks_; }

    /// Contribution of coordinate i along axis d to the node index (nodeIndex = Σ_d of them).
    Index axisOffset(int d, int i) const {
        return static_cast<Index>(i >> 2) * blockStride_[d] + (i & 3) * (Index(1) << (2 * d));
    }
    Index nodeIndex(const IVec<dim>& i) const {
        Index k = 0;
        for (int d = 0; d < dim; ++d)
            k += axisOffset(d, i[d]);
        return k;
    }
    /// Integer coordinates of node k (inverse of nodeIndex).
    IVec<dim> nodeCoord(Index k) const {
        const IVec<dim> c = blockCoord(k / NodesPerBlock);
        const int local = static_cast<int>(k % NodesPerBlock);
        IVec<dim> i;
        for (int d = 0; d < dim; ++d)
            i[d] = c[d] * BlockSize + ((local >> (2 * d)) & 3);
        return i;
    }
    /// The number of node k in files (restart state): x fastest over nodes(), independent of
    /// the storage layout.
    Index fileIndex(Index k) const {
        const IVec<dim> i = nodeCoord(k);
        Index f = i[dim - 1];
        for (int d = dim - 2; d >= 0; --d)
            f = f * n_[d] + i[d];
        return f;
    }
    /// Node of file number f, or -1 when f numbers no node.
    Index nodeOfFileIndex(Index f) const {
        IVec<dim> i;
        for (int d = 0; d < dim; ++d) {
            i[d] = static_cast<int>(f % n_[d]);
            f /= n_[d];
        }
        return f == 0 ? nodeIndex(i) : -1;
    }
    /// Nodes in files (the product of nodes()).
    Index numFileNodes() const { return numFileNodes_; }
    Vec<dim> nodePosition(const IVec<dim>& i) const {
        return origin_ + h_ * i.template cast<double>();
    }
    /// Block of a point, from its coordinate in cell units (x - origin)/h.
    Index blockOf(const Vec<dim>& xh) const {
        Index k = 0;
        for (int d = dim - 1; d >= 0; --d) {
            const int b = static_cast<int>(xh[d]) / BlockSize;
            k = k * nb_[d] + b;
        }
        return k;
    }
    IVec<dim> blockCoord(Index b) const {
        IVec<dim> c;
        for (int d = 0; d < dim; ++d) {
            c[d] = static_cast<int>(b % nb_[d]);
            b /= nb_[d];
        }
        return c;
    }
    /// True if a point (cell units) is far enough inside the arrays for every kernel.
    bool insideArrays(const Vec<dim>& xh) const {
        for (int d = 0; d < dim; ++d)
            if (!(xh[d] >= 1.0 && xh[d] < n_[d] - 3.0)) return false;
        return true;
    }

    /// Visit every node of the given blocks, x fastest within a block, the blocks in parallel:
    /// fn(node index). The one loop over grid nodes (clearing, grid velocity, grid update).
    template <class Fn> void forEachNode(const std::vector<Index>& blocks, Fn&& fn) const {
        const Index nb = static_cast<Index>(blocks.size());
#pragma omp parallel for if (worthThreads(64 * nb)) schedule(static)
        for (Index k = 0; k < nb; ++k) {
            const Index b = blocks[k];
            const Index first = b * NodesPerBlock;
            if (!edge_[b]) {
                for (int l = 0; l < NodesPerBlock; ++l)
                    fn(first + l);
                continue;
            }
            const IVec<dim> c = blockCoord(b);
            for (int l = 0; l < NodesPerBlock; ++l) {
                bool inside = true;
                for (int d = 0; d < dim; ++d)
                    inside = inside && c[d] * BlockSize + ((l >> (2 * d)) & 3) < n_[d];
                if (inside) fn(first + l);
            }
        }
    }

    const std::vector<Index>& activeBlocks() const {
        return active_;
    }
    bool isActive(Index block) const {
        return activeFlag_[block] != 0;
    }

    static std::string faceName(int f);
    /// Nodes on or outside face f (within the ghost layers): the nodes its condition acts on.
    const std::vector<Index>& faceNodes(int f) const {
        return faceNodes_[f];
    }

protected:
    double h_ = 0, invH_ = 0;
    Vec<dim> lo_, hi_, origin_;
    IVec<dim> n_, nb_;
    std::array<Index, dim> blockStride_{}; ///< NodesPerBlock × blocks below along lower axes
    Index numNodes_ = 0, numBlocks_ = 0, numFileNodes_ = 0;
    std::vector<char>
        edge_; ///< per block: holds padding beyond nodes() (the last block of an axis)
    std::array<std::vector<Index>, NumFaces> faceNodes_;
    std::vector<Index> active_;
    std::vector<char> activeFlag_; ///< per block: 1 if in active_
};

} // namespace mpm
