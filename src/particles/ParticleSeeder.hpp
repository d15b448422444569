// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "grid/Grid.hpp"
#include "materials/Material.hpp"
#include "particles/InitialStress.hpp"
#include "particles/Particles.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace mpm {

/// Seeds the particle sets of constant/particles: each set's region (regular or Poisson-disk
/// seeding), material, initial velocity (a vector, `{type: uniform, value}` or an axial mode
/// `{type: axialMode, amplitude, direction, origin, length, mode}`) and initial stress (none,
/// geostatic σ_v = −ρ|g|(z_s − z), σ_h = K0 σ_v, or a gravity preload run by the solver).
/// `outsideBodies: yes` leaves out the points closer to a rigid body than `bodyClearance` [m]
/// (default half their spacing): fines seeded in the voids of a body skeleton, no point
/// starting inside a body; a larger clearance leaves a gap around every body.
template <int dim> class ParticleSeeder {
public:
    ParticleSeeder(const Grid<dim>& grid,
                   const std::vector<std::unique_ptr<Material<dim>>>& materials,
                   const Vec<dim>& gravity)
        : grid_(grid), materials_(materials), gravity_(gravity) {}

    /// Append the particles of every set of `sets` (constant/particles) to `particles`, whose
    /// model state is declared; materials initialise their points.
    void seed(const Dictionary& sets, Particles<dim>& particles);

    /// The gravity preload a set asked for (requested = false if none).
    const PreloadSettings& preload() const { return preload_; }
    /// The scene's rigid bodies for `outsideBodies: yes`: the signed distance from x to the
    /// nearest body surface [m] (negative inside a body).
    void setBodyDistance(std::function<double(const Vec<dim>&)> distance) {
        bodyDistance_ = std::move(distance);
    }

private:
    const Grid<dim>& grid_;
    const std::vector<std::unique_ptr<Material<dim>>>& materials_;
    Vec<dim> gravity_;
    PreloadSettings preload_;
    std::function<double(const Vec<dim>&)> bodyDistance_; ///< empty: no bodies
};

} // namespace mpm
