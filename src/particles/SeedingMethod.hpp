// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"
#include "particles/Region.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace mpm {

/// How a particle set fills its region (`seeding.method` of a set in constant/particles;
/// SeedingMethodRegistry, family `seedingMethods`): `regular` (n points per cell and direction
/// at sub-cell centres) or `poissonDisk` (Bridson). Chosen once per set at start.
template <int dim> class SeedingMethod {
public:
    virtual ~SeedingMethod() = default;

    /// The points in `region` of a grid with origin `origin` and cell size h [m].
    virtual std::vector<Vec<dim>> positions(const Region<dim>& region, const Vec<dim>& origin,
                                            double h) const = 0;
    /// The volume a point stands for as seeded [m^dim], `n` the points `positions` gave.
    virtual double nominalVolume(const Region<dim>& region, double h, std::size_t n) const = 0;
    /// Each point's volume: `nominal` for every point unless the method computes its own
    /// (`poissonDisk` with `volumes: voronoi`: its Voronoi cell in the region, outside `inBody`).
    virtual std::vector<double> volumes(const Region<dim>& region, const std::vector<Vec<dim>>& xs,
                                        double nominal, double h,
                                        const std::function<bool(const Vec<dim>&)>& inBody) const;

    /// The method `set` gives: `seeding: {method: …, …}`, `regular` with 2 points per
    /// direction when absent. Reads and checks the keys of `seeding`.
    static std::unique_ptr<SeedingMethod> create(const Dictionary& set);
};

template <class Base, class... Args> class Registry; // case/Registry.hpp
template <int dim> using SeedingMethodRegistry = Registry<SeedingMethod<dim>>;

extern template class SeedingMethod<2>;
extern template class SeedingMethod<3>;

} // namespace mpm
