// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "core/Parallel.hpp"
#include "core/Types.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// One material point within the coupling distance r_p of a body (world frame).
template <int dim> struct Contact {
    Index particle;
    double phi;      ///< signed distance of the point to the body surface, ξ [000 Eq. 21] [m]
    Vec<dim> normal; ///< outward body normal at the point
    Vec<dim> vRel;   ///< particle velocity minus the body's rigid velocity there [m/s]
    double rp;       ///< coupling radius r_p = V_p^(1/dim) [000 §3.2] [m]
    double mass;     ///< m_p [kg]
    double wave;     ///< elastic wave speed of the point's material c [m/s]
};

/// A particle–body contact law (constant/rigidBodies `coupling: {type: …}`): the force on each
/// point in contact, computed for all contacts of one body in one call (no per-point virtual
/// dispatch). Friction uses the smoothed Coulomb law [004 Eq. 35–38] with the accumulated slip
/// u_T kept per particle.
template <int dim> class CouplingLaw {
public:
    CouplingLaw(const Dictionary& dict, double h);
    virtual ~CouplingLaw() = default;

    /// Forces on the points (world frame) for this step; `slip` is the per-particle
    /// accumulated slip u_T [m], updated here (and reset for points leaving contact by the
    /// caller).
    virtual void forces(const std::vector<Contact<dim>>& contacts, double dt,
                        std::vector<double>& slip, std::vector<Vec<dim>>& f) const = 0;

    /// True if the law guarantees ξ > 0: points that would end a step closer than
    /// minimumGap(r_p) are projected back out (the barrier); false for penalty springs.
    virtual bool nonPenetrating() const = 0;
    /// The smallest gap a point may end a step at, ξ_min [m].
    double minimumGap(double rp) const { return minGapFraction_ * rp; }

    /// The contact limit on Δt for a point of mass m and wave speed c [000 Eq. 24] [s].
    virtual double stableDeltaT(double m, double c) const = 0;

    double friction() const { return mu_; }

    /// The coupling radius of a point whose default is r_p = (V_p⁰)^(1/dim) [m]: that default,
    /// or a law's own (`sdem`'s `radius`).
    virtual double contactRadius(double rpDefault) const { return rpDefault; }
    /// Width of the band beyond r_p searched every step [m] (`sdem`'s Verlet distance V_d): the
    /// points of φ < r_p + band are the candidates; forces act for φ < r_p only.
    virtual double searchBand() const { return 0.0; }
    /// Where −f acts on the body for contact `c` of a point at x (the body's torque is
    /// (p − x_b) × (−f)): x itself by default [004 Eq. 41–42].
    virtual Vec<dim> contactPoint(const Vec<dim>& x, const Contact<dim>&) const { return x; }
    /// True if the slip of a point out of contact must read 0 at the next contact, wherever the
    /// point went meanwhile (a tangential spring history): the coupling then zeroes every
    /// point's slip outside contact each step, not only those the broad phase visits.
    virtual bool resetsAllSlip() const { return false; }
    /// `gasifiedPoints: grid` (default): a gasified point (ρ̄ < ρ_c of its material) takes its
    /// contact force through the grid like a dense point [000 Eq. 19]; `local`: on its own
    /// velocity after G2P [000 Eq. 20].
    bool gasifiedOnGrid() const { return gasifiedOnGrid_; }

    static std::unique_ptr<CouplingLaw> create(const Dictionary& dict, double h);

protected:
    /// The loop of every law's forces(): f[k] = force(contacts[k]) for each contact, on the
    /// threads when worth it (each contact writes its own f[k] and its point's slip only). A
    /// short loop runs outside any parallel region: even a region of one thread costs a futex
    /// system call (5–10 µs on the project's machine), once per body and step.
    template <class Force>
    static void forEachContact(const std::vector<Contact<dim>>& contacts, std::vector<Vec<dim>>& f,
                               Force&& force) {
        const Index n = static_cast<Index>(contacts.size());
        if (!worthThreads(n)) {
            for (Index k = 0; k < n; ++k)
                f[k] = force(contacts[k]);
            return;
        }
#pragma omp parallel for schedule(static)
        for (Index k = 0; k < n; ++k)
            f[k] = force(contacts[k]);
    }

    /// Tangential force of the smoothed Coulomb law [004 Eq. 35–38] on a point with normal
    /// force fn, advancing its accumulated slip u_T.
    Vec<dim> frictionForce(const Contact<dim>& c, double fn, double dt, double& slip) const;

    double h_;
    double mu_ = 0;               ///< Coulomb friction coefficient [-]
    double slipFraction_ = 0.01;  ///< s_p / r_p of [004 Eq. 36]
    double minGapFraction_ = 0.0; ///< ξ_min / r_p
    bool gasifiedOnGrid_ = true;  ///< gasified points' force through the grid
};

template <int dim> using CouplingLawRegistry = Registry<CouplingLaw<dim>, double>;

} // namespace mpm
