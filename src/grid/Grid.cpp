// SPDX-License-Identifier: GPL-3.0-or-later
#include "grid/Grid.hpp"

#include <cmath>
#include <cstring>
#include <sstream>

namespace mpm {

template <int dim> std::string Grid<dim>::faceName(int f) {
    static const char* axes = "xyz";
    return std::string(1, axes[f / 2]) + (f % 2 == 0 ? "Min" : "Max");
}

template <int dim> Grid<dim>::Grid(const Dictionary& dict) {
    h_ = dict.getScalar("cellSize", Bounds::positive());
    invH_ = 1.0 / h_;
    const Dictionary b = dict.subDict("bounds");
    const std::vector<double> lo = b.getVector("min", dim);
    const std::vector<double> hi = b.getVector("max", dim);
    b.checkUnknownKeys();
    for (int d = 0; d < dim; ++d) {
        lo_[d] = lo[d];
        hi_[d] = hi[d];
        const double extent = hi[d] - lo[d];
        if (!(extent > 0)) b.error("max", "max must exceed min in every direction");
        const double cells = extent / h_;
        const double rounded = std::round(cells);
        if (rounded < 1 || std::fabs(cells - rounded) > 1e-6 * std::max(1.0, cells)) {
            std::ostringstream os;
            os << "the box extent " << extent << " m along "
               << "xyz"[d] << " is not a whole number of cells of size " << h_ << " m";
            dict.error("cellSize", os.str());
        }
        if (rounded > 1e5) dict.error("cellSize", "more than 100000 cells in one direction");
        n_[d] = static_cast<int>(rounded) + 1 + 2 * Pad;
        nb_[d] = (n_[d] + BlockSize - 1) / BlockSize;
        origin_[d] = lo_[d] - Pad * h_;
        hi_[d] = lo_[d] + rounded * h_;
    }
    numBlocks_ = 1;
    numFileNodes_ = 1;
    for (int d = 0; d < dim; ++d) {
        blockStride_[d] = NodesPerBlock * numBlocks_;
        numBlocks_ *= nb_[d];
        numFileNodes_ *= n_[d];
    }
    numNodes_ = numBlocks_ * NodesPerBlock;
    // The node fields are reserved, not committed (NodeArray): the limit is address space.
    if (numNodes_ > Index(4) * 1000 * 1000 * 1000)
        dict.error("cellSize", "the grid would have more than 4e9 nodes");

    edge_.assign(numBlocks_, 0);
    for (Index k = 0; k < numBlocks_; ++k) {
        const IVec<dim> c = blockCoord(k);
        for (int d = 0; d < dim; ++d)
            if ((c[d] + 1) * BlockSize > n_[d]) edge_[k] = 1;
    }

    // Nodes on or beyond each face: layers 0..Pad on the low side, n-1-Pad..n-1 on the high
    // side, listed x fastest.
    for (int f = 0; f < NumFaces; ++f) {
        const int axis = f / 2;
        IVec<dim> first = IVec<dim>::Zero(), end = n_;
        if (f % 2 == 0)
            end[axis] = Pad + 1;
        else
            first[axis] = n_[axis] - 1 - Pad;
        IVec<dim> i = first;
        while (true) {
            faceNodes_[f].push_back(nodeIndex(i));
            int d = 0;
            while (d < dim && ++i[d] >= end[d])
                i[d] = first[d], ++d;
            if (d == dim) break;
        }
    }

    mass.reset(numNodes_);
    momentum.reset(numNodes_);
    force.reset(numNodes_);
    vOld.reset(numNodes_);
    v.reset(numNodes_);
    lines.reset(numNodes_);
    activeFlag_.assign(numBlocks_, 0);
}

template <int dim> void Grid<dim>::activate(std::vector<Index>&& blocks) {
    // Blocks that stay active are zeroed in place (their pages stay committed); runs of
    // blocks the material has left are zeroed and their whole pages released. A block that
    // becomes active is written with zeros too, scratch lines included, although it reads as
    // zero: a page whose first access is a read maps the shared zero page, and the write that
    // follows replaces that mapping, which flushes the other threads' TLBs (an interrupt per
    // page, costly under a hypervisor: P2G's sums into such pages took 3–4× as long with two
    // threads as with one, docs/benchmarks.md). Written first, the page is simply allocated.
    constexpr char Was = 1, Now = 2;
    for (Index b : active_)
        activeFlag_[b] = Was;
    for (Index b : blocks)
        activeFlag_[b] |= Now;
    auto forFields = [this](Index block, Index count, auto&& op, bool withScratch) {
        const Index first = block * NodesPerBlock, n = count * NodesPerBlock;
        op(mass, first, n);
        op(momentum, first, n);
        op(force, first, n);
        op(vOld, first, n);
        op(v, first, n);
        if (withScratch) op(lines, first, n);
    };
    const Index nb = static_cast<Index>(blocks.size());
#pragma omp parallel for if (worthThreads(64 * nb)) schedule(static)
    for (Index k = 0; k < nb; ++k)
        forFields(
            blocks[k], 1,
            [](auto& field, Index first, Index n) {
                std::memset(static_cast<void*>(field.data() + first), 0, n * sizeof(field[0]));
            },
            activeFlag_[blocks[k]] == Now);
    const Index na = static_cast<Index>(active_.size());
    // Runs of left blocks, joined across gaps of blocks that were never active (zero already)
    // up to a few blocks long.
    constexpr Index MaxGap = 8;
    for (Index k = 0; k < na;) {
        const Index first = active_[k];
        if (activeFlag_[first] != Was) {
            ++k;
            continue;
        }
        Index last = first;
        ++k;
        while (k < na && activeFlag_[active_[k]] == Was && active_[k] - last <= MaxGap) {
            bool free = true;
            for (Index c = last + 1; c < active_[k]; ++c)
                free = free && !activeFlag_[c];
            if (!free) break;
            last = active_[k++];
        }
        forFields(
            first, last + 1 - first, [](auto& field, Index f, Index n) { field.release(f, n); },
            true);
    }
    for (Index b : active_)
        activeFlag_[b] = 0;
    for (Index b : blocks)
        activeFlag_[b] = 1;
    active_ = std::move(blocks); // activeFlag_ now flags them
}

template class Grid<2>;
template class Grid<3>;

} // namespace mpm
