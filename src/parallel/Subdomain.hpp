// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/PeriodicLattice.hpp"
#include "case/Case.hpp"
#include "grid/Grid.hpp"
#include "parallel/Comm.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/GridHalo.hpp"
#include "particles/Particles.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mpm {

/// This rank's part of a parallel run (docs/parallel.md): the decomposition it started with or
/// was rebalanced to, its grid halo and its points' migration. A serial run has none.
template <int dim> class Subdomain {
public:
    /// Read `constant/decomposition` of `cs` (this rank's processor case) and
    /// system/decomposeParDict (its `rebalance`); an InputError when the decomposition has
    /// another number of subdomains than the run has ranks. `closeBlocks` adds to a sorted list
    /// of blocks those periodic faces relate to them (BoundaryConditions::closeActiveBlocks).
    Subdomain(const Case& cs, const Grid<dim>& grid, const Comm& comm,
              std::function<void(std::vector<Index>&)> closeBlocks);
    Subdomain(const Subdomain&) = delete; // the halo refers to the decomposition
    Subdomain& operator=(const Subdomain&) = delete;

    /// A restart from time directory `from`: its decomposition when it has one (a rebalanced
    /// run writes it with every time).
    void readTime(const Case& cs, const std::string& from);
    /// Write the decomposition into the time directory `dir` (rebalanced runs only).
    void writeTime(const std::filesystem::path& dir) const;

    /// A fresh start: keep this rank's points of the whole seeding.
    void keepOwned(Particles<dim>& p) const;
    /// Rebalance when due at step `step`, then migrate the points to their owners; true when
    /// this rank's points changed. `scratch`: the reorder buffers.
    bool exchangePoints(Particles<dim>& p, long step, PermuteBuffers<dim>& scratch);

    /// Periodic faces across the ranks (PeriodicLattice::fold of a serial run), after the halo
    /// sum: every image node of this rank's active blocks adds its values of `fields`
    /// (NodeArrays) onto its owner node — here, or on the rank owning the owner's block, which
    /// adds the ranks' images in rank order after its own — and takes back the owner's total.
    template <class... Fields>
    void foldPeriodic(const PeriodicLattice<dim>& lattice, Fields&... fields);

    /// True when the decomposition may change during the run (decomposeParDict `rebalance`).
    bool rebalances() const { return rebalance_.enabled(); }
    /// True if this rank owns block b.
    bool owns(Index block) const { return decomposition_.owner(block) == comm_.rank(); }
    GridHalo<dim>& halo() { return *halo_; }
    const GridHalo<dim>& halo() const { return *halo_; }

private:
    static constexpr Index Nb = Grid<dim>::NodesPerBlock;

    /// Decompose again by the current points when the largest rank holds more than
    /// RebalanceSettings::maxImbalance times the mean (and the blocks allow better); true when
    /// it did.
    bool rebalance(const Particles<dim>& p, long step);
    /// The ranks owning a block next to one of this rank's (or related to one by a periodic
    /// face), made symmetric: all a step's messages go to them, since a stencil reaches one
    /// block and a point moves at most one cell a step (the CFL check).
    void findNeighbours();

    const Comm& comm_;
    const Grid<dim>& grid_;
    Decomposition<dim> decomposition_;
    Dictionary dict_; ///< system/decomposeParDict, to decompose again
    RebalanceSettings rebalance_;
    std::function<void(std::vector<Index>&)> closeBlocks_;
    std::vector<int> neighbours_;
    bool started_ = false;                ///< the first migration (a restart) may send anywhere
    std::unique_ptr<GridHalo<dim>> halo_; ///< refers to decomposition_
};

template <int dim>
template <class... Fields>
void Subdomain<dim>::foldPeriodic(const PeriodicLattice<dim>& lattice, Fields&... fields) {
    if (!lattice.any()) return;
    const int me = comm_.rank();
    const std::size_t n = static_cast<std::size_t>(comm_.size());
    std::vector<std::pair<Index, Index>> local;               // (image, owner), both here
    std::vector<std::vector<std::pair<Index, Index>>> out(n); // owner on rank r
    for (Index b : halo_->owned())
        lattice.forImagesOf(b, [&](Index image, Index owner) {
            const int r = decomposition_.owner(owner / Nb);
            (r == me ? local : out[static_cast<std::size_t>(r)]).emplace_back(image, owner);
        });
    // The images' values to the owners' ranks: the owner node, then each field's value.
    std::vector<std::vector<char>> send(n);
    for (std::size_t r = 0; r < n; ++r) {
        ByteWriter w(send[r]);
        for (const auto& [image, owner] : out[r]) {
            w.put(owner);
            (w.put(&fields[image], 1), ...);
        }
    }
    const std::vector<std::vector<char>> recv = comm_.exchange(send, &neighbours_);
    for (const auto& [image, owner] : local)
        ((fields[owner] += fields[image]), ...);
    std::vector<std::vector<Index>> in(n); // owner nodes of rank r's images, in its order
    for (std::size_t r = 0; r < n; ++r) {
        if (static_cast<int>(r) == me) continue;
        ByteReader read(recv[r]);
        while (!read.done()) {
            const Index owner = read.get<Index>();
            in[r].push_back(owner);
            auto add = [&](auto& f) {
                std::remove_reference_t<decltype(f[owner])> x;
                read.get(&x, 1);
                f[owner] += x;
            };
            (add(fields), ...);
        }
    }
    // The owners' totals back to the images.
    for (const auto& [image, owner] : local)
        ((fields[image] = fields[owner]), ...);
    std::vector<std::vector<char>> back(n);
    for (std::size_t r = 0; r < n; ++r) {
        ByteWriter w(back[r]);
        for (Index owner : in[r])
            (w.put(&fields[owner], 1), ...);
    }
    const std::vector<std::vector<char>> totals = comm_.exchange(back, &neighbours_);
    for (std::size_t r = 0; r < n; ++r) {
        if (static_cast<int>(r) == me) continue;
        ByteReader read(totals[r]);
        for (const auto& [image, owner] : out[r])
            (read.get(&fields[image], 1), ...);
    }
}

} // namespace mpm
