// SPDX-License-Identifier: GPL-3.0-or-later
// MpmSimulation: starting a run (fresh, restarted or decomposed), its time-step limits and the
// constants it logs.
#include "solver/MpmSimulation.hpp"

#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "io/ParticleIO.hpp"
#include "io/PvtuFile.hpp"
#include "io/SeedingRecord.hpp"
#include "solver/GravityPreload.hpp"
#include "solver/StateMeasures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace mpm {

template <int dim> void MpmSimulation<dim>::logDerivedConstants() const {
    std::ostringstream os;
    for (const auto& m : materials_)
        os << "Material " << m->name() << ":\n" << m->describe();
    const char* per = dim == 2 ? "/m" : "";
    for (const auto& b : bodies_.bodies()) {
        os << "Body " << b->name() << ": mass " << b->mass() << " kg" << per << ", centroid ("
           << b->position().transpose() << ") m, principal inertia ";
        if constexpr (dim == 2)
            os << b->inertia()[2];
        else
            os << '(' << b->inertia().transpose() << ')';
        os << " kg m2" << per << '\n';
    }
    if (splitting_)
        os << "Particle splitting: a point splits in two when its domain is stretched beyond "
           << splitting_->maxStretch()
           << (splitting_->byDefault() ? " (the default with a granular material; splitting: off "
                                         "to disable)"
                                       : "")
           << '\n';
    log() << os.str() << '\n';
}

template <int dim> void MpmSimulation<dim>::setUpParallel() {
    subdomain_ = std::make_unique<Subdomain<dim>>(
        case_, grid_, comm_, [this](std::vector<Index>& blocks) { bc_.closeActiveBlocks(blocks); });
    // A unilateral wall's contact under USF is restart state on the nodes a rank owns: it
    // would not follow the nodes to their new owner after a rebalance (docs/parallel.md).
    if (wallContactIsState() && subdomain_->rebalances())
        throw InputError("system/decomposeParDict", 0, "rebalance",
                         "rebalancing is not available with a unilateral wall (slip, friction, "
                         "velocity) under a USF stress update: the walls' contact state "
                         "stays with the rank that owned its nodes; remove rebalance or use USL");
    // F̄'s and the trans-phase density's nodal sums: complete on every node a rank reads,
    // ghosts included.
    const auto fold = [this](NodeArray<double>& q) {
        auto comm = timer_(PhaseTimer::Comm);
        subdomain_->halo().sum(q);
        if (bc_.anyPeriodic()) subdomain_->foldPeriodic(bc_.lattice(), q);
        subdomain_->halo().copy(q, grid_.mass);
    };
    antiLocking_->setNodalFold(fold);
    if (phaseDensity_) phaseDensity_->setNodalFold(fold);
    if (comm_.master())
        rootWriter_ = std::make_unique<io::TimeDirectoryWriter>(
            global_, bodies_.empty() ? std::vector<std::string>{"particles"}
                                     : std::vector<std::string>{"particles", "rigidBodies"});
}

template <int dim> void MpmSimulation<dim>::exchangePoints() {
    auto timer = timer_(PhaseTimer::Comm);
    const long step = preloading_ ? preloadIndex_ : time_->index();
    if (subdomain_->exchangePoints(particles_, step, scratch_)) buildMaterialLists();
}

template <int dim> void MpmSimulation<dim>::start(Time& time) {
    time_ = &time;
    // Parallel: the latest time every processor holds complete, agreed by all ranks.
    std::string from = io::restartDirectory(case_, time, comm_);
    // A time directory the seeding wrote (its uniform/seeding record) whose inputs changed since
    // (a new cellSize, particle set or material): seed again, as a fresh start would.
    if (!from.empty()) {
        const std::string change = io::seedingChange(case_, from);
        if (comm_.any(!change.empty())) {
            log() << "Not restarting from time " << from << ": "
                  << (change.empty() ? "its inputs have changed" : change)
                  << " since it was seeded (" << case_.displayName(from + "/uniform/seeding")
                  << "); seeding again\n";
            from.clear();
        }
    }
    const bool fresh = from.empty();
    if (fresh) {
        gravity_ = acceleration_->at(time.startFrom() == "startTime" ? time.startTime() : 0.0);
        ParticleSeeder<dim> seeder(grid_, materials_, gravity_);
        if (!bodies_.empty())
            seeder.setBodyDistance([this](const Vec<dim>& x) { return bodies_.distance(x); });
        seeder.seed(case_.read("constant/particles"), particles_);
        bc_.wrap(particles_);
        if (subdomain_) subdomain_->keepOwned(particles_);
        preload_ = seeder.preload();
        seedingRecord_ = io::seedingRecord(io::seedingInputs(case_, preload_.requested));
        time.setStart(time.startFrom() == "startTime" ? time.startTime() : 0.0, 0, 0.0);
    } else {
        readTime(time, from);
        log() << "Restart from time " << from << " (" << particles_.size() << " particles)\n";
    }
    buildMaterialLists();
    if (coupling_) coupling_->setParticles(particles_, comm_);
    transfer_ = Transfer<dim>::create(case_.read("system/mpmSchemes"), gimpHalfWidth());
    if (fresh && preload_.requested) gravityPreload();

    maxSpeed_ = comm_.max(maxSpeed(particles_, bodies_));
    lightestMass_ = lightestMass();
    const std::string limit = stepLimit();
    log() << "Stable deltaT: " << criticalDeltaT() << " s, limit " << limit << "\n";
    time.checkFixedDeltaT(criticalDeltaT(), limit);
    std::array<bool, 3> periodic{};
    for (int d = 0; d < dim; ++d)
        periodic[d] = bc_.periodic(d);
    energyBudget_ = energyBudget(particles_, materials_, bodies_, *acceleration_, gravity_, grid_,
                                 periodic, comm_);

    if (!options_.noFunctionObjects) functions_ = FunctionObject<dim>::createAll(time.dict());
    for (auto& f : functions_)
        f->prepare(state(), time); // every check before anything is written
    snapshot();
    if (options_.dryRun) return;
    if (!fresh && time.endReached()) return; // a finished case: nothing to open or write
    for (auto& f : functions_)
        f->open(global_, time, comm_.master());
    if (fresh) {
        write();
        for (auto& f : functions_)
            f->executeNow(state(), time);
    }
}

template <int dim> void MpmSimulation<dim>::readTime(Time& time, const std::string& from) {
    time_ = &time;
    io::readParticles(case_, from, particles_, materials_.size());
    if (subdomain_) {
        subdomain_->readTime(case_, from);
        subdomain_->exchangePoints(particles_, -1, scratch_); // no rebalance at step -1
    }
    time.readTimeDict(from);
    if (!bodies_.empty()) bodies_.read(case_, from);
    gravity_ = acceleration_->at(time.value());
    if (!acceleration_->isConstant())
        accelerationWork_ = case_.read(from + "/uniform/accelerationWork").getScalar("work");
    if (wallContactIsState()) {
        const std::string file = from + "/uniform/wallContact";
        if (case_.exists(file))
            readWallContact(file);
        else
            log() << "No " << file << ": the walls start released, as in a fresh run\n";
    }
}

template <int dim> double MpmSimulation<dim>::lightestMass() const {
    const auto& m = particles_.mass; // restarting from an empty file is allowed
    return comm_.min(m.empty() ? 1e300 : *std::min_element(m.begin(), m.end()));
}

template <int dim> double MpmSimulation<dim>::gimpHalfWidth() const {
    // GIMP's particle half-width l_p = ½ V_p^(1/dim), in cell units, from the mean seeding volume.
    // The sum in fixed point (units of 2⁻⁵² h): integer sums are exact, so l_p is the same for
    // any order of the points, on any number of threads or ranks and after a restart (GIMP
    // weights at the support's edge are that sensitive: docs/parallel.md).
    // A point split k times (ParticleSplitting) stands for 2⁻ᵏ of its seed, whose V⁰ is 2ᵏ its
    // own: weighted so, its children give the seed's share exactly, restarted or not.
    __extension__ using Int128 = __int128;
    constexpr int Deepest = ParticleSplitting<dim>::MaxLevel;
    const std::vector<int>* levels = splitting_ ? &splitting_->levels(particles_) : nullptr;
    Int128 sum = 0, count = 0;
    for (std::size_t i = 0; i < particles_.size(); ++i) {
        const int k = levels ? (*levels)[i] : 0;
        const double side = std::pow(std::ldexp(particles_.volume0[i], k), 1.0 / dim);
        sum += Int128(std::llround(std::ldexp(side * grid_.invH(), 52))) << (Deepest - k);
        count += Int128(1) << (Deepest - k);
    }
    Int128 total = 0, seeds = 0;
    for (const Int128 part : comm_.gather(sum))
        total += part;
    for (const Int128 part : comm_.gather(count))
        seeds += part;
    return 0.5 * std::ldexp(static_cast<double>(total), -52) / static_cast<double>(seeds);
}

template <int dim> void MpmSimulation<dim>::gravityPreload() {
    // [000 §4.2]: damped loading by gravity; then velocities are zeroed and the run starts at
    // t = 0 from the preloaded state.
    const double savedDamping = damping_;
    damping_ = preload_.damping;
    preloading_ = true;
    maxSpeed_ = 0;
    const double window = preloadWindow(gravity_, Vec<dim>(grid_.hi() - grid_.lo()), maxWaveSpeed_);
    runGravityPreload(preload_, window, [&](long k, double& dt) {
        dt = time_->maxCo() * grid_.h() / (maxWaveSpeed_ + maxSpeed_) * viscousFactor_;
        preloadIndex_ = k;
        step(dt); // the material only: bodies wait while preloading_
        return lastKinetic_;
    });
    particles_.stop();
    maxSpeed_ = 0;
    damping_ = savedDamping;
    preloading_ = false;
    timer_.reset();
    if (subdomain_) subdomain_->halo().resetBytes();
}

template <int dim> double MpmSimulation<dim>::criticalDeltaT() const {
    // The viscous limit [002 Eq. 79] as a factor on the CFL limit: the smallest factor of all
    // materials with the largest wave speed (conservative for mixed materials, exact for one).
    double dt = grid_.h() / (maxWaveSpeed_ + maxSpeed_) * viscousFactor_;
    if (coupling_) dt = std::min(dt, coupling_->stableDeltaT(lightestMass_, maxWaveSpeed_));
    return dt;
}

template <int dim> std::string MpmSimulation<dim>::stepLimit() const {
    std::ostringstream os; // the governing limit, its formula and values
    const double cfl = grid_.h() / (maxWaveSpeed_ + maxSpeed_);
    const double contact =
        coupling_ ? coupling_->stableDeltaT(lightestMass_, maxWaveSpeed_) : 1e300;
    if (contact < cfl * viscousFactor_)
        os << "of the coupling's contact stiffness (the material's limit is "
           << cfl * viscousFactor_ << " s)";
    else if (viscousFactor_ < 1.0)
        os << "viscous, h/(c + |v|max) (sqrt(thetaHat^2 + 1) - thetaHat) [002 Eq. 79] (h = "
           << grid_.h() << " m, c = " << maxWaveSpeed_ << " m/s, |v|max = " << maxSpeed_
           << " m/s, thetaHat = " << 0.5 * (1.0 / viscousFactor_ - viscousFactor_)
           << "; inviscid it would be " << cfl << " s)";
    else
        os << "h/(c + |v|max) (h = " << grid_.h() << " m, c = " << maxWaveSpeed_
           << " m/s, |v|max = " << maxSpeed_ << " m/s)";
    return os.str();
}

template <int dim> double MpmSimulation<dim>::stableDeltaT() const {
    return time_->maxCo() * criticalDeltaT();
}

template <int dim> bool MpmSimulation<dim>::wallContactIsState() const {
    return bc_.hasUnilateral() && order_->gradientBeforeUpdate();
}

template <int dim> void MpmSimulation<dim>::readWallContact(const std::string& file) {
    const Dictionary d = case_.read(file);
    const std::vector<double> nodes = d.getVector("nodes");
    const std::vector<double> flags = d.getVector("flags", static_cast<int>(nodes.size()));
    d.checkUnknownKeys();
    std::vector<std::pair<Index, int>> contact;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const bool node = nodes[k] >= 0 && nodes[k] < static_cast<double>(grid_.numFileNodes()) &&
                          nodes[k] == std::floor(nodes[k]);
        if (!node) d.error("nodes", "entry " + std::to_string(k) + " is not a node of the grid");
        if (!(flags[k] >= 1 && flags[k] < (1 << dim) && flags[k] == std::floor(flags[k])))
            d.error("flags", "entry " + std::to_string(k) + " is not an axis bit set (1 to " +
                                 std::to_string((1 << dim) - 1) + ")");
        contact.emplace_back(grid_.nodeOfFileIndex(static_cast<Index>(nodes[k])),
                             static_cast<int>(flags[k]));
    }
    bc_.setWallContact(contact);
}

// The members above, for both dimensions (the class itself is instantiated in MpmSimulation.cpp).
#define MPM_SIMULATION_RUN(D)                                                                      \
    template void MpmSimulation<D>::logDerivedConstants() const;                                   \
    template void MpmSimulation<D>::setUpParallel();                                               \
    template void MpmSimulation<D>::exchangePoints();                                              \
    template void MpmSimulation<D>::start(Time&);                                                  \
    template void MpmSimulation<D>::readTime(Time&, const std::string&);                           \
    template double MpmSimulation<D>::lightestMass() const;                                        \
    template double MpmSimulation<D>::gimpHalfWidth() const;                                       \
    template void MpmSimulation<D>::gravityPreload();                                              \
    template double MpmSimulation<D>::criticalDeltaT() const;                                      \
    template std::string MpmSimulation<D>::stepLimit() const;                                      \
    template double MpmSimulation<D>::stableDeltaT() const;                                        \
    template bool MpmSimulation<D>::wallContactIsState() const;                                    \
    template void MpmSimulation<D>::readWallContact(const std::string&);
MPM_SIMULATION_RUN(2)
MPM_SIMULATION_RUN(3)
#undef MPM_SIMULATION_RUN

} // namespace mpm
