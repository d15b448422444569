// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryConditions.hpp"
#include "boundary/VelocityConstraints.hpp"
#include "case/Case.hpp"
#include "case/Time.hpp"
#include "contact/Coupling.hpp"
#include "forces/BodyAcceleration.hpp"
#include "grid/Grid.hpp"
#include "io/TimeDirectory.hpp"
#include "materials/Material.hpp"
#include "monitors/FunctionObject.hpp"
#include "parallel/Comm.hpp"
#include "parallel/Subdomain.hpp"
#include "particles/BlockSort.hpp"
#include "particles/ParticleSeeder.hpp"
#include "particles/Particles.hpp"
#include "particles/Splitting.hpp"
#include "rigid/BodySet.hpp"
#include "solver/LastGoodState.hpp"
#include "solver/PhaseTimer.hpp"
#include "solver/Simulation.hpp"
#include "solver/State.hpp"
#include "solver/StressUpdateOrder.hpp"
#include "transfers/AntiLocking.hpp"
#include "transfers/PhaseDensity.hpp"
#include "transfers/Transfer.hpp"

#include <array>
#include <memory>
#include <vector>

namespace mpm {

/// Explicit MPM in dim dimensions: owns the state; step() is the list of phases of
/// docs/architecture.md ("The step").
template <int dim> class MpmSimulation final : public Simulation, private StressPhases {
public:
    /// `cs`: the case, or this rank's processor case (Case::processor) in a parallel run.
    MpmSimulation(const Case& cs, const RunOptions& options, const Dictionary& gridDict,
                  const Comm& comm);

    void start(Time& time) override;
    double stableDeltaT() const override;
    void step(double dt) override;
    void executeFunctions() override;
    void write() override;
    void report(std::ostream& os) const override;
    /// All ranks' points (collective).
    long numParticles() const override { return comm_.sum(static_cast<Index>(particles_.size())); }
    int dimension() const override { return dim; }

    const Particles<dim>& particles() const { return particles_; }
    const Grid<dim>& grid() const { return grid_; }

    /// Read time directory `from` as a restart does (its particles, uniform/time into `time`,
    /// the bodies' state, the body acceleration's work, the walls' contact) and make `time`
    /// the simulation's clock; start() calls it to restart, mpmFoam -postProcess for each time.
    void readTime(Time& time, const std::string& from);
    /// What function objects read (collective in a parallel run: its minima and sums).
    State<dim> state() const {
        State<dim> s(particles_, grid_, materials_, gravity_, reactions_, bodies_.bodies(),
                     *acceleration_, comm_);
        s.minimumGap = comm_.min(coupling_ ? coupling_->minimumGapSeen() : 1e300);
        s.contacts = comm_.sum(coupling_ ? coupling_->numContacts() : Index(0));
        s.time = time_->value();
        s.accelerationWork = accelerationWork_;
        s.minimumGapBeforeProjection =
            comm_.min(coupling_ ? coupling_->minimumGapBeforeProjection() : 1e300);
        return s;
    }

private:
    static constexpr long ReorderInterval = 20;

    // Phases of a step.
    void sortAndComputeWeights();
    void computeCouplingForces(double dt);
    void particleToGrid();
    void updateGridVelocity(double dt);
    void gridToParticle(double dt);
    void advanceBodies(double dt);
    void pushPointsOutOfBodies(double dt);
    void checkBodies();
    /// `constant/velocityConstraints`: which nodes each entry reaches (after P2G) and
    /// v_a ← w_a(t) on them.
    void markConstrainedNodes();
    /// Periodic faces: image nodes onto their owners and back (`fields`, a FoldField set),
    /// across the ranks in a parallel run; nothing without periodic faces.
    void foldPeriodic(unsigned fields);
    void applyVelocityConstraints(NodeArray<Vec<dim>>& v, double t);
    // Phases a stress-update order places (StressPhases).
    void gridVelocityFromMomentum() override;
    void velocityGradient() override;
    void updateStress(double dt) override;
    void scatterInternalForce() override;
    void remapMomentum() override;

    // Set-up.
    void gravityPreload();
    double gimpHalfWidth() const;
    double lightestMass() const; ///< min m_p over every rank [kg]
    void pointsSplit();          ///< after ParticleSplitting added points: lists, masses
    void buildMaterialLists();
    double criticalDeltaT() const;
    /// The limit that governs criticalDeltaT, with its formula and values (log and errors).
    std::string stepLimit() const;
    /// Under USF with a unilateral wall the last update's wall contact is restart state
    /// (`<time>/uniform/wallContact`, BoundaryConditions::constrain).
    bool wallContactIsState() const;
    void readWallContact(const std::string& file);

    // Parallel runs (docs/parallel.md); nothing of it runs in a serial one.
    /// Check the case uses only what a parallel run supports; read the decomposition.
    void setUpParallel();
    /// Log each material's and body's derived constants (cone slope, K0, ρ_c, mass, inertia).
    void logDerivedConstants() const;
    /// Rebalance when due, then send the points whose block another rank owns there (after G2P:
    /// at the start of the step).
    void exchangePoints();
    /// The blocks whose nodes this rank updates: its owned active blocks, or all active ones.
    const std::vector<Index>& updateBlocks() const {
        return subdomain_ ? subdomain_->halo().owned() : grid_.activeBlocks();
    }
    /// Parallel runs: the ghosts' partial sums of node `fields` onto their owners, and the
    /// owners' values back to the ghosts (GridHalo); nothing in a serial run.
    template <class... Fields> void sumGhosts(Fields&... fields) {
        if (!subdomain_) return;
        auto comm = timer_(PhaseTimer::Comm);
        subdomain_->halo().sum(fields...);
    }
    template <class... Fields> void copyToGhosts(Fields&... fields) {
        if (!subdomain_) return;
        auto comm = timer_(PhaseTimer::Comm);
        subdomain_->halo().copy(fields...);
    }
    /// Collective failure check: stops every rank when `bad` holds on any (fail on each).
    void failIfAny(bool bad, const std::string& phase, Index particle, const std::string& what);
    /// The same when every rank already knows `anyRank` (from an exchange it shared with other
    /// figures); `here`: this rank's own `bad`.
    void failIf(bool anyRank, bool here, const std::string& phase, Index particle,
                const std::string& what);

    // Failure handling: keep a recent good state and write it before stopping.
    void snapshot() {
        good_.save(particles_, bodies_, *time_,
                   {accelerationWork_, wallContactIsState()
                                           ? bc_.wallContact()
                                           : std::vector<std::pair<Index, int>>{}});
    }
    [[noreturn]] void fail(const std::string& phase, Index particle, const std::string& what);

    const Case& case_;
    Case global_; ///< the root case (case_ itself in a serial run): postProcessing, .pvtu
    RunOptions options_;
    const Comm& comm_;
    std::unique_ptr<Subdomain<dim>> subdomain_; ///< parallel runs only
    Time* time_ = nullptr;

    Grid<dim> grid_;
    BoundaryConditions<dim> bc_; ///< conditions on the faces' patches, periodic faces
    std::unique_ptr<BodyAcceleration<dim>> acceleration_; ///< g(t) of constant/g
    Vec<dim> gravity_ = Vec<dim>::Zero();                 ///< g of this step: g(t + Δt/2)
    double accelerationWork_ = 0;                         ///< State::accelerationWork [J]
    Particles<dim> particles_;
    PermuteBuffers<dim> scratch_; ///< reorder buffers, kept between reorders
    std::vector<Index> reorder_;  ///< the reorder's permutation (BlockSort::visitOrder)
    std::vector<std::unique_ptr<Material<dim>>> materials_;
    std::vector<char> volumeFromRate_; ///< per material: V from Eq. 76, not det F
    std::vector<std::vector<Index>> materialParticles_;
    std::unique_ptr<Transfer<dim>> transfer_;
    std::unique_ptr<StressUpdateOrder> order_;
    std::unique_ptr<AntiLocking<dim>> antiLocking_; ///< `antiLocking` (none, fBar: F̄)
    /// Particle splitting (`splitting: {maxStretch: …}`), or none
    std::unique_ptr<ParticleSplitting<dim>> splitting_;
    Index split_ = 0; ///< points split in this run, all ranks
    /// The trans-phase density ρ̄_p (PhaseDensity.hpp), with any trans-phase material
    std::unique_ptr<PhaseDensity<dim>> phaseDensity_;
    BlockSort<dim> sort_;
    double dt_ = 0; ///< size of the step under way
    Index removed_ = 0;
    double damping_ = 0;                   ///< local (Cundall) damping coefficient α [-]
    VelocityConstraints<dim> constraints_; ///< none without the file
    std::vector<NodeArray<double>> reach_; ///< per constraint: Σ_p w_ip over its points
    std::vector<double> inMaterial_;       ///< scratch: 1 for the constraint's points
    PreloadSettings preload_;
    /// A fresh start's record of its inputs (io/SeedingRecord.hpp), written by the first write
    /// into <time>/uniform/seeding; empty once written, and on a restart.
    std::string seedingRecord_;
    bool preloading_ = false;
    long preloadIndex_ = 0;
    double lastKinetic_ = 0;
    std::array<Vec<dim>, 2 * dim> reactions_;
    BodySet<dim> bodies_;
    std::unique_ptr<Coupling<dim>> coupling_;
    std::vector<double> waveOf_; ///< per material
    std::vector<std::unique_ptr<FunctionObject<dim>>> functions_;
    io::TimeDirectoryWriter writer_;
    std::unique_ptr<io::TimeDirectoryWriter> rootWriter_; ///< rank 0 of a parallel run: .pvtu

    double maxSpeed_ = 0;
    double maxMoveSpeed_ = 0; ///< largest grid (PIC) speed a point moved with in the last G2P
    double maxWaveSpeed_ = 0;
    double viscousFactor_ = 1; ///< smallest Material::viscousStepFactor of the materials [-]
    double lightestMass_ = 1e300;
    double energyBudget_ = 1e300;
    PhaseTimer timer_;
    LastGoodState<dim> good_;
};

} // namespace mpm
