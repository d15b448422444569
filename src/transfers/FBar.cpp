// SPDX-License-Identifier: GPL-3.0-or-later
#include "transfers/FBar.hpp"

#include "core/Parallel.hpp"

#include <cmath>

namespace mpm {

template <int dim>
void FBar<dim>::apply(Particles<dim>& p, const Grid<dim>& g, const Transfer<dim>& transfer,
                      const BlockSort<dim>& sort, double dt) {
    const Index n = static_cast<Index>(p.size());
    weighted_.resize(n);
    if (nodal_.size() != g.numNodes()) nodal_.reset(g.numNodes());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
    for (Index i = 0; i < n; ++i)
        weighted_[i] = p.mass[i] * (Mat<dim>::Identity() + dt * p.L[i]).determinant();
    g.forEachNode(g.activeBlocks(), [this](Index k) { nodal_[k] = 0.0; });
    transfer.scatterScalar(weighted_, nodal_, sort);
    if (foldNodal_) foldNodal_(nodal_); // periodic faces: images onto owners
    g.forEachNode(g.activeBlocks(),
                  [&](Index k) { nodal_[k] = g.mass[k] > 0.0 ? nodal_[k] / g.mass[k] : 0.0; });
    transfer.gatherScalar(nodal_, average_);
#pragma omp parallel for if (worthThreads(n)) schedule(static)
    for (Index i = 0; i < n; ++i) {
        const Mat<dim> f = Mat<dim>::Identity() + dt * p.L[i];
        const double ratio = average_[i] * p.mass[i] / weighted_[i]; // ΔJ̄_p / ΔJ_p
        // A non-positive ratio is an inverted increment; leave it for the solver's det F check.
        if (!(ratio > 0.0)) continue;
        const double scale = dim == 3 ? std::cbrt(ratio) : std::sqrt(ratio);
        p.L[i] = (scale * f - Mat<dim>::Identity()) / dt;
    }
}

template class FBar<2>;
template class FBar<3>;

MPM_REGISTER_DIMS(AntiLockingRegistry, FBar, "fBar");
MPM_SCHEMA("antiLocking", "fBar",
           {"F̄: each point's volume change replaced by its neighbourhood's mass-weighted average",
            {},
            "antiLocking: fBar"});

} // namespace mpm
