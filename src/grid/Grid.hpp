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
/// box. Node arrays are dense, x fastest. Nodes are grouped in blocks of 4^dim for the
/// race-free P2G (DESIGN §4) and to skip empty regions.
template <int dim> class Grid {
public:
    static constexpr int Pad = 3;
    static constexpr int BlockSize = 4;
    static constexpr int NumFaces = 2 * dim;

    explicit Grid(const Dictionary& dict);

    double h() const { return h_; }
    double invH() const { return invH_; }
    const Vec<dim>& lo() const { return lo_; }
    const Vec<dim>& hi() const { return hi_; }
    /// Position of node (0, …, 0), Pad cells below lo.
    const Vec<dim>& origin() const { return origin_; }
    const IVec<dim>& nodes() const { return n_; }
    Index numNodes() const { return numNodes_; }
    const IVec<dim>& blocks() const { return nb_; }
    Index numBlocks() const { return numBlocks_; }

    Index nodeIndex(const IVec<dim>& i) const {
        Index k = i[dim - 1];
        for (int d = dim - 2; d >= 0; --d)
            k = k * n_[d] + i[d];
        return k;
    }
    Index stride(int d) const { return stride_[d]; }
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
            const IVec<dim> c = blockCoord(blocks[k]);
            IVec<dim> lo, hi;
            for (int d = 0; d < dim; ++d) {
                lo[d] = c[d] * BlockSize;
                hi[d] = std::min(lo[d] + BlockSize, n_[d]);
            }
            IVec<dim> i = lo;
            while (true) {
                fn(nodeIndex(i));
                int d = 0;
                while (d < dim && ++i[d] >= hi[d])
                    i[d] = lo[d], ++d;
                if (d == dim) break;
            }
        }
    }

    static std::string faceName(int f);
    /// Nodes on or outside face f (within the ghost layers): the nodes its condition acts on.
    const std::vector<Index>& faceNodes(int f) const {
        return faceNodes_[f];
    }

    // Node fields (SoA). vOld is the P2G velocity, v the updated one.
    std::vector<double> mass;
    std::vector<Vec<dim>> momentum;
    std::vector<Vec<dim>> force;
    std::vector<Vec<dim>> vOld;
    std::vector<Vec<dim>> v;

private:
    double h_ = 0, invH_ = 0;
    Vec<dim> lo_, hi_, origin_;
    IVec<dim> n_, nb_;
    std::array<Index, dim> stride_{};
    Index numNodes_ = 0, numBlocks_ = 0;
    std::array<std::vector<Index>, NumFaces> faceNodes_;
};

} // namespace mpm
