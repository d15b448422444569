// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/BodySet.hpp"

#include "core/Log.hpp"
#include "io/ParticleFile.hpp"
#include "rigid/LevelSetShape.hpp"
#include "rigid/RigidBodyOutput.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm {

template <int dim>
BodySet<dim>::BodySet(const Case& cs, const Grid<dim>& grid, const PeriodicLattice<dim>* lattice)
    : lattice_(lattice && lattice->any() ? lattice : nullptr) {
    if (!cs.exists("constant/rigidBodies")) return;
    const Dictionary dict = cs.read("constant/rigidBodies");
    for (const std::string& name : dict.keys()) {
        const Dictionary bd = dict.subDict(name);
        // The coupling is read here (a body without `coupling` gets the barrier, no friction).
        const Dictionary cd = bd.has("coupling")
                                  ? bd.subDict("coupling")
                                  : Dictionary::fromString("{type: barrier}", bd.fileName());
        laws_.push_back(CouplingLaw<dim>::create(cd, grid.h()));
        bodies_.push_back(std::make_unique<RigidBody<dim>>(bd, name));
        const RigidBody<dim>& body = *bodies_.back();
        // A level set coarser than the MPM grid goes unstable near twice the larger spacing
        // [004 §5.2]: warn.
        const double spacing = body.shape().samplingSpacing();
        if (spacing > grid.h() * (1 + 1e-9))
            warning() << "constant/rigidBodies: body '" << name << "': its level-set spacing "
                      << spacing << " m is coarser than the MPM cell size " << grid.h()
                      << " m; the coupling can go unstable [004 §5.2] — "
                      << "rebuild it with a smaller spacing in surfaceToLevelSetDict\n";
        // A moving body starts with its centre in the grid; a fixed one (a terrain, an incline)
        // may lie anywhere.
        for (int d = 0; d < dim && body.motion() != Motion::Fixed; ++d) {
            const double x = body.position()[d];
            if (x < grid.lo()[d] || x > grid.hi()[d])
                bd.error("position", "the centre of a moving body lies outside the grid bounds");
        }
        // Periodic faces: the coupling meets a point through the body's image nearest it, which
        // must be the only one that can touch it.
        for (int d = 0; d < dim && lattice_ && body.motion() != Motion::Fixed; ++d) {
            const double period = lattice_->period()[d];
            if (!lattice_->periodic(d) || body.shape().boundingRadius() + grid.h() < 0.5 * period)
                continue;
            std::ostringstream os;
            os << "a moving body across periodic faces must be smaller than half the period: its "
                  "bounding radius "
               << body.shape().boundingRadius() << " m plus the cell size " << grid.h()
               << " m must be less than L/2 = " << 0.5 * period << " m along "
               << "xyz"[d] << " (enlarge the periodic box)";
            bd.error("shape", os.str());
        }
    }
    dict.checkUnknownKeys();
    if (cs.exists("constant/bodyContact")) {
        auto law = BodyContactLaw<dim>::create(cs.read("constant/bodyContact"));
        if (bodies_.size() >= 2) contact_ = std::move(law);
        if (contact_ && lattice_) contact_->setPeriodic(*lattice_);
    }
}

template <int dim> void BodySet<dim>::clearForces() {
    for (auto& b : bodies_)
        b->clearForces();
}

template <int dim> void BodySet<dim>::wrap() {
    if (!lattice_) return;
    for (auto& b : bodies_)
        if (b->motion() != Motion::Fixed) b->movePositionTo(lattice_->wrapPosition(b->position()));
}

template <int dim> void BodySet<dim>::advance(double dt, double t, const Vec<dim>& g) {
    if (!contact_) {
        for (auto& b : bodies_)
            b->advance(dt, t, g);
        return;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(dt / contact_->stableDeltaT(bodies_))));
    const double h = dt / n;
    std::vector<Vec<dim>> force;
    std::vector<Vec3> torque;
    for (const auto& b : bodies_) {
        force.push_back(b->force());
        torque.push_back(b->torque());
    }
    for (int s = 0; s < n; ++s) {
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            bodies_[b]->clearForces();
            bodies_[b]->addForceAndTorque(force[b], torque[b]);
        }
        contact_->addForces(bodies_, history_, h);
        for (auto& b : bodies_)
            b->advance(h, t + s * h, g);
    }
}

template <int dim>
std::string BodySet<dim>::check(const Grid<dim>& grid,
                                const std::function<bool(int, const Vec<dim>&)>& open) const {
    for (const auto& b : bodies_) {
        if (!std::isfinite(b->position().sum()) || !std::isfinite(b->velocity().sum()))
            return "rigid body '" + b->name() + "' has a non-finite state";
        const double r = b->shape().boundingRadius();
        for (int f = 0; f < Grid<dim>::NumFaces && b->motion() != Motion::Fixed; ++f) {
            const int a = f / 2;
            if (lattice_ && lattice_->periodic(a)) continue; // wrapped at the next step
            const bool beyond = f % 2 == 0 ? b->position()[a] < grid.lo()[a] - r
                                           : b->position()[a] > grid.hi()[a] + r;
            if (beyond && !open(f, b->position()))
                return "rigid body '" + b->name() + "' has passed through the grid face " +
                       Grid<dim>::faceName(f) + " (bodies do not collide with the walls)";
        }
    }
    return {};
}

template <int dim> double BodySet<dim>::maxRimSpeed() const {
    double s = 0;
    for (const auto& b : bodies_)
        s = std::max(s, b->velocity().norm() +
                            b->angularVelocity().norm() * b->shape().boundingRadius());
    return s;
}

template <int dim> bool BodySet<dim>::driven() const {
    for (const auto& b : bodies_)
        if (b->motion() == Motion::Prescribed || b->motion() == Motion::Driven) return true;
    return false;
}

template <int dim> double BodySet<dim>::energyBudget(double gravityTimesExtent) const {
    double e = 0;
    for (const auto& b : bodies_)
        e += b->kineticEnergy() + b->mass() * gravityTimesExtent;
    return e;
}

template <int dim> std::vector<std::string> BodySet<dim>::saveState() const {
    std::vector<std::string> state;
    for (const auto& b : bodies_) {
        std::ostringstream os;
        b->writeState(os);
        state.push_back(os.str());
    }
    if (contact_) state.push_back(historyText());
    return state;
}

template <int dim> void BodySet<dim>::restoreState(const std::vector<std::string>& state) {
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        bodies_[b]->readState(Dictionary::fromString(state[b], "snapshot"));
    if (contact_) readHistory(Dictionary::fromString(state.back(), "snapshot"));
}

template <int dim> std::string BodySet<dim>::historyText() const {
    std::ostringstream os;
    os.precision(17);
    os << "contacts: [";
    const char* sep = "";
    for (const auto& [key, xi] : history_) {
        os << sep << "[" << key[0] << ", " << key[1] << ", " << key[2] << ", " << key[3];
        for (int d = 0; d < dim; ++d)
            os << ", " << xi[d];
        os << "]";
        sep = ", ";
    }
    os << "]\n";
    return os.str();
}

template <int dim> void BodySet<dim>::readHistory(const Dictionary& dict) {
    history_.clear();
    const int n = static_cast<int>(bodies_.size());
    // Rows [body, body, k, l, ξ…] (4 + dim numbers); files written before the key had a fourth
    // index hold [body, body, k, ξ…] (3 + dim), read with l = 0.
    for (const auto& row : dict.vectorList("contacts")) {
        const int nKey = static_cast<int>(row.size()) - dim;
        if (nKey != 3 && nKey != 4)
            dict.error("contacts", "expected rows [body, body, k, l, " +
                                       std::string(dim == 2 ? "ξx, ξy" : "ξx, ξy, ξz") +
                                       "] (or [body, body, k, ξ…] of older files)");
        std::array<int, 4> key{};
        for (int k = 0; k < nKey; ++k) {
            key[k] = static_cast<int>(row[k]);
            if (key[k] != row[k] || key[k] < 0 || (k < 2 && key[k] >= n))
                dict.error("contacts", "a contact names a body or probe that does not exist");
        }
        Vec<dim> xi;
        for (int d = 0; d < dim; ++d)
            xi[d] = row[nKey + d];
        history_[key] = xi;
    }
    dict.checkUnknownKeys();
}

template <int dim> void BodySet<dim>::write(const std::filesystem::path& dir) const {
    writeRigidBodies(dir / "rigidBodies.vtp", bodies_);
    writeRigidBodyState(dir / "uniform" / "rigidBodies", bodies_);
    if (contact_) io::writeTextAtomic(dir / "uniform" / "bodyContacts", historyText());
}

template <int dim> void BodySet<dim>::read(const Case& cs, const std::string& timeDir) {
    readRigidBodyState(cs.read(timeDir + "/uniform/rigidBodies"), bodies_);
    if (contact_) readHistory(cs.read(timeDir + "/uniform/bodyContacts"));
}

template <int dim> double BodySet<dim>::distance(const Vec<dim>& x) const {
    double nearest = 1e300;
    Vec<dim> normal;
    for (const auto& b : bodies_)
        nearest = std::min(
            nearest, b->distance(lattice_ ? lattice_->imageNear(x, b->position()) : x, normal));
    return nearest;
}

template <int dim> void BodySet<dim>::sumForces(const Comm& comm) {
    std::vector<double> ft;
    for (const auto& b : bodies_) {
        for (int d = 0; d < dim; ++d)
            ft.push_back(b->force()[d]);
        for (int d = 0; d < 3; ++d)
            ft.push_back(b->torque()[d]);
    }
    comm.sum(ft.data(), static_cast<int>(ft.size()));
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        const double* x = ft.data() + k * (dim + 3);
        bodies_[k]->clearForces();
        bodies_[k]->addForceAndTorque(Vec<dim>(Eigen::Map<const Vec<dim>>(x)),
                                      Vec3(x[dim], x[dim + 1], x[dim + 2]));
    }
}

template <int dim> std::vector<double> BodySet<dim>::twists() const {
    std::vector<double> t(bodies_.size() * (dim + 3));
    for (std::size_t k = 0; k < bodies_.size(); ++k)
        bodies_[k]->twist(t.data() + k * (dim + 3));
    return t;
}

template <int dim>
void BodySet<dim>::sumTwistChanges(const Comm& comm, const std::vector<double>& before) {
    std::vector<double> change = twists();
    for (std::size_t k = 0; k < change.size(); ++k)
        change[k] -= before[k];
    comm.sum(change.data(), static_cast<int>(change.size()));
    for (std::size_t k = 0; k < change.size(); ++k)
        change[k] += before[k];
    for (std::size_t k = 0; k < bodies_.size(); ++k)
        bodies_[k]->setTwist(change.data() + k * (dim + 3));
}

template class BodySet<2>;
template class BodySet<3>;

} // namespace mpm
