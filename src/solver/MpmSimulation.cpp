// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/MpmSimulation.hpp"

#include "core/Parallel.hpp"
#include "solver/StateMeasures.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <sstream>

namespace mpm {

template <int dim>
MpmSimulation<dim>::MpmSimulation(const Case& cs, const RunOptions& options,
                                  const Dictionary& gridDict, const Comm& comm)
    : case_(cs), global_(cs.globalRoot()), options_(options), comm_(comm), grid_(gridDict),
      bc_(gridDict, grid_), bodies_(cs, grid_, &bc_.lattice()),
      writer_(cs, bodies_.empty() ? std::vector<std::string>{"particles"}
                                  : std::vector<std::string>{"particles", "rigidBodies"}) {
    gridDict.checkUnknownKeys();
    for (auto& r : reactions_)
        r.setZero();

    acceleration_ = cs.exists("constant/g") ? BodyAcceleration<dim>::create(cs.read("constant/g"))
                                            : BodyAcceleration<dim>::constant(Vec<dim>::Zero());

    materials_ = Material<dim>::createAll(cs.read("constant/materials"));
    for (const auto& m : materials_) {
        maxWaveSpeed_ = std::max(maxWaveSpeed_, m->waveSpeed());
        viscousFactor_ = std::min(viscousFactor_, m->viscousStepFactor(grid_.h()));
        waveOf_.push_back(m->waveSpeed());
        m->declareState(particles_);
    }
    logDerivedConstants();
    if (cs.exists("constant/velocityConstraints")) {
        std::vector<std::string> names;
        for (const auto& m : materials_)
            names.push_back(m->name());
        const Dictionary dict = cs.read("constant/velocityConstraints");
        constraints_ = VelocityConstraints<dim>(dict, names);
        if (bc_.anyPeriodic())
            dict.error("", "velocity constraints are not available with periodic faces");
        reach_.resize(constraints_.size());
        for (auto& r : reach_)
            r.reset(grid_.numNodes());
    }
    if (!bodies_.empty()) {
        coupling_ = std::make_unique<Coupling<dim>>(bodies_.takeCouplingLaws(), &bc_.lattice());
        coupling_->declareState(particles_, bodies_.bodies());
    }

    const Dictionary schemes = cs.read("system/mpmSchemes");
    order_ = StressUpdateOrder::create(schemes);
    damping_ = schemes.getScalarOr("damping", 0.0, Bounds::halfOpen(0.0, 1.0));
    antiLocking_ = AntiLocking<dim>::create(schemes);
    if (bc_.anyPeriodic())
        antiLocking_->setNodalFold(
            [this](NodeArray<double>& q) { bc_.foldField(q, grid_.activeBlocks()); });
    if (std::any_of(materials_.begin(), materials_.end(),
                    [](const auto& m) { return m->criticalDensity() > 0.0; })) {
        phaseDensity_ = std::make_unique<PhaseDensity<dim>>(transPhaseFields(particles_).density);
        if (bc_.anyPeriodic())
            phaseDensity_->setNodalFold(
                [this](NodeArray<double>& q) { bc_.foldField(q, grid_.activeBlocks()); });
    }
    splitting_ = ParticleSplitting<dim>::create(schemes, phaseDensity_ != nullptr, particles_);
    if (splitting_ && coupling_) coupling_->keepNearBodyFlag(particles_);
    // The transfer needs the particle size (GIMP); it is built in start(), so check the
    // schemes' keys now by building one with a provisional width.
    transfer_ = Transfer<dim>::create(schemes, 0.25);
    schemes.checkUnknownKeys();
    if (comm_.parallel()) setUpParallel();
}

template <int dim>
void MpmSimulation<dim>::failIfAny(bool bad, const std::string& phase, Index particle,
                                   const std::string& what) {
    failIf(comm_.any(bad), bad, phase, particle, what);
}

template <int dim>
void MpmSimulation<dim>::failIf(bool anyRank, bool here, const std::string& phase, Index particle,
                                const std::string& what) {
    if (!anyRank) return;
    if (here) fail(phase, particle, what);
    fail(phase, -1, "stopped: another rank failed (its message names the particle)");
}

template <int dim> void MpmSimulation<dim>::pointsSplit() {
    buildMaterialLists();
    lightestMass_ = lightestMass(); // the coupling's stable step follows the lightest point
    if (coupling_) coupling_->setParticles(particles_, comm_);
}

template <int dim> void MpmSimulation<dim>::buildMaterialLists() {
    volumeFromRate_.resize(materials_.size());
    for (std::size_t m = 0; m < materials_.size(); ++m)
        volumeFromRate_[m] = materials_[m]->volumeFromRate();
    materialParticles_.assign(materials_.size(), {});
    for (std::size_t i = 0; i < particles_.size(); ++i)
        materialParticles_[particles_.material[i]].push_back(static_cast<Index>(i));
}

// ---------------------------------------------------------------------------------------------
// The step

template <int dim> void MpmSimulation<dim>::step(double dt) {
    const double t0 = PhaseTimer::now();
    dt_ = dt;
    const bool withBodies = !bodies_.empty() && !preloading_;
    const bool varyingG = !acceleration_->isConstant() && !preloading_;
    if (!preloading_) gravity_ = acceleration_->at(time_->value() - 0.5 * dt); // t + Δt/2
    sortAndComputeWeights();
    const Vec<dim> moment0 = varyingG ? massMoment(particles_, bodies_, comm_) : Vec<dim>::Zero();
    if (withBodies) computeCouplingForces(dt);
    particleToGrid();
    order_->afterParticleToGrid(*this, dt); // USF: L, stress and internal force
    updateGridVelocity(dt);
    gridToParticle(dt);
    order_->afterGridToParticle(*this, dt); // USL: stress; MUSL: remap, L, stress
    if (withBodies) {
        advanceBodies(dt);
        pushPointsOutOfBodies(dt);
        checkBodies();
    }
    // Work of a time-varying g: g(t + Δt/2)·Σ m Δx with the displacements of the step.
    if (varyingG)
        accelerationWork_ += gravity_.dot(massMoment(particles_, bodies_, comm_) - moment0);
    timer_.stepDone(PhaseTimer::now() - t0);
    if (timer_.steps() % 20 == 0) snapshot();
}

template <int dim> void MpmSimulation<dim>::sortAndComputeWeights() {
    auto timer = timer_(PhaseTimer::Sort);
    const double t = preloading_ ? time_->value() : time_->value() - dt_;
    bc_.wrap(particles_); // periodic faces: back across the seam
    bodies_.wrap();
    if (bc_.hasOpen())
        if (const Index left = bc_.removeOutflow(particles_, t)) {
            buildMaterialLists();
            removed_ += left;
        }
    if (splitting_)
        if (const Index split =
                splitting_->apply(particles_, comm_, grid_.h(), nearBodyFlag(particles_));
            split > 0) {
            split_ += split; // the same on every rank
            pointsSplit();
        }
    if (subdomain_) exchangePoints();
    const Index outside = sort_.update(particles_, grid_);
    failIfAny(outside >= 0, "sort", outside, "left the grid");
    // Every ReorderInterval steps (by absolute step index, so a restart reorders at the same
    // steps) store the particles in the order P2G visits them, for locality in P2G and G2P.
    if ((preloading_ ? preloadIndex_ : time_->index()) % ReorderInterval == 0) {
        sort_.visitOrder(reorder_);
        particles_.permute(reorder_, scratch_);
        sort_.update(particles_, grid_);
        buildMaterialLists();
    }
    transfer_->computeWeights(particles_, grid_);
}

template <int dim> void MpmSimulation<dim>::computeCouplingForces(double dt) {
    auto timer = timer_(PhaseTimer::Contact);
    bodies_.clearForces();
    const std::vector<int>* gasified =
        phaseDensity_ ? &particles_.flag(transPhaseFields(particles_).gasified) : nullptr;
    coupling_->computeForces(particles_, bodies_.bodies(), waveOf_, gasified, sort_, grid_, dt);
    if (comm_.parallel()) bodies_.sumForces(comm_); // every rank's points push the bodies
}

template <int dim> void MpmSimulation<dim>::particleToGrid() {
    auto timer = timer_(PhaseTimer::P2G);
    std::vector<Index> blocks = sort_.activeNodeBlocks();
    bc_.closeActiveBlocks(blocks);
    if (subdomain_) {
        auto comm = timer_(PhaseTimer::Comm);
        blocks = subdomain_->halo().exchangeBlocks(blocks);
    }
    grid_.activate(std::move(blocks)); // zero, and the sparse grid follows the material
    if (subdomain_)                    // the conditions act on the nodes this rank updates
        bc_.selectActive(grid_, [&](Index b) { return grid_.isActive(b) && subdomain_->owns(b); });
    else
        bc_.selectActive(grid_);
    transfer_->scatter(particles_, grid_, sort_, order_->forceWithMomentum());
    if (coupling_) // coupling forces of dense points [000 Eq. 19–20]
        transfer_->scatterPointForces(coupling_->gridPoints(), coupling_->gridForces(), grid_);
    if (order_->forceWithMomentum())
        sumGhosts(grid_.mass, grid_.momentum, grid_.force);
    else
        sumGhosts(grid_.mass, grid_.momentum);
    // Periodic faces: image nodes onto their owners; the force once all of it is scattered.
    foldPeriodic(order_->forceWithMomentum() ? FoldAll : FoldMassMomentum);
    if (!constraints_.empty()) markConstrainedNodes();
}

template <int dim> void MpmSimulation<dim>::foldPeriodic(unsigned fields) {
    if (!bc_.anyPeriodic()) return;
    if (!subdomain_) {
        bc_.fold(grid_, grid_.activeBlocks(), fields);
        return;
    }
    auto comm = timer_(PhaseTimer::Comm);
    const PeriodicLattice<dim>& lattice = bc_.lattice();
    if (fields == FoldAll)
        subdomain_->foldPeriodic(lattice, grid_.mass, grid_.momentum, grid_.force);
    else if (fields == FoldMassMomentum)
        subdomain_->foldPeriodic(lattice, grid_.mass, grid_.momentum);
    else
        subdomain_->foldPeriodic(lattice, grid_.force);
}

template <int dim> void MpmSimulation<dim>::markConstrainedNodes() {
    inMaterial_.resize(particles_.size());
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
        const int m = constraints_.material(k);
        for (std::size_t p = 0; p < particles_.size(); ++p)
            inMaterial_[p] = particles_.material[p] == m ? 1.0 : 0.0;
        grid_.forEachNode(grid_.activeBlocks(), [&](Index i) { reach_[k][i] = 0.0; });
        transfer_->scatterScalar(inMaterial_, reach_[k], sort_);
        sumGhosts(reach_[k]); // complete on the nodes updated here
    }
}

template <int dim>
void MpmSimulation<dim>::applyVelocityConstraints(NodeArray<Vec<dim>>& v, double t) {
    if (constraints_.empty() || preloading_) return;
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
        const Vec<dim> w = constraints_.velocity(k, t);
        const NodeArray<double>& reach = reach_[k];
        grid_.forEachNode(updateBlocks(), [&](Index i) {
            if (reach[i] > 0) constraints_.set(k, w, v[i]);
        });
    }
}

template <int dim> void MpmSimulation<dim>::gridVelocityFromMomentum() {
    auto timer = timer_(PhaseTimer::Grid);
    transfer_->velocityFromMomentum(fieldsOf(grid_), updateBlocks());
    bc_.constrain(grid_, grid_.vOld, time_->value() - dt_);
    applyVelocityConstraints(grid_.vOld, time_->value() - dt_);
    copyToGhosts(grid_.vOld);
}

template <int dim> void MpmSimulation<dim>::velocityGradient() {
    auto timer = timer_(PhaseTimer::G2P);
    transfer_->velocityGradient(particles_, grid_);
}

template <int dim> void MpmSimulation<dim>::scatterInternalForce() {
    auto timer = timer_(PhaseTimer::P2G);
    transfer_->scatterForce(particles_, grid_, sort_);
    sumGhosts(grid_.force);
    foldPeriodic(FoldForce);
}

template <int dim> void MpmSimulation<dim>::remapMomentum() {
    auto timer = timer_(PhaseTimer::P2G);
    grid_.forEachNode(grid_.activeBlocks(), [this](Index i) {
        grid_.mass[i] = 0;
        grid_.momentum[i].setZero();
    });
    transfer_->scatter(particles_, grid_, sort_, false);
    sumGhosts(grid_.mass, grid_.momentum);
    foldPeriodic(FoldMassMomentum);
}

template <int dim> void MpmSimulation<dim>::updateGridVelocity(double dt) {
    auto timer = timer_(PhaseTimer::Grid);
    transfer_->updateVelocity(fieldsOf(grid_), updateBlocks(), gravity_, damping_, dt);
    bc_.constrainUpdate(grid_, gravity_, time_->value(), dt, reactions_);
    applyVelocityConstraints(grid_.v, time_->value());
    copyToGhosts(grid_.vOld, grid_.v);
    // Parallel: each rank holds its own nodes' share of the reactions; G2P's exchange sums them.
}

template <int dim> void MpmSimulation<dim>::gridToParticle(double dt) {
    auto timer = timer_(PhaseTimer::G2P);
    const GatherStats st =
        transfer_->gather(particles_, grid_, dt, order_->gradientInGridToParticle());
    if (coupling_) coupling_->applyLocalForces(particles_, dt);
    // The step's figures of every rank in one exchange, not five: the not-finite check, E_k, the
    // fastest and the fastest-moving speed, and the grid update's reactions (each rank's nodes'
    // share). Under load each exchange waits for the other ranks' next time slice
    // (docs/parallel.md, "Ranks under load"). Sums run in rank order, as Comm::sum's: the same
    // bits; a serial run keeps its reactions as they are.
    constexpr int NumReactions = 2 * dim * dim;
    const bool notFinite = st.firstNonFinite >= 0;
    std::array<double, 4 + NumReactions> mine{notFinite ? 1.0 : 0.0, st.kineticEnergy, st.maxSpeed,
                                              st.maxMoveSpeed};
    std::copy_n(reactions_[0].data(), NumReactions, mine.begin() + 4);
    double anyNotFinite = 0.0;
    lastKinetic_ = 0.0;
    maxSpeed_ = 0.0;
    maxMoveSpeed_ = 0.0;
    std::array<double, NumReactions> reactions{};
    for (const auto& rank : comm_.gather(mine)) {
        anyNotFinite = std::max(anyNotFinite, rank[0]);
        lastKinetic_ += rank[1];
        maxSpeed_ = std::max(maxSpeed_, rank[2]);
        maxMoveSpeed_ = std::max(maxMoveSpeed_, rank[3]);
        for (int k = 0; k < NumReactions; ++k)
            reactions[k] += rank[4 + k];
    }
    if (subdomain_) std::copy_n(reactions.begin(), NumReactions, reactions_[0].data());
    failIf(anyNotFinite > 0.0, notFinite, "G2P", st.firstNonFinite,
           "has a velocity that is not finite");
    // The displacement of the step, Δt times the grid velocity the points moved with ([000
    // Eq. 16]), not their new (FLIP) velocity: a point whose FLIP velocity is large moves no
    // farther for it.
    if (maxMoveSpeed_ * dt > grid_.h()) {
        std::ostringstream os;
        os << "moved more than one cell in one step (|v| = " << maxMoveSpeed_ << " m/s, dt = " << dt
           << " s, h = " << grid_.h() << " m): the run is unstable or deltaT is too large";
        fail("G2P", st.fastestMoving, os.str());
    }
    if (lastKinetic_ > energyBudget_) {
        std::ostringstream os;
        os << "is the fastest of a kinetic-energy blow-up: E_k = " << lastKinetic_
           << " J exceeds 10× what the initial state and the body acceleration can supply ("
           << energyBudget_ / 10 << " J)";
        fail("G2P", fastestParticle(particles_), os.str());
    }
}

template <int dim> void MpmSimulation<dim>::updateStress(double dt) {
    auto timer = timer_(PhaseTimer::Constitutive);
    assert(gradientSeen(particles_, grid_,
                        order_->gradientInGridToParticle() ? grid_.v : grid_.vOld) &&
           "the stress update saw no velocity gradient in a non-uniform flow");
    // Kinematics: [L ← L̄ (F̄ anti-locking)], F ← (1 + Δt L) F, V = det(F) V⁰ or, for rate-form
    // materials, V ← V exp(Δt tr L) [002 Eq. 76] (Material::volumeFromRate).
    antiLocking_->apply(particles_, grid_, *transfer_, sort_, dt);
    const Index inverted = particles_.updateDeformation(dt, volumeFromRate_);
    const bool isInverted = inverted < static_cast<Index>(particles_.size());
    if (phaseDensity_) phaseDensity_->apply(particles_, grid_, *transfer_, sort_);
    // A rank with an inverted point updates no stress; one exchange then stops every rank if
    // any had an inverted point or a stress that is not finite (the first material's first).
    Index bad = -1;
    for (std::size_t m = 0; m < materials_.size() && !isInverted && bad < 0; ++m)
        bad = materials_[m]->updateStress(particles_, materialParticles_[m], dt);
    const bool here = isInverted || bad >= 0;
    failIf(comm_.any(here), here, "constitutive", isInverted ? inverted : bad,
           !isInverted ? "has a stress that is not finite"
           : volumeFromRate_[particles_.material[inverted]]
               ? "has a volume that is not finite (velocity gradient not finite)"
               : "has det F <= 0 (inverted element)");
}

template <int dim> void MpmSimulation<dim>::advanceBodies(double dt) {
    auto timer = timer_(PhaseTimer::Bodies);
    bodies_.advance(dt, time_->value() - dt, gravity_);
}

template <int dim> void MpmSimulation<dim>::pushPointsOutOfBodies(double dt) {
    auto timer = timer_(PhaseTimer::Bodies);
    // A point projected out of a body gives its momentum to the body (an impulse): each rank's
    // points change its copy of the bodies, and the ranks add up the changes.
    const std::vector<double> twists = comm_.parallel() ? bodies_.twists() : std::vector<double>{};
    coupling_->enforceGap(particles_, bodies_.bodies(), maxMoveSpeed_ * dt, dt);
    if (comm_.parallel()) bodies_.sumTwistChanges(comm_, twists);
}

template <int dim> void MpmSimulation<dim>::checkBodies() {
    const std::string wrong = bodies_.check(
        grid_, [&](int f, const Vec<dim>& x) { return bc_.open(f, x, time_->value()); });
    if (!wrong.empty()) fail("rigid bodies", -1, wrong);
    // The gap enforcement changed velocities: the CFL speed is taken from the state again, as a
    // restart takes it (a restarted run then steps exactly as an uninterrupted one).
    maxSpeed_ = comm_.max(maxSpeed(particles_, bodies_));
}

// ---------------------------------------------------------------------------------------------
// Output and failure

template class MpmSimulation<2>;
template class MpmSimulation<3>;

std::unique_ptr<Simulation> Simulation::create(const Case& cs, const RunOptions& options,
                                               const Comm& comm) {
    const Dictionary grid = cs.read("constant/grid");
    const int dim = grid.getInt("dimension", Bounds::closed(2, 3));
    if (dim == 2) return std::make_unique<MpmSimulation<2>>(cs, options, grid, comm);
    return std::make_unique<MpmSimulation<3>>(cs, options, grid, comm);
}

} // namespace mpm
