// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "grid/Grid.hpp"
#include "parallel/Comm.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/GridHalo.hpp"
#include "particles/Particles.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace mpm {

/// This rank's part of a parallel run (docs/parallel.md): the decomposition it started with or
/// was rebalanced to, its grid halo and its points' migration. A serial run has none.
template <int dim> class Subdomain {
public:
    /// Read `constant/decomposition` of `cs` (this rank's processor case) and
    /// system/decomposeParDict (its `rebalance`); an InputError when the decomposition has
    /// another number of subdomains than the run has ranks.
    Subdomain(const Case& cs, const Grid<dim>& grid, const Comm& comm);
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

    /// True if this rank owns block b.
    bool owns(Index block) const { return decomposition_.owner(block) == comm_.rank(); }
    GridHalo<dim>& halo() { return *halo_; }
    const GridHalo<dim>& halo() const { return *halo_; }

private:
    /// Decompose again by the current points when the largest rank holds more than
    /// RebalanceSettings::maxImbalance times the mean (and the blocks allow better).
    void rebalance(const Particles<dim>& p, long step);

    const Comm& comm_;
    const Grid<dim>& grid_;
    Decomposition<dim> decomposition_;
    Dictionary dict_; ///< system/decomposeParDict, to decompose again
    RebalanceSettings rebalance_;
    std::unique_ptr<GridHalo<dim>> halo_; ///< refers to decomposition_
};

} // namespace mpm
