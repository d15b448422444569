// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"

#include <memory>

namespace mpm {

/// The phases of a step a stress-update order arranges (implemented by MpmSimulation).
class StressPhases {
public:
    /// v_i = (m v)_i / m_i from this P2G, boundary conditions applied (no reactions).
    virtual void gridVelocityFromMomentum() = 0;
    /// L_p = Σ_i v_i ⊗ ∇w_ip from that velocity [002 Eq. 75].
    virtual void velocityGradient() = 0;
    /// F ← (1 + Δt L) F, V = det F V⁰, σ by the materials.
    virtual void updateStress(double dt) = 0;
    /// f_i = −Σ_p V_p σ_p ∇w_ip (the force P2G left out).
    virtual void scatterInternalForce() = 0;
    /// P2G again of the updated particle momenta with the step's weights (those of x^n).
    virtual void remapMomentum() = 0;

protected:
    ~StressPhases() = default;
};

/// Where in the step the stress is updated (system/mpmSchemes `stressUpdate`), chosen once:
///  - USL (update stress last): P2G scatters the internal force of the last stress with the
///    momentum; G2P takes L from the updated grid velocity; the stress is updated after G2P.
///  - USF (update stress first, [001], [002 §3.3]): after P2G the grid velocity gives L, the
///    stress is updated and its internal force scattered before the grid update.
///  - MUSL (modified USL, Sulsky et al. 1995): as USL, but after G2P the updated momenta are
///    projected back to the grid and L is taken from that velocity, which removes the
///    contribution of nodes with vanishing mass from L.
/// The orders are the family `stressUpdateOrders` of StressUpdateOrderRegistry: another one is a
/// class deriving this one, registered by MPM_REGISTER with its MPM_SCHEMA in its own .cpp.
class StressUpdateOrder {
public:
    virtual ~StressUpdateOrder() = default;
    /// P2G scatters the internal force with mass and momentum.
    virtual bool forceWithMomentum() const = 0;
    /// G2P computes L from the updated grid velocity.
    virtual bool gradientInGridToParticle() const = 0;
    /// L is taken before this step's grid update, so it sees the wall contact of the last one
    /// (BoundaryConditions::constrain): that contact is restart state.
    virtual bool gradientBeforeUpdate() const { return false; }
    /// What follows P2G before the grid update.
    virtual void afterParticleToGrid(StressPhases&, double /*dt*/) const {}
    /// What follows G2P.
    virtual void afterGridToParticle(StressPhases&, double /*dt*/) const {}

    /// Build the order named by `stressUpdate` (USF | USL | MUSL; default USL), once at set-up.
    static std::unique_ptr<StressUpdateOrder> create(const Dictionary& schemes);
};

/// The stress-update orders by name (dimension-independent: the family's registry of
/// dimension 0).
using StressUpdateOrderRegistry = Registry<StressUpdateOrder>;

} // namespace mpm
