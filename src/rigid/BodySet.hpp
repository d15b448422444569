// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/PeriodicLattice.hpp"
#include "case/Case.hpp"
#include "contact/BodyContact.hpp"
#include "contact/CouplingLaw.hpp"
#include "grid/Grid.hpp"
#include "parallel/Comm.hpp"
#include "rigid/RigidBody.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// The rigid bodies of a scene (constant/rigidBodies): owns them, advances them, checks them,
/// keeps their state for restart and for the failure snapshot.
///
/// Body–body contact (constant/bodyContact, a BodyContactLaw) runs inside advance() only when the
/// scene has a law and at least two bodies; otherwise it costs nothing. With it, the bodies
/// sub-step: n = ⌈Δt/Δt_c⌉ steps of Δt/n with the law's stable step Δt_c, contact forces
/// recomputed each sub-step and the coupling forces of the MPM step held. The contact history
/// (tangential springs) is part of the restart state (`<time>/uniform/bodyContacts`).
///
/// Periodic faces: a moving body whose centre has crossed a seam is moved back by the period at
/// the start of a step (wrap), as points are; bodies meet each other through their minimum
/// image (BodyContactLaw) and are never reported as through a periodic face (check).
template <int dim> class BodySet {
public:
    using List = std::vector<std::unique_ptr<RigidBody<dim>>>;

    /// Read constant/rigidBodies (no bodies when the file is absent) and each body's coupling to
    /// the material (`coupling`, default `{type: barrier}`); `grid` checks that a moving body
    /// starts with its centre inside it and warns about level sets coarser than it [004 §5.2].
    /// `lattice`: the periodic faces (kept by reference; nullptr: none). Along a periodic axis a
    /// moving body must have R + h < L/2 (bounding radius R, cell size h, period L): a point
    /// then touches one image of it at most.
    BodySet(const Case& cs, const Grid<dim>& grid, const PeriodicLattice<dim>* lattice = nullptr);

    bool empty() const { return bodies_.empty(); }
    const List& bodies() const { return bodies_; }
    List& bodies() { return bodies_; }

    /// The coupling laws read with the bodies (law b couples body b), handed over once.
    std::vector<std::unique_ptr<CouplingLaw<dim>>> takeCouplingLaws() { return std::move(laws_); }

    void clearForces();
    /// A parallel run: every body's force and torque become the sum over the ranks (each rank
    /// gathered its own points' coupling forces).
    void sumForces(const Comm& comm);
    /// Every body's twist (RigidBody::twist), concatenated.
    std::vector<double> twists() const;
    /// A parallel run: twist = before + Σ over the ranks of (this rank's twist − before).
    void sumTwistChanges(const Comm& comm, const std::vector<double>& before);
    /// Periodic faces: move every moving body whose centre lies outside [lo, hi) along a periodic
    /// axis back by whole periods (PeriodicLattice::wrapPosition); orientation and velocities
    /// unchanged. Nothing without periodic faces.
    void wrap();
    /// True if body–body contact runs (a law and at least two bodies).
    bool hasContact() const { return contact_ != nullptr; }
    const ContactHistory<dim>& contactHistory() const { return history_; }
    /// Advance every body over dt from time t with gravity g and the forces gathered this step
    /// (sub-stepping with body–body contact).
    void advance(double dt, double t, const Vec<dim>& g);
    /// A body whose state is not finite or which has passed through a walled grid face (bodies
    /// do not collide with the walls; one leaving through an open face flies on, one crossing a
    /// periodic face is wrapped at the next step): what is wrong, or empty.
    /// `open(face, x)`: whether face `face` lets a body at x through.
    std::string check(const Grid<dim>& grid,
                      const std::function<bool(int, const Vec<dim>&)>& open) const;
    /// Signed distance from x to the nearest body surface (through periodic faces: to each
    /// body's image nearest x) [m], negative inside a body; 1e300 without bodies.
    double distance(const Vec<dim>& x) const;
    /// Largest rim speed |v| + |ω| R of a moving body [m/s] (the CFL counts bodies too).
    double maxRimSpeed() const;
    /// True if a prescribed or driven body can do unbounded work on the material.
    bool driven() const;
    /// Σ ½ m v² + ½ ωᵀIω + m |g| L: what the bodies can supply to a blow-up (L: the grid extent).
    double energyBudget(double gravityTimesExtent) const;

    /// State of every body (RigidBody::writeState text) and, last, the contact history, for the
    /// failure snapshot.
    std::vector<std::string> saveState() const;
    void restoreState(const std::vector<std::string>& state);
    /// Write `<time>/rigidBodies.vtp` and `<time>/uniform/rigidBodies` into `dir`.
    void write(const std::filesystem::path& dir) const;
    /// Read `<timeDir>/uniform/rigidBodies` of a restart.
    void read(const Case& cs, const std::string& timeDir);

private:
    List bodies_;
    const PeriodicLattice<dim>* lattice_ = nullptr; ///< null without periodic faces
    std::vector<std::unique_ptr<CouplingLaw<dim>>> laws_;
    std::unique_ptr<BodyContactLaw<dim>> contact_;
    ContactHistory<dim> history_;

    std::string historyText() const;
    void readHistory(const Dictionary& dict);
};

} // namespace mpm
