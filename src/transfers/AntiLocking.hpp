// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Registry.hpp"
#include "grid/Grid.hpp"
#include "particles/BlockSort.hpp"
#include "particles/Particles.hpp"
#include "transfers/Transfer.hpp"

#include <functional>
#include <memory>

namespace mpm {

/// Volumetric anti-locking (system/mpmSchemes `antiLocking`), chosen once at set-up: after the
/// step's velocity gradients L_p are known and before the stress update, `apply` may replace
/// them (F̄: FBar.hpp). `none` (the default) leaves them as they are.
///
/// The methods are the family `antiLocking` of AntiLockingRegistry<dim>: another one is a class
/// deriving this one, registered by MPM_REGISTER_DIMS with its MPM_SCHEMA in its own .cpp.
template <int dim> class AntiLocking {
public:
    virtual ~AntiLocking() = default;

    /// Replace p.L (grid mass from this step's P2G; the weights those of x^n).
    virtual void apply(Particles<dim>& p, const Grid<dim>& g, const Transfer<dim>& transfer,
                       const BlockSort<dim>& sort, double dt) = 0;

    /// On a periodic lattice or with several ranks: `fold(q)` completes a nodal scalar sum (the
    /// images onto their owners, the halo), set once at set-up. A method without nodal sums
    /// ignores it.
    virtual void setNodalFold(std::function<void(NodeArray<double>&)> /*fold*/) {}

    /// Build the method named by `antiLocking` (none | fBar; default none).
    static std::unique_ptr<AntiLocking> create(const Dictionary& schemes);
};

template <int dim> using AntiLockingRegistry = Registry<AntiLocking<dim>>;

} // namespace mpm
