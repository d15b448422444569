// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <memory>
#include <vector>

namespace mpm {

/// Gravity preload stage [000 §4.2] (`initialStress: {type: gravityPreload, …}` of a set).
struct PreloadSettings {
    bool requested = false;
    double damping = 0.5;    ///< local damping during the preload
    double tolerance = 1e-4; ///< stop when E_k ≤ tolerance · peak E_k
    long maxSteps = 20000;
};

/// The initial stress of a particle set (`initialStress:` of a set in constant/particles, a word
/// or a map; InitialStressRegistry, family `initialStress`): `none`, `geostatic`
/// (σ_v = −ρ|g|(z_s − z), σ_h = K0 σ_v) or `gravityPreload` (the solver settles the material
/// under gravity first [000 §4.2]). Chosen once per set at start.
template <int dim> class InitialStress {
public:
    virtual ~InitialStress() = default;

    /// True when the stress needs gravity (constant/g non-zero).
    virtual bool needsGravity() const { return false; }
    /// Told the set's points and their spacing V^(1/dim) [m] before `at` is asked.
    virtual void place(const std::vector<Vec<dim>>& /*xs*/, double /*spacing*/) {}
    /// σ₀ [Pa] (tension positive) at x of a material of density ρ [kg/m^3].
    virtual Mat3 at(const Vec<dim>& /*x*/, double /*rho*/) const { return Mat3::Zero(); }
    /// True when a point starts from the elastic stretch of its prestress, F = (bᵉ)^½.
    virtual bool prestretches() const { return false; }
    /// The gravity preload it asks for (requested = false: none).
    virtual PreloadSettings preload() const { return {}; }

    /// The initial stress `set` gives (`none` when absent), `K0` the material's default
    /// coefficient of earth pressure at rest and `gravity` constant/g's [m/s^2]. A type that
    /// needs gravity where there is none is an InputError at `initialStress`.
    static std::unique_ptr<InitialStress> create(const Dictionary& set, double K0,
                                                 const Vec<dim>& gravity);
};

template <class Base, class... Args> class Registry; // case/Registry.hpp
template <int dim> using InitialStressRegistry = Registry<InitialStress<dim>, double, Vec<dim>>;

extern template class InitialStress<2>;
extern template class InitialStress<3>;

} // namespace mpm
