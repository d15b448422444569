// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "case/Time.hpp"
#include "contact/Coupling.hpp"
#include "grid/Grid.hpp"
#include "io/PvdIndex.hpp"
#include "materials/Material.hpp"
#include "monitors/FunctionObject.hpp"
#include "particles/BlockSort.hpp"
#include "particles/Particles.hpp"
#include "rigid/RigidBody.hpp"
#include "solver/Simulation.hpp"
#include "transfers/FBar.hpp"
#include "transfers/Transfer.hpp"

#include <array>
#include <memory>
#include <vector>

namespace mpm {

/// Wall time spent in each phase of the step [s].
struct PhaseTimes {
    double sort = 0, contact = 0, p2g = 0, grid = 0, g2p = 0, constitutive = 0, bodies = 0, io = 0,
           functions = 0;
};

/// Explicit MPM in dim dimensions: owns the state; step() is the list of phases of DESIGN §4.
template <int dim> class MpmSimulation final : public Simulation {
public:
    MpmSimulation(const Case& cs, const RunOptions& options, const Dictionary& gridDict);

    void start(Time& time) override;
    double stableDeltaT() const override;
    void step(double dt) override;
    void executeFunctions() override;
    void write() override;
    void report(std::ostream& os) const override;
    long numParticles() const override { return static_cast<long>(particles_.size()); }
    int dimension() const override { return dim; }

    const Particles<dim>& particles() const { return particles_; }
    const Grid<dim>& grid() const { return grid_; }

private:
    static constexpr long ReorderInterval = 20;

    // Phases of a step.
    void sortParticles();
    void removeOutflow();
    void particleToGrid();
    void gridVelocity();
    void updateStress(double dt);
    void scatterInternalForce();
    void gridUpdate(double dt);
    void gridToParticle(double dt);
    void remapVelocity();
    void couple(double dt);
    void advanceBodies(double dt);

    // Set-up.
    void readRigidBodies();
    void gravityPreload();
    double gimpHalfWidth() const;
    void seed();
    void restart(const std::string& timeDir);
    void buildMaterialLists();
    void checkDeltaT() const;
    void applyBoundaryConditions(bool recordReactions, double dt);

    // Failure handling: keep a recent good state and write it before stopping.
    void snapshot();
    [[noreturn]] void fail(const std::string& phase, Index particle, const std::string& what);
    State<dim> state() const {
        return {particles_,
                grid_,
                materials_,
                gravity_,
                reactions_,
                bodies_,
                coupling_ ? coupling_->minimumGapSeen() : 1e300,
                coupling_ ? coupling_->numContacts() : 0,
                coupling_ ? coupling_->minimumGapBeforeProjection() : 1e300};
    }

    const Case& case_;
    RunOptions options_;
    Time* time_ = nullptr;

    Grid<dim> grid_;
    Vec<dim> gravity_ = Vec<dim>::Zero();
    Particles<dim> particles_;
    Particles<dim> scratch_; ///< reorder buffers, kept between reorders
    std::vector<std::unique_ptr<Material<dim>>> materials_;
    std::vector<std::string> materialNames_;
    std::vector<std::vector<Index>> materialParticles_;
    std::unique_ptr<Transfer<dim>> transfer_;
    std::unique_ptr<FBar<dim>> fBar_; ///< F̄ anti-locking (`antiLocking: fBar`), or none
    BlockSort<dim> sort_;
    bool usf_ = false;
    bool musl_ = false;
    bool hasOpenFace_ = false;
    Index removed_ = 0;
    double damping_ = 0; ///< local (Cundall) damping coefficient α [-]
    /// Gravity preload stage [000 §4.2] (`initialStress: gravityPreload` in constant/particles).
    struct Preload {
        bool requested = false;
        double damping = 0.5;    ///< local damping during the preload
        double tolerance = 1e-4; ///< stop when E_k ≤ tolerance · peak E_k
        long maxSteps = 20000;
    } preload_;
    bool preloading_ = false;
    long preloadIndex_ = 0;
    double lastKinetic_ = 0;
    std::vector<Index> activeBlocks_;
    std::vector<char> touched_; ///< face nodes already given a reaction this step
    std::array<Vec<dim>, 2 * dim> reactions_;
    std::vector<std::unique_ptr<RigidBody<dim>>> bodies_;
    std::unique_ptr<Coupling<dim>> coupling_;
    std::vector<double> waveOf_, criticalDensityOf_; ///< per material
    std::vector<std::unique_ptr<FunctionObject<dim>>> functions_;
    std::unique_ptr<io::PvdIndex> pvd_, bodiesPvd_;

    double maxSpeed_ = 0;
    double maxMoveSpeed_ = 0; ///< largest grid (PIC) speed a point moved with in the last G2P
    double maxWaveSpeed_ = 0;
    double lightestMass_ = 1e300;
    double energyBudget_ = 1e300;
    long steps_ = 0;
    double stepWall_ = 0;
    PhaseTimes times_;

    Particles<dim> good_;
    std::vector<std::string> goodBodies_; ///< body states at the snapshot (writeState text)
    double goodTime_ = 0, goodDeltaT_ = 0;
    long goodIndex_ = 0;
    bool hasGood_ = false;
};

} // namespace mpm
