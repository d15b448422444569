// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "core/Types.hpp"

#include <memory>
#include <string>

namespace mpm {

/// The body acceleration g(t) [m/s²] of constant/g, acting on every material point and every
/// free rigid body: gravity, or gravity seen from an accelerating frame (a vibrated plate
/// [002 §4.5], a tilting incline [002 §4.2]). Chosen by `type:` (constant, sinusoidal, ramp,
/// table); a file with `value:` and no `type:` is constant.
template <int dim> class BodyAcceleration {
public:
    virtual ~BodyAcceleration() = default;

    /// g(t) [m/s²] at simulated time t [s].
    virtual Vec<dim> at(double t) const = 0;
    /// True if g does not depend on time; only then is −g·x a potential [J/kg].
    virtual bool isConstant() const = 0;
    /// The largest |g(t)| over all time [m/s²].
    virtual double maxMagnitude() const = 0;
    /// Total variation V = ∫ |dg/dt| dt over all time [m/s²]: 0 for a constant field, +inf for
    /// a periodic one.
    virtual double totalVariation() const = 0;

    /// Upper bound of the work [J] the field can do on `mass` [kg] moving within a region of
    /// diameter `extent` [m] (the grid's diagonal). For one point, by parts,
    /// W = ∫ m g·ẋ dt = m g(T)·(x(T) − x₀) − ∫ m ġ·(x − x₀) dt ≤ m extent (|g|max + V);
    /// for a constant g this is m |g| extent, the largest drop in potential. The sinusoidal
    /// field overrides it (V is infinite). The solver's blow-up check bounds the kinetic energy
    /// by the initial energy plus this.
    virtual double energySupply(double mass, double extent) const;

    /// The field described by constant/g's dictionary (checks its unknown keys).
    static std::unique_ptr<BodyAcceleration> create(const Dictionary& dict);
    /// A constant field g (no constant/g: zero).
    static std::unique_ptr<BodyAcceleration> constant(const Vec<dim>& g);
};

template <int dim> using BodyAccelerationRegistry = Registry<BodyAcceleration<dim>>;

} // namespace mpm
