// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/MpmSimulation.hpp"
#include "core/Parallel.hpp"

#include "core/Log.hpp"
#include "core/SymmetricEigen.hpp"
#include "io/ParticleFile.hpp"
#include "particles/Region.hpp"
#include "particles/Seeding.hpp"
#include "rigid/LevelSetShape.hpp"
#include "rigid/RigidBodyOutput.hpp"
#include "solver/Reduce.hpp"

#include <omp.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace mpm {

namespace fs = std::filesystem;

namespace {

double wallTime() {
    return omp_get_wtime();
}

/// Adds the wall time of a scope to a phase counter.
class ScopedTimer {
public:
    explicit ScopedTimer(double& acc) : acc_(acc), t0_(wallTime()) {}
    ~ScopedTimer() { acc_ += wallTime() - t0_; }
    ScopedTimer(const ScopedTimer&) = delete;
    ScopedTimer& operator=(const ScopedTimer&) = delete;

private:
    double& acc_;
    double t0_;
};

template <int dim> Vec<dim> toVec(const std::vector<double>& v) {
    Vec<dim> r;
    for (int d = 0; d < dim; ++d)
        r[d] = v[d];
    return r;
}

/// Initial velocity of a particle set: a vector, or {type: uniform, value} or
/// {type: axialMode, amplitude, direction, origin, length, mode}: the n-th mode of a bar fixed
/// at `origin`, v = A sin((2n - 1)π s / 2L) d with s = (x - origin)·d.
template <int dim> class InitialVelocity {
public:
    explicit InitialVelocity(const Dictionary& set) {
        if (!set.isDict("velocity")) {
            value_ = toVec<dim>(set.getVectorOr("velocity", std::vector<double>(dim, 0.0), dim));
            return;
        }
        const Dictionary d = set.subDict("velocity");
        const std::string type = d.getWord("type", {"uniform", "axialMode"});
        if (type == "uniform") {
            value_ = toVec<dim>(d.getVector("value", dim));
        } else {
            mode_ = true;
            amplitude_ = d.getScalar("amplitude");
            direction_ = toVec<dim>(d.getVector("direction", dim));
            if (direction_.norm() == 0) d.error("direction", "direction must not be zero");
            direction_.normalize();
            origin_ = toVec<dim>(d.getVectorOr("origin", std::vector<double>(dim, 0.0), dim));
            length_ = d.getScalar("length", Bounds::positive());
            n_ = d.getIntOr("mode", 1, Bounds::closed(1, 1000));
        }
        d.checkUnknownKeys();
    }
    Vec<dim> at(const Vec<dim>& x) const {
        if (!mode_) return value_;
        const double s = (x - origin_).dot(direction_);
        return amplitude_ * std::sin((2 * n_ - 1) * M_PI * s / (2.0 * length_)) * direction_;
    }

private:
    Vec<dim> value_ = Vec<dim>::Zero();
    bool mode_ = false;
    double amplitude_ = 0, length_ = 1;
    int n_ = 1;
    Vec<dim> direction_ = Vec<dim>::Zero(), origin_ = Vec<dim>::Zero();
};

} // namespace

template <int dim>
MpmSimulation<dim>::MpmSimulation(const Case& cs, const RunOptions& options,
                                  const Dictionary& gridDict)
    : case_(cs), options_(options), grid_(gridDict) {
    gridDict.checkUnknownKeys();
    for (auto& r : reactions_)
        r.setZero();
    for (const auto& f : grid_.faces())
        hasOpenFace_ |= f.kind == FaceCondition::Kind::Open;

    if (cs.exists("constant/g")) {
        const Dictionary g = cs.read("constant/g");
        gravity_ = toVec<dim>(g.getVector("value", dim));
        g.checkUnknownKeys();
    }

    const Dictionary mats = cs.read("constant/materials");
    for (const std::string& name : mats.keys()) {
        materials_.push_back(Material<dim>::create(mats.subDict(name), name));
        materialNames_.push_back(name);
    }
    if (materials_.empty()) mats.error("", "no materials are defined");
    for (const auto& m : materials_) {
        maxWaveSpeed_ = std::max(maxWaveSpeed_, m->waveSpeed());
        waveOf_.push_back(m->waveSpeed());
        criticalDensityOf_.push_back(m->criticalDensity());
    }
    readRigidBodies();

    const Dictionary schemes = cs.read("system/mpmSchemes");
    const std::string order = schemes.getWordOr("stressUpdate", "USL", {"USF", "USL", "MUSL"});
    usf_ = order == "USF";
    musl_ = order == "MUSL";
    damping_ = schemes.getScalarOr("damping", 0.0, Bounds::halfOpen(0.0, 1.0));
    if (schemes.getWordOr("antiLocking", "none", {"none", "fBar"}) == "fBar")
        fBar_ = std::make_unique<FBar<dim>>();
    // The transfer needs the particle size (GIMP); it is built in start(), so check the
    // schemes' keys now by building one with a provisional width.
    transfer_ = Transfer<dim>::create(schemes, 0.25);
    schemes.checkUnknownKeys();
}

template <int dim> void MpmSimulation<dim>::readRigidBodies() {
    if (!case_.exists("constant/rigidBodies")) return;
    const Dictionary dict = case_.read("constant/rigidBodies");
    std::vector<std::unique_ptr<CouplingLaw<dim>>> laws;
    for (const std::string& name : dict.keys()) {
        const Dictionary bd = dict.subDict(name);
        // The coupling is read here (a body without `coupling` gets the barrier, no friction).
        const Dictionary cd = bd.has("coupling")
                                  ? bd.subDict("coupling")
                                  : Dictionary::fromString("{type: barrier}", bd.fileName());
        laws.push_back(CouplingLaw<dim>::create(cd, grid_.h()));
        bodies_.push_back(std::make_unique<RigidBody<dim>>(bd, name));
        if constexpr (dim == 3) {
            // A level set coarser than the MPM grid goes unstable near twice the larger
            // spacing [004 §5.2]: warn.
            const auto* ls = dynamic_cast<const LevelSetShape*>(&bodies_.back()->shape());
            if (ls && ls->levelSet().grid.spacing > grid_.h() * (1 + 1e-9))
                warning() << "constant/rigidBodies: body '" << name << "': its level-set spacing "
                          << ls->levelSet().grid.spacing << " m is coarser than the MPM cell size "
                          << grid_.h() << " m; the coupling can go unstable [004 §5.2] — "
                          << "rebuild it with a smaller spacing in surfaceToLevelSetDict\n";
        }
        // A moving body starts with its centre in the grid; a fixed one (a terrain, an incline)
        // may lie anywhere.
        for (int d = 0; d < dim && bodies_.back()->motion() != Motion::Fixed; ++d) {
            const double x = bodies_.back()->position()[d];
            if (x < grid_.lo()[d] || x > grid_.hi()[d])
                bd.error("position", "the centre of a moving body lies outside the grid bounds");
        }
    }
    dict.checkUnknownKeys();
    if (!bodies_.empty()) coupling_ = std::make_unique<Coupling<dim>>(std::move(laws));
}

template <int dim> void MpmSimulation<dim>::start(Time& time) {
    time_ = &time;
    const auto dirs = case_.timeDirectories();
    std::string from;
    if (time.startFrom() == "latestTime" && !dirs.empty()) from = dirs.back().second;
    if (time.startFrom() == "firstTime" && !dirs.empty()) from = dirs.front().second;
    if (time.startFrom() == "startTime") {
        for (const auto& [t, n] : dirs)
            if (std::fabs(t - time.startTime()) <= 1e-12 * std::max(1.0, t)) from = n;
        if (from.empty() && time.startTime() != 0.0)
            time.dict().error("startTime", "no time directory " + timeName(time.startTime(), 6) +
                                               " with particles.vtu to start from");
    }

    const bool fresh = from.empty();
    if (fresh) {
        seed();
        time.setStart(time.startFrom() == "startTime" ? time.startTime() : 0.0, 0, 0.0);
    } else {
        restart(from);
    }
    buildMaterialLists();
    if (coupling_) coupling_->setParticles(particles_);
    if (fresh && preload_.requested) {
        transfer_ = Transfer<dim>::create(case_.read("system/mpmSchemes"), gimpHalfWidth());
        gravityPreload();
    }

    transfer_ = Transfer<dim>::create(case_.read("system/mpmSchemes"), gimpHalfWidth());

    maxSpeed_ = 0;
    for (const auto& v : particles_.v)
        maxSpeed_ = std::max(maxSpeed_, v.norm());
    for (const auto& b : bodies_)
        maxSpeed_ = std::max(maxSpeed_, b->velocity().norm());
    lightestMass_ = 1e300;
    for (double m : particles_.mass)
        lightestMass_ = std::min(lightestMass_, m);
    checkDeltaT();

    // Energy budget for the blow-up check: what the initial state and gravity could supply.
    const State<dim> s = state();
    const Index n = static_cast<Index>(particles_.size());
    const double kinetic = deterministicSum(
        n, [&](Index i) { return 0.5 * particles_.mass[i] * particles_.v[i].squaredNorm(); });
    const double strain = deterministicSum(n, [&](Index i) {
        return materials_[particles_.material[i]]->strainEnergy(particles_, i);
    });
    const double mass = deterministicSum(n, [&](Index i) { return particles_.mass[i]; });
    double extent = 0;
    for (int d = 0; d < dim; ++d)
        extent += std::fabs(gravity_[d]) * (grid_.hi()[d] - grid_.lo()[d]);
    double bodyEnergy = 0;
    bool driven = false;
    for (const auto& b : bodies_) {
        bodyEnergy += b->kineticEnergy() + b->mass() * extent;
        // Prescribed and driven motions can do unbounded work.
        driven |= b->motion() == Motion::Prescribed || b->motion() == Motion::Driven;
    }
    energyBudget_ = 10.0 * (kinetic + strain + mass * extent + bodyEnergy);
    if (energyBudget_ <= 0 || driven) energyBudget_ = 1e300;

    if (!options_.noFunctionObjects) functions_ = FunctionObject<dim>::createAll(time.dict());
    (void)s;

    for (auto& f : functions_)
        f->prepare(state(), time); // every check before anything is written
    snapshot();
    if (options_.dryRun) return;
    for (auto& f : functions_)
        f->open(case_, time);
    if (fresh) {
        write();
        for (auto& f : functions_)
            f->executeNow(state(), time);
    }
}

template <int dim> double MpmSimulation<dim>::gimpHalfWidth() const {
    // GIMP's particle half-width l_p = ½ V_p^(1/dim), in cell units, from the mean seeding volume.
    double meanSize = 0;
    for (double v0 : particles_.volume0)
        meanSize += std::pow(v0, 1.0 / dim);
    return 0.5 * meanSize / static_cast<double>(particles_.size()) * grid_.invH();
}

template <int dim> void MpmSimulation<dim>::gravityPreload() {
    // [000 §4.2]: the stresses are initialised by loading the material with gravity, damped,
    // until the kinetic energy is nearly zero; bodies wait. Then velocities are zeroed and the
    // run starts at t = 0 from the preloaded state.
    const double t0 = wallTime();
    const double savedDamping = damping_;
    damping_ = preload_.damping;
    preloading_ = true;
    maxSpeed_ = 0;
    // E_k also vanishes at the turning points of an oscillation: require it to stay below the
    // tolerance for a whole period of the slowest vertical mode, 4 L/c with L the grid's
    // extent along g (an upper bound of the material's height).
    double extent = 0;
    for (int d = 0; d < dim; ++d)
        extent += std::fabs(gravity_[d]) / gravity_.norm() * (grid_.hi()[d] - grid_.lo()[d]);
    const double window = 4.0 * extent / maxWaveSpeed_;
    double peak = 0, kinetic = 0, quiet = 0;
    long k = 0;
    for (; k < preload_.maxSteps; ++k) {
        const double dt = time_->maxCo() * grid_.h() / (maxWaveSpeed_ + maxSpeed_);
        preloadIndex_ = k;
        step(dt); // the material only: bodies wait while preloading_
        kinetic = lastKinetic_;
        peak = std::max(peak, kinetic);
        quiet = kinetic <= preload_.tolerance * peak ? quiet + dt : 0.0;
        if (quiet >= window) break;
    }
    if (k == preload_.maxSteps)
        warning() << "gravity preload: kinetic energy still " << kinetic / std::max(peak, 1e-300)
                  << " of its peak after " << k << " steps (maxSteps); continuing\n";
    for (std::size_t i = 0; i < particles_.size(); ++i) {
        particles_.v[i].setZero();
        particles_.C[i].setZero();
    }
    maxSpeed_ = 0;
    damping_ = savedDamping;
    preloading_ = false;
    times_ = PhaseTimes{};
    steps_ = 0;
    stepWall_ = 0;
    log() << "Gravity preload: " << k << " steps, kinetic energy " << kinetic << " J ("
          << kinetic / std::max(peak, 1e-300) << " of its peak), " << wallTime() - t0 << " s\n";
}

template <int dim> void MpmSimulation<dim>::seed() {
    const Dictionary sets = case_.read("constant/particles");
    Index nextId = 0;
    for (const std::string& setName : sets.keys()) {
        const Dictionary set = sets.subDict(setName);
        const std::string matName = set.getString("material");
        int mat = -1;
        for (std::size_t m = 0; m < materialNames_.size(); ++m)
            if (materialNames_[m] == matName) mat = static_cast<int>(m);
        if (mat < 0) {
            std::string valid;
            for (const auto& n : materialNames_)
                valid += (valid.empty() ? "" : ", ") + n;
            set.error("material",
                      "unknown material '" + matName + "'; constant/materials defines: " + valid);
        }
        const auto region = Region<dim>::create(set.subDict("region"));
        {
            // Check before seeding: a region far larger than the grid would seed without bound.
            const auto box = region->bounds();
            const double tol = 1e-9 * grid_.h();
            for (int d = 0; d < dim; ++d)
                if (box.min()[d] < grid_.lo()[d] - tol || box.max()[d] > grid_.hi()[d] + tol) {
                    std::ostringstream os;
                    os << "the region extends outside the grid bounds ([" << box.min().transpose()
                       << "] – [" << box.max().transpose() << "] is not inside ["
                       << grid_.lo().transpose() << "] – [" << grid_.hi().transpose()
                       << "] of constant/grid)";
                    set.error("region", os.str());
                }
        }

        std::string method = "regular";
        int perDirection = 2;
        int perCell = dim == 2 ? 4 : 8;
        long rngSeed = 0;
        if (set.has("seeding")) {
            const Dictionary sd = set.subDict("seeding");
            method = sd.getWordOr("method", "regular", {"regular", "poissonDisk"});
            if (method == "regular")
                perDirection = sd.getIntOr("perDirection", 2, Bounds::closed(1, 8));
            else {
                perCell = sd.getIntOr("perCell", perCell, Bounds::closed(1, 512));
                rngSeed = sd.getIntOr("seed", 0, Bounds::nonNegative());
            }
            sd.checkUnknownKeys();
        }
        const InitialVelocity<dim> velocity(set);

        // Initial stress: none, or geostatic σ_v = -ρ|g|(z_s - z), σ_h = K0 σ_v.
        bool geostatic = false;
        double K0 = materials_[mat]->defaultK0();
        double surface = 0;
        bool surfaceGiven = false;
        const std::vector<std::string> stressTypes{"none", "geostatic", "gravityPreload"};
        std::string stressType = "none";
        if (set.isDict("initialStress")) {
            const Dictionary is = set.subDict("initialStress");
            stressType = is.getWord("type", stressTypes);
            if (stressType == "geostatic") {
                K0 = is.getScalarOr("K0", K0, Bounds::nonNegative());
                surfaceGiven = is.has("surface");
                if (surfaceGiven) surface = is.getScalar("surface");
            } else if (stressType == "gravityPreload") {
                preload_.damping = is.getScalarOr("damping", 0.5, Bounds::halfOpen(0.0, 1.0));
                preload_.tolerance = is.getScalarOr("tolerance", 1e-4, {0.0, 1.0, false, false});
                preload_.maxSteps = is.getIntOr("maxSteps", 20000, Bounds::closed(1, 1e9));
            }
            is.checkUnknownKeys();
        } else {
            stressType = set.getWordOr("initialStress", "none", stressTypes);
        }
        geostatic = stressType == "geostatic";
        if (stressType == "gravityPreload") {
            if (gravity_.norm() == 0)
                set.error("initialStress", "a gravity preload needs gravity (constant/g)");
            preload_.requested = true;
        }
        set.checkUnknownKeys();

        std::vector<Vec<dim>> xs;
        double volume = 0;
        if (method == "regular") {
            xs = seedRegular<dim>(*region, grid_.origin(), grid_.h(), perDirection);
            volume = std::pow(grid_.h() / perDirection, dim);
        } else {
            xs = seedPoissonDisk<dim>(*region, poissonDiskSpacing(grid_.h(), perCell, dim),
                                      static_cast<std::uint64_t>(rngSeed));
            if (!xs.empty()) volume = region->volume() / static_cast<double>(xs.size());
        }
        if (xs.empty())
            set.error("region", "the region seeds no particles (is it smaller "
                                "than a cell, or outside the grid?)");
        for (const auto& x : xs)
            for (int d = 0; d < dim; ++d)
                if (x[d] < grid_.lo()[d] || x[d] > grid_.hi()[d]) {
                    std::ostringstream os;
                    os << "particles lie outside the grid bounds (a particle at (" << x.transpose()
                       << ") is outside [" << grid_.lo().transpose() << "] – ["
                       << grid_.hi().transpose() << "] of constant/grid)";
                    set.error("region", os.str());
                }

        Vec<dim> up = Vec<dim>::Zero();
        const double gNorm = gravity_.norm();
        if (geostatic) {
            if (gNorm == 0)
                set.error("initialStress", "a geostatic initial stress needs gravity (constant/g)");
            up = -gravity_ / gNorm;
            if (!surfaceGiven) {
                surface = -1e300;
                for (const auto& x : xs)
                    surface = std::max(surface, up.dot(x));
                surface += 0.5 * std::pow(volume, 1.0 / dim);
            }
        }

        const double rho = materials_[mat]->density();
        const std::size_t first = particles_.size();
        particles_.resize(first + xs.size());
        for (std::size_t k = 0; k < xs.size(); ++k) {
            const std::size_t i = first + k;
            particles_.x[i] = xs[k];
            particles_.v[i] = velocity.at(xs[k]);
            particles_.C[i].setZero();
            particles_.L[i].setZero();
            particles_.F[i].setIdentity();
            particles_.mass[i] = rho * volume;
            particles_.volume0[i] = volume;
            particles_.volume[i] = volume;
            particles_.plasticStrain[i] = 0;
            particles_.slip[i] = 0;
            particles_.id[i] = nextId++;
            particles_.material[i] = mat;
            Mat3 sigma0 = Mat3::Zero();
            if (geostatic) {
                const double sv = -rho * gNorm * std::max(0.0, surface - up.dot(xs[k]));
                Vec3 u = Vec3::Zero();
                u.template head<dim>() = up;
                sigma0 = K0 * sv * Mat3::Identity() + (1.0 - K0) * sv * u * u.transpose();
            }
            materials_[mat]->initialise(particles_, static_cast<Index>(i), sigma0);
            if (geostatic) {
                // Start from the elastic stretch of the prestress, F = (bᵉ)^½, so that J < 1:
                // the bed is compressed from its stress-free density like after a gravity
                // preload, and a trans-phase material is not at its critical density.
                Vec3 lam;
                Mat3 Q;
                symmetricEigen3(particles_.be[i], lam, Q);
                const Mat3 V = fromEigen(Q, lam.cwiseSqrt());
                particles_.F[i] = V.template topLeftCorner<dim, dim>();
                particles_.volume[i] = volume * particles_.F[i].determinant();
            }
        }
    }
    if (particles_.size() == 0) sets.error("", "constant/particles defines no particle sets");
    sets.checkUnknownKeys();
}

template <int dim> void MpmSimulation<dim>::restart(const std::string& timeDir) {
    const fs::path file = case_.path(timeDir) / "particles.vtu";
    io::PointCloud cloud;
    try {
        cloud = io::readVtu(file);
    } catch (const std::exception& e) {
        throw InputError(timeDir + "/particles.vtu", 0, "", e.what());
    }
    const std::size_t n = cloud.size();
    auto need = [&](const std::string& name, int comps) -> const io::PointArray& {
        const io::PointArray* a = cloud.find(name);
        if (!a || a->components != comps)
            throw InputError(timeDir + "/particles.vtu", 0, name,
                             "restart array missing or with the wrong number of components (" +
                                 std::to_string(comps) + " expected); was it written by mpmFoam?");
        return *a;
    };
    const auto& id = need("id", 1);
    const auto& mat = need("material", 1);
    const auto& vel = need("velocity", 3);
    const auto& mass = need("mass", 1);
    const auto& vol0 = need("initialVolume", 1);
    const auto& vol = need("volume", 1);
    const auto& eps = need("plasticStrain", 1);
    const auto& slip = need("contactSlip", 1);
    const auto& F = need("deformationGradient", 9);
    const auto& be = need("elasticLeftCauchyGreen", 9);
    const auto& sig = need("stress", 9);
    const auto& C = need("affineVelocity", 9);
    particles_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int a = 0; a < dim; ++a) {
            particles_.x[i][a] = cloud.points[3 * i + a];
            particles_.v[i][a] = vel.f64[3 * i + a];
            for (int b = 0; b < dim; ++b) {
                particles_.F[i](a, b) = F.f64[9 * i + 3 * a + b];
                particles_.C[i](a, b) = C.f64[9 * i + 3 * a + b];
            }
        }
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                particles_.be[i](a, b) = be.f64[9 * i + 3 * a + b];
                particles_.stress[i](a, b) = sig.f64[9 * i + 3 * a + b];
            }
        particles_.L[i].setZero();
        particles_.mass[i] = mass.f64[i];
        particles_.volume0[i] = vol0.f64[i];
        particles_.volume[i] = vol.f64[i];
        particles_.plasticStrain[i] = eps.f64[i];
        particles_.slip[i] = slip.f64[i];
        particles_.id[i] = id.i64[i];
        particles_.material[i] = static_cast<int>(mat.i64[i]);
        if (mat.i64[i] < 0 || mat.i64[i] >= static_cast<Index>(materials_.size()))
            throw InputError(timeDir + "/particles.vtu", 0, "material",
                             "material index " + std::to_string(mat.i64[i]) +
                                 " is not defined in constant/materials");
    }
    time_->readTimeDict(timeDir);
    if (!bodies_.empty()) readRigidBodyState(case_.read(timeDir + "/uniform/rigidBodies"), bodies_);
    log() << "Restart from time " << timeDir << " (" << n << " particles)\n";
}

template <int dim> void MpmSimulation<dim>::buildMaterialLists() {
    materialParticles_.assign(materials_.size(), {});
    for (std::size_t i = 0; i < particles_.size(); ++i)
        materialParticles_[particles_.material[i]].push_back(static_cast<Index>(i));
}

template <int dim> double MpmSimulation<dim>::stableDeltaT() const {
    double dt = grid_.h() / (maxWaveSpeed_ + maxSpeed_);
    if (coupling_) dt = std::min(dt, coupling_->stableDeltaT(lightestMass_, maxWaveSpeed_));
    return time_->maxCo() * dt;
}

template <int dim> void MpmSimulation<dim>::checkDeltaT() const {
    if (time_->adjustTimeStep()) return;
    double critical = grid_.h() / (maxWaveSpeed_ + maxSpeed_);
    if (coupling_)
        critical = std::min(critical, coupling_->stableDeltaT(lightestMass_, maxWaveSpeed_));
    if (time_->fixedDeltaT() <= critical) return;
    std::ostringstream os;
    os << "deltaT = " << time_->fixedDeltaT()
       << " s exceeds the stable limit h/(c + |v|max) = " << critical << " s (h = " << grid_.h()
       << " m, c = " << maxWaveSpeed_ << " m/s, |v|max = " << maxSpeed_ << " m/s)";
    if (!time_->allowUnstableDeltaT())
        time_->dict().error("deltaT", os.str() + "; reduce deltaT, set adjustTimeStep: yes, or "
                                                 "set allowUnstableDeltaT: yes to run anyway");
    warning() << os.str() << "; running anyway (allowUnstableDeltaT: yes)\n";
}

// ---------------------------------------------------------------------------------------------
// The step

template <int dim> void MpmSimulation<dim>::step(double dt) {
    const double t0 = wallTime();
    const bool withBodies = !bodies_.empty() && !preloading_;
    sortParticles();
    if (withBodies) couple(dt);
    particleToGrid();
    if (usf_) {
        gridVelocity();
        transfer_->velocityGradient(particles_, grid_);
        updateStress(dt);
        scatterInternalForce();
    }
    gridUpdate(dt);
    gridToParticle(dt);
    if (musl_) remapVelocity();
    if (!usf_) updateStress(dt);
    if (withBodies) advanceBodies(dt);
    stepWall_ += wallTime() - t0;
    ++steps_;
    if (steps_ % 20 == 0) snapshot();
}

template <int dim> void MpmSimulation<dim>::sortParticles() {
    ScopedTimer timer(times_.sort);
    if (hasOpenFace_) removeOutflow();
    const Index outside = sort_.update(particles_, grid_);
    if (outside >= 0) fail("sort", outside, "left the grid");
    // Every ReorderInterval steps (by absolute step index, so a restart reorders at the same
    // steps) store the particles in block order, for locality in P2G and G2P.
    if ((preloading_ ? preloadIndex_ : time_->index()) % ReorderInterval == 0) {
        particles_.permute(sort_.order(), scratch_);
        sort_.update(particles_, grid_);
        buildMaterialLists();
    }
    transfer_->computeWeights(particles_, grid_);
}

template <int dim> void MpmSimulation<dim>::couple(double dt) {
    ScopedTimer timer(times_.contact);
    for (auto& b : bodies_)
        b->clearForces();
    coupling_->computeForces(particles_, particles_.slip, bodies_, waveOf_, criticalDensityOf_,
                             sort_, grid_, dt);
}

template <int dim> void MpmSimulation<dim>::advanceBodies(double dt) {
    ScopedTimer timer(times_.bodies);
    for (auto& b : bodies_)
        b->advance(dt, time_->value() - dt, gravity_);
    if (coupling_) coupling_->enforceGap(particles_, bodies_, maxMoveSpeed_ * dt, dt);
    for (const auto& b : bodies_) {
        if (!std::isfinite(b->position().sum()) || !std::isfinite(b->velocity().sum()))
            fail("rigid bodies", -1, "rigid body '" + b->name() + "' has a non-finite state");
        // Bodies do not collide with the grid walls: one that has passed through a wall is
        // an error (one leaving through an open face simply flies on).
        const double r = b->shape().boundingRadius();
        for (int f = 0; f < Grid<dim>::NumFaces && b->motion() != Motion::Fixed; ++f) {
            const int a = f / 2;
            const bool beyond = f % 2 == 0 ? b->position()[a] < grid_.lo()[a] - r
                                           : b->position()[a] > grid_.hi()[a] + r;
            if (beyond && grid_.faces()[f].kind != FaceCondition::Kind::Open)
                fail("rigid bodies", -1,
                     "rigid body '" + b->name() + "' has passed through the grid face " +
                         Grid<dim>::faceName(f) + " (bodies do not collide with the walls)");
        }
        // Bodies count for the CFL too, at their rim speed |v| + |ω| r.
        maxSpeed_ = std::max(maxSpeed_, b->velocity().norm() + b->angularVelocity().norm() *
                                                                   b->shape().boundingRadius());
    }
}

template <int dim> void MpmSimulation<dim>::removeOutflow() {
    // Particles more than one cell beyond an open face have left the domain: remove them,
    // keeping the order of the others (deterministic).
    const Index n = static_cast<Index>(particles_.size());
    // Beyond these bounds on an open side a particle has left (±inf on walled sides).
    Vec<dim> lo, hi;
    for (int d = 0; d < dim; ++d) {
        lo[d] = grid_.faces()[2 * d].kind == FaceCondition::Kind::Open ? grid_.lo()[d] - grid_.h()
                                                                       : -1e300;
        hi[d] = grid_.faces()[2 * d + 1].kind == FaceCondition::Kind::Open
                    ? grid_.hi()[d] + grid_.h()
                    : 1e300;
    }
    auto outside = [&](Index i) {
        return ((particles_.x[i] - lo).minCoeff() < 0) || ((hi - particles_.x[i]).minCoeff() < 0);
    };
    Index anyOut = 0;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(+ : anyOut)
    for (Index i = 0; i < n; ++i)
        anyOut += outside(i);
    if (anyOut == 0) return;
    std::vector<Index> keep;
    keep.reserve(n);
    for (Index i = 0; i < n; ++i)
        if (!outside(i)) keep.push_back(i);
    if (static_cast<Index>(keep.size()) == n) return;
    if (keep.empty()) throw RunError("every particle has left the domain through open faces");
    particles_.permute(keep);
    buildMaterialLists();
    removed_ += n - static_cast<Index>(keep.size());
}

template <int dim> void MpmSimulation<dim>::particleToGrid() {
    ScopedTimer timer(times_.p2g);
    // Only nodes of last step's active blocks can be non-zero.
    const IVec<dim> n = grid_.nodes();
    auto forNodes = [&](Index b, auto&& fn) {
        const IVec<dim> c = grid_.blockCoord(b);
        IVec<dim> lo, hi;
        for (int d = 0; d < dim; ++d) {
            lo[d] = c[d] * Grid<dim>::BlockSize;
            hi[d] = std::min(lo[d] + Grid<dim>::BlockSize, n[d]);
        }
        if constexpr (dim == 2) {
            for (int j = lo[1]; j < hi[1]; ++j)
                for (int i = lo[0]; i < hi[0]; ++i)
                    fn(grid_.nodeIndex(IVec<dim>(i, j)));
        } else {
            for (int k = lo[2]; k < hi[2]; ++k)
                for (int j = lo[1]; j < hi[1]; ++j)
                    for (int i = lo[0]; i < hi[0]; ++i)
                        fn(grid_.nodeIndex(IVec<dim>(i, j, k)));
        }
    };
    const Index nOld = static_cast<Index>(activeBlocks_.size());
#pragma omp parallel for if (worthThreads(64 * nOld)) schedule(static)
    for (Index k = 0; k < nOld; ++k)
        forNodes(activeBlocks_[k], [&](Index i) {
            grid_.mass[i] = 0;
            grid_.momentum[i].setZero();
            grid_.force[i].setZero();
            grid_.vOld[i].setZero();
            grid_.v[i].setZero();
        });
    activeBlocks_ = sort_.activeNodeBlocks();
    transfer_->scatter(particles_, grid_, sort_, !usf_);
    if (coupling_) // coupling forces of dense points [000 Eq. 19–20]
        transfer_->scatterPointForces(coupling_->gridPoints(), coupling_->gridForces(), grid_);
}

template <int dim>
void MpmSimulation<dim>::applyBoundaryConditions(bool recordReactions, double dt) {
    std::vector<Vec<dim>>& vel = recordReactions ? grid_.v : grid_.vOld;
    if (recordReactions) {
        touched_.resize(grid_.numNodes(), 0);
        for (int f = 0; f < Grid<dim>::NumFaces; ++f)
            for (Index i : grid_.faceNodes(f))
                touched_[i] = 0;
    }
    for (int f = 0; f < Grid<dim>::NumFaces; ++f) {
        const FaceCondition& fc = grid_.faces()[f];
        Vec<dim> reaction = Vec<dim>::Zero();
        if (fc.kind != FaceCondition::Kind::Open) {
            const int axis = f / 2;
            const double sign = f % 2 == 0 ? -1.0 : 1.0; // outward normal along axis
            for (Index i : grid_.faceNodes(f)) {
                const double m = grid_.mass[i];
                if (m == 0) continue;
                Vec<dim>& v = vel[i];
                // The reaction balances the physical forces on the node: the first face acting
                // on a node measures it from the undamped update v⁰ + Δt (f/m + g), not from
                // the (locally damped) v; a later face (edges, corners) from what is left.
                Vec<dim> before = v;
                if (recordReactions && !touched_[i]) {
                    before = grid_.vOld[i] + dt * (grid_.force[i] / m + gravity_);
                    touched_[i] = 1;
                }
                const double vn = sign * v[axis]; // > 0: into the wall
                switch (fc.kind) {
                case FaceCondition::Kind::NoSlip:
                    v.setZero();
                    break;
                case FaceCondition::Kind::Slip:
                    if (vn > 0) v[axis] = 0;
                    break;
                case FaceCondition::Kind::Friction:
                    if (vn > 0) {
                        v[axis] = 0;
                        const double vt = v.norm();
                        const double drop = fc.friction * vn;
                        v *= vt > drop ? (1.0 - drop / vt) : 0.0;
                    }
                    break;
                case FaceCondition::Kind::Open:
                    break;
                }
                if (recordReactions) reaction += m * (before - v) / dt;
            }
        }
        if (recordReactions) reactions_[f] = reaction;
    }
}

template <int dim> void MpmSimulation<dim>::gridVelocity() {
    ScopedTimer timer(times_.grid);
    const Index n = grid_.numNodes();
    (void)n;
    const auto& blocks = activeBlocks_;
    const IVec<dim> nodes = grid_.nodes();
#pragma omp parallel for if (worthThreads(64 * static_cast <Index>(blocks.size()))) schedule(static)
    for (Index k = 0; k < static_cast<Index>(blocks.size()); ++k) {
        const IVec<dim> c = grid_.blockCoord(blocks[k]);
        IVec<dim> lo, hi;
        for (int d = 0; d < dim; ++d) {
            lo[d] = c[d] * Grid<dim>::BlockSize;
            hi[d] = std::min(lo[d] + Grid<dim>::BlockSize, nodes[d]);
        }
        IVec<dim> i = lo;
        while (true) {
            const Index node = grid_.nodeIndex(i);
            const double m = grid_.mass[node];
            grid_.vOld[node] = m > 0 ? Vec<dim>(grid_.momentum[node] / m) : Vec<dim>::Zero();
            int d = 0;
            while (d < dim && ++i[d] >= hi[d])
                i[d] = lo[d], ++d;
            if (d == dim) break;
        }
    }
    applyBoundaryConditions(false, 0.0);
}

template <int dim> void MpmSimulation<dim>::remapVelocity() {
    ScopedTimer timer(times_.p2g);
    // MUSL: project the updated particle momenta back to the grid with the step's weights
    // (those of x^n) and take L from that velocity.
    const IVec<dim> nodes = grid_.nodes();
    const auto& blocks = activeBlocks_;
#pragma omp parallel for if (worthThreads(64 * static_cast <Index>(blocks.size()))) schedule(static)
    for (Index k = 0; k < static_cast<Index>(blocks.size()); ++k) {
        const IVec<dim> c = grid_.blockCoord(blocks[k]);
        IVec<dim> lo, hi;
        for (int d = 0; d < dim; ++d) {
            lo[d] = c[d] * Grid<dim>::BlockSize;
            hi[d] = std::min(lo[d] + Grid<dim>::BlockSize, nodes[d]);
        }
        IVec<dim> i = lo;
        while (true) {
            const Index node = grid_.nodeIndex(i);
            grid_.mass[node] = 0;
            grid_.momentum[node].setZero();
            int d = 0;
            while (d < dim && ++i[d] >= hi[d])
                i[d] = lo[d], ++d;
            if (d == dim) break;
        }
    }
    transfer_->scatter(particles_, grid_, sort_, false);
    gridVelocity();
    transfer_->velocityGradient(particles_, grid_);
}

template <int dim> void MpmSimulation<dim>::scatterInternalForce() {
    ScopedTimer timer(times_.p2g);
    transfer_->scatterForce(particles_, grid_, sort_);
}

template <int dim> void MpmSimulation<dim>::gridUpdate(double dt) {
    ScopedTimer timer(times_.grid);
    const auto& blocks = activeBlocks_;
    const IVec<dim> nodes = grid_.nodes();
    const Vec<dim> g = gravity_;
    const double alpha = damping_;
    const bool damped = alpha > 0; // loop-invariant: hoisted out of the node loop
#pragma omp parallel for if (worthThreads(64 * static_cast <Index>(blocks.size()))) schedule(static)
    for (Index k = 0; k < static_cast<Index>(blocks.size()); ++k) {
        const IVec<dim> c = grid_.blockCoord(blocks[k]);
        IVec<dim> lo, hi;
        for (int d = 0; d < dim; ++d) {
            lo[d] = c[d] * Grid<dim>::BlockSize;
            hi[d] = std::min(lo[d] + Grid<dim>::BlockSize, nodes[d]);
        }
        IVec<dim> i = lo;
        while (true) {
            const Index node = grid_.nodeIndex(i);
            const double m = grid_.mass[node];
            if (m > 0) {
                // [000 Eq. 14]: (m v)ⁿ⁺¹ = m v + Δt f, with gravity f_ext = m g.
                const Vec<dim> v0 = grid_.momentum[node] / m;
                Vec<dim> f = grid_.force[node] + m * g;
                // Local non-viscous damping f ← f - α |f| sign(v), per component.
                if (damped)
                    for (int a = 0; a < dim; ++a)
                        f[a] -= alpha * std::fabs(f[a]) * ((v0[a] > 0) - (v0[a] < 0));
                grid_.vOld[node] = v0;
                grid_.v[node] = v0 + (dt / m) * f;
            }
            int d = 0;
            while (d < dim && ++i[d] >= hi[d])
                i[d] = lo[d], ++d;
            if (d == dim) break;
        }
    }
    applyBoundaryConditions(true, dt);
}

template <int dim> void MpmSimulation<dim>::gridToParticle(double dt) {
    ScopedTimer timer(times_.g2p);
    const GatherStats st = transfer_->gather(particles_, grid_, dt, !usf_ && !musl_);
    if (coupling_) coupling_->applyLocalForces(particles_, dt);
    lastKinetic_ = st.kineticEnergy;
    if (st.firstNonFinite >= 0) fail("G2P", st.firstNonFinite, "has a velocity that is not finite");
    maxSpeed_ = st.maxSpeed;
    maxMoveSpeed_ = st.maxMoveSpeed;
    if (maxSpeed_ * dt > grid_.h()) {
        Index worst = 0;
        for (Index i = 0; i < static_cast<Index>(particles_.size()); ++i)
            if (particles_.v[i].norm() > particles_.v[worst].norm()) worst = i;
        std::ostringstream os;
        os << "moved more than one cell in one step (|v| = " << maxSpeed_ << " m/s, dt = " << dt
           << " s, h = " << grid_.h() << " m): the run is unstable or deltaT is too large";
        fail("G2P", worst, os.str());
    }
    if (st.kineticEnergy > energyBudget_) {
        Index worst = 0;
        for (Index i = 0; i < static_cast<Index>(particles_.size()); ++i)
            if (particles_.v[i].norm() > particles_.v[worst].norm()) worst = i;
        std::ostringstream os;
        os << "is the fastest of a kinetic-energy blow-up: E_k = " << st.kineticEnergy
           << " J exceeds 10× what the initial state and gravity can supply (" << energyBudget_ / 10
           << " J)";
        fail("G2P", worst, os.str());
    }
}

template <int dim> void MpmSimulation<dim>::updateStress(double dt) {
    ScopedTimer timer(times_.constitutive);
    // Kinematics: [L ← L̄ (F̄ anti-locking)], F ← (1 + Δt L) F, V = det(F) V⁰ [002 Eq. 76].
    if (fBar_) fBar_->apply(particles_, grid_, *transfer_, sort_, dt);
    const Index n = static_cast<Index>(particles_.size());
    Index inverted = n;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : inverted)
    for (Index i = 0; i < n; ++i) {
        particles_.F[i] = (Mat<dim>::Identity() + dt * particles_.L[i]) * particles_.F[i];
        const double J = particles_.F[i].determinant();
        if (!(J > 0)) inverted = std::min(inverted, i);
        particles_.volume[i] = J * particles_.volume0[i];
    }
    if (inverted < n) fail("constitutive", inverted, "has det F <= 0 (inverted element)");
    for (std::size_t m = 0; m < materials_.size(); ++m) {
        const Index bad = materials_[m]->updateStress(particles_, materialParticles_[m], dt);
        if (bad >= 0) fail("constitutive", bad, "has a stress that is not finite");
    }
}

// ---------------------------------------------------------------------------------------------
// Output and failure

template <int dim> void MpmSimulation<dim>::executeFunctions() {
    ScopedTimer timer(times_.functions);
    for (auto& f : functions_)
        f->execute(state(), *time_);
}

template <int dim> void MpmSimulation<dim>::write() {
    if (options_.dryRun) return;
    ScopedTimer timer(times_.io);
    const std::string name = time_->name();
    const std::size_t n = particles_.size();
    io::PointCloud cloud;
    cloud.points.assign(3 * n, 0.0);
    auto f64 = [&](const std::string& nm, int comps) -> std::vector<double>& {
        cloud.arrays.push_back({nm, comps, std::vector<double>(comps * n), {}, false});
        return cloud.arrays.back().f64;
    };
    auto i64 = [&](const std::string& nm) -> std::vector<std::int64_t>& {
        cloud.arrays.push_back({nm, 1, {}, std::vector<std::int64_t>(n), true});
        return cloud.arrays.back().i64;
    };
    cloud.arrays.reserve(16);
    auto& id = i64("id");
    auto& mat = i64("material");
    auto& vel = f64("velocity", 3);
    auto& stress = f64("stress", 9);
    auto& pressure = f64("pressure", 1);
    auto& density = f64("density", 1);
    auto& volume = f64("volume", 1);
    auto& mass = f64("mass", 1);
    auto& plastic = f64("plasticStrain", 1);
    auto& slip = f64("contactSlip", 1);
    auto& vol0 = f64("initialVolume", 1);
    auto& F = f64("deformationGradient", 9);
    auto& be = f64("elasticLeftCauchyGreen", 9);
    auto& C = f64("affineVelocity", 9);
    const auto& p = particles_;
    for (std::size_t i = 0; i < n; ++i) {
        for (int a = 0; a < dim; ++a) {
            cloud.points[3 * i + a] = p.x[i][a];
            vel[3 * i + a] = p.v[i][a];
            for (int b = 0; b < dim; ++b) {
                F[9 * i + 3 * a + b] = p.F[i](a, b);
                C[9 * i + 3 * a + b] = p.C[i](a, b);
            }
        }
        if (dim == 2) F[9 * i + 8] = 1.0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                stress[9 * i + 3 * a + b] = p.stress[i](a, b);
                be[9 * i + 3 * a + b] = p.be[i](a, b);
            }
        id[i] = p.id[i];
        mat[i] = p.material[i];
        pressure[i] = -p.stress[i].trace() / 3.0;
        density[i] = p.mass[i] / p.volume[i];
        volume[i] = p.volume[i];
        mass[i] = p.mass[i];
        plastic[i] = p.plasticStrain[i];
        slip[i] = p.slip[i];
        vol0[i] = p.volume0[i];
    }

    // Write into a temporary directory, then rename: never a half-written time directory.
    const fs::path dir = case_.path(name);
    const fs::path tmp = case_.path("." + name + ".writing");
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    io::writeVtu(tmp / "particles.vtu", cloud);
    time_->writeTimeDict(tmp);
    if (!bodies_.empty()) {
        writeRigidBodies(tmp / "rigidBodies.vtp", bodies_);
        writeRigidBodyState(tmp / "uniform" / "rigidBodies", bodies_);
    }
    fs::remove_all(dir);
    fs::rename(tmp, dir);

    if (!pvd_) pvd_ = std::make_unique<io::PvdIndex>(case_.path("particles.pvd"), time_->value());
    pvd_->add(time_->value(), name + "/particles.vtu");
    if (!bodies_.empty()) {
        if (!bodiesPvd_)
            bodiesPvd_ =
                std::make_unique<io::PvdIndex>(case_.path("rigidBodies.pvd"), time_->value());
        bodiesPvd_->add(time_->value(), name + "/rigidBodies.vtp");
    }
    for (const std::string& old : time_->wrote()) {
        fs::remove_all(case_.path(old));
        pvd_->remove(old + "/particles.vtu");
        if (bodiesPvd_) bodiesPvd_->remove(old + "/rigidBodies.vtp");
    }
}

template <int dim> void MpmSimulation<dim>::snapshot() {
    good_ = particles_;
    goodBodies_.clear();
    for (const auto& b : bodies_) {
        std::ostringstream os;
        b->writeState(os);
        goodBodies_.push_back(os.str());
    }
    goodTime_ = time_->value();
    goodIndex_ = time_->index();
    goodDeltaT_ = time_->deltaT();
    hasGood_ = true;
}

template <int dim>
void MpmSimulation<dim>::fail(const std::string& phase, Index particle, const std::string& what) {
    std::ostringstream os;
    os << "step " << time_->index() << " (t = " << time_->value() << " s), phase " << phase << ": ";
    if (particle >= 0)
        os << "particle " << particles_.id[particle] << " at ("
           << particles_.x[particle].transpose() << ") ";
    os << what << '.';
    if (hasGood_ && !options_.dryRun) {
        particles_ = good_;
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            bodies_[b]->readState(Dictionary::fromString(goodBodies_[b], "snapshot"));
        time_->setStart(goodTime_, goodIndex_, goodDeltaT_);
        write();
        os << "\nThe last good state (step " << goodIndex_ << ", t = " << goodTime_
           << " s) is written to " << time_->name() << "/.";
    }
    throw RunError(os.str());
}

template <int dim> void MpmSimulation<dim>::report(std::ostream& os) const {
    const double total = stepWall_ + times_.io + times_.functions;
    (void)0;
    auto line = [&](const char* name, double t) {
        os << "    " << std::left << std::setw(14) << name << std::right << std::setw(10)
           << std::fixed << std::setprecision(3) << t << " s " << std::setw(6)
           << std::setprecision(1) << (total > 0 ? 100.0 * t / total : 0.0) << " %\n";
    };
    os << "\nPhase timing (" << steps_ << " steps, " << particles_.size() << " particles, "
       << omp_get_max_threads() << " threads):\n";
    line("sort", times_.sort);
    if (coupling_) line("contact", times_.contact);
    line("P2G", times_.p2g);
    line("grid", times_.grid);
    line("G2P", times_.g2p);
    line("constitutive", times_.constitutive);
    if (!bodies_.empty()) line("rigid bodies", times_.bodies);
    line("functions", times_.functions);
    line("IO", times_.io);
    line("total", total);
    const double pups = stepWall_ > 0 ? particles_.size() * steps_ / stepWall_ : 0.0;
    if (removed_ > 0) os << removed_ << " particles left through open faces and were removed\n";
    os << std::defaultfloat << std::setprecision(4) << "Particle-updates per second: " << pups
       << " (" << pups / 1e6 << " M)\n";
}

template class MpmSimulation<2>;
template class MpmSimulation<3>;

std::unique_ptr<Simulation> Simulation::create(const Case& cs, const RunOptions& options) {
    const Dictionary grid = cs.read("constant/grid");
    const int dim = grid.getInt("dimension", Bounds::closed(2, 3));
    if (dim == 2) return std::make_unique<MpmSimulation<2>>(cs, options, grid);
    return std::make_unique<MpmSimulation<3>>(cs, options, grid);
}

} // namespace mpm
