// SPDX-License-Identifier: GPL-3.0-or-later
#include "transfers/PhaseDensity.hpp"

namespace mpm {

template <int dim>
void PhaseDensity<dim>::apply(Particles<dim>& p, const Grid<dim>& g, const Transfer<dim>& transfer,
                              const BlockSort<dim>& sort) {
    if (nodal_.size() != g.numNodes()) nodal_.reset(g.numNodes());
    g.forEachNode(g.activeBlocks(), [this](Index k) { nodal_[k] = 0.0; });
    transfer.scatterScalar(p.volume, nodal_, sort);
    if (foldNodal_) foldNodal_(nodal_);
    g.forEachNode(g.activeBlocks(),
                  [&](Index k) { nodal_[k] = nodal_[k] > 0.0 ? g.mass[k] / nodal_[k] : 0.0; });
    transfer.gatherScalar(nodal_, p.scalar(handle_));
}

template class PhaseDensity<2>;
template class PhaseDensity<3>;

} // namespace mpm
