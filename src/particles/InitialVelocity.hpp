// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <memory>

namespace mpm {

/// The initial velocity field of a particle set (`velocity:` of a set in constant/particles):
/// a vector (uniform), or a map chosen by its `type:` key (InitialVelocityRegistry, family
/// `initialVelocity`): `uniform`, `axialMode` (a bar's n-th mode), `radialMode` (a ball's or
/// cylinder's breathing mode [002 Eq. 62]). Evaluated once per point at seeding.
template <int dim> class InitialVelocity {
public:
    virtual ~InitialVelocity() = default;

    /// v(x) [m/s] at the point x [m].
    virtual Vec<dim> at(const Vec<dim>& x) const = 0;

    /// The velocity `set` gives: its `velocity` entry as a vector or a map, zero when absent.
    static std::unique_ptr<InitialVelocity> create(const Dictionary& set);
};

template <class Base, class... Args> class Registry; // case/Registry.hpp
template <int dim> using InitialVelocityRegistry = Registry<InitialVelocity<dim>>;

extern template class InitialVelocity<2>;
extern template class InitialVelocity<3>;

} // namespace mpm
