// SPDX-License-Identifier: GPL-3.0-or-later
#include "grid/Grid.hpp"

#include <cstring>

namespace mpm {

template <int dim> Grid<dim>::Grid(const Dictionary& dict) : GridLayout<dim>(dict) {
    mass.reset(this->numNodes());
    momentum.reset(this->numNodes());
    force.reset(this->numNodes());
    vOld.reset(this->numNodes());
    v.reset(this->numNodes());
    lines.reset(this->numNodes());
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
