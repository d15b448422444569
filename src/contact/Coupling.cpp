// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/Coupling.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "transfers/PhaseDensity.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm {

template <int dim>
Coupling<dim>::Coupling(std::vector<std::unique_ptr<CouplingLaw<dim>>> laws,
                        const PeriodicLattice<dim>* lattice)
    : laws_(std::move(laws)), lattice_(lattice && lattice->any() ? lattice : nullptr) {}

template <int dim>
const PeriodicLattice<dim>* Coupling<dim>::imagesFor(const RigidBody<dim>& body,
                                                     double searchReach) const {
    if (!lattice_) return nullptr;
    const double reach = body.shape().boundingRadius() + searchReach;
    for (int d = 0; d < dim; ++d) {
        if (!lattice_->periodic(d) || 2 * reach < lattice_->period()[d]) continue;
        if (body.motion() == Motion::Fixed) return nullptr; // coupled where it lies
        std::ostringstream os;
        os << "rigid body '" << body.name() << "': its bounding radius "
           << body.shape().boundingRadius() << " m plus the coupling radius " << searchReach
           << " m is not less than half the period " << lattice_->period()[d]
           << " m: a point could touch two of its periodic images";
        throw RunError(os.str());
    }
    return lattice_;
}

template <int dim>
template <class Fn>
void Coupling<dim>::forParticlesNear(const RigidBody<dim>& body, const Vec<dim>& shift,
                                     const Particles<dim>& p, double reach,
                                     const BlockSort<dim>& sort, const Grid<dim>& grid,
                                     Fn&& fn) const {
    // Called right after the sort: every point lies in its block. Blocks of the ball's bounding
    // box, then two culls by the distance φ (1-Lipschitz, one cell of margin for a sampled
    // field): a block whose centre is farther than its half-diagonal + h + reach, then, inside a
    // kept block, the 2^dim half-blocks (2 cells a side) likewise. The body's image at
    // x_b + shift: φ(y) of that image is the body's φ(y − shift).
    const Vec<dim> centre = body.position() + shift;
    const double radius = body.shape().boundingRadius() + reach;
    const double size = Grid<dim>::BlockSize * grid.h();
    const double halfDiagonal = 0.5 * size * std::sqrt(double(dim));
    const double margin = grid.h() + reach;
    IVec<dim> lo, hi;
    for (int d = 0; d < dim; ++d) {
        lo[d] = std::max(
            0, static_cast<int>(std::floor((centre[d] - radius - grid.origin()[d]) / size)));
        hi[d] =
            std::min(grid.blocks()[d] - 1,
                     static_cast<int>(std::floor((centre[d] + radius - grid.origin()[d]) / size)));
        if (hi[d] < lo[d]) return;
    }
    const auto& order = sort.order();
    constexpr int NumHalves = 1 << dim;
    IVec<dim> c = lo;
    while (true) {
        Index b = 0;
        for (int d = dim - 1; d >= 0; --d)
            b = b * grid.blocks()[d] + c[d];
        if (const auto r = sort.particlesOf(b); r.begin < r.end) {
            Vec<dim> corner;
            for (int d = 0; d < dim; ++d)
                corner[d] = grid.origin()[d] + c[d] * size;
            Vec<dim> normal;
            if (body.distance(corner + Vec<dim>::Constant(0.5 * size) - shift, normal) <=
                halfDiagonal + margin) {
                int keep = 0; // bit q: half-block q (bit d of q: upper half along d) is near
                for (int q = 0; q < NumHalves; ++q) {
                    Vec<dim> half = corner;
                    for (int d = 0; d < dim; ++d)
                        half[d] += ((q >> d) & 1 ? 0.75 : 0.25) * size;
                    if (body.distance(half - shift, normal) <= 0.5 * halfDiagonal + margin)
                        keep |= 1 << q;
                }
                for (Index j = r.begin; j < r.end; ++j) {
                    const Index i = order[j];
                    int q = 0;
                    for (int d = 0; d < dim; ++d)
                        q |= (p.x[i][d] - corner[d] >= 0.5 * size) << d;
                    if (keep >> q & 1) fn(i);
                }
            }
        }
        int d = 0;
        while (d < dim && ++c[d] > hi[d])
            c[d] = lo[d], ++d;
        if (d == dim) break;
    }
}

template <int dim>
void Coupling<dim>::computeForces(Particles<dim>& p,
                                  const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                                  const std::vector<double>& wave, const std::vector<int>* gasified,
                                  const BlockSort<dim>& sort, const Grid<dim>& grid, double dt) {
    gridPoints_.clear();
    gridForces_.clear();
    localPoints_.clear();
    localForces_.clear();
    numContacts_ = 0;
    std::vector<int>* nearBody = nearBody_ ? &p.flag(*nearBody_) : nullptr;
    if (nearBody != nullptr) std::fill(nearBody->begin(), nearBody->end(), 0);
    const double band = nearBody != nullptr ? nearBodyCells * grid.h() : 0.0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (!laws_[b]) continue;
        RigidBody<dim>& body = *bodies[b];
        const CouplingLaw<dim>& law = *laws_[b];
        std::vector<double>& slip = p.scalar(slip_[b]);
        const double reach = searchReach(law);
        const PeriodicLattice<dim>* images = imagesFor(body, reach);
        // Narrow phase in parallel over the broad phase's points, kept in their order.
        nearPoints(body, images, p, reach + band, sort, grid);
        contacts_.clear();
        for (std::size_t k = 0; k < near_.size(); ++k) {
            const Index i = near_[k];
            const double rp = law.contactRadius(radius(p.volume0[i]));
            if (nearBody != nullptr && phi_[k] < rp + band) (*nearBody)[i] = 1;
            if (phi_[k] >= rp) {
                slip[i] = 0; // out of contact: the slip history restarts
                continue;
            }
            const int m = p.material[i];
            contacts_.push_back({i, phi_[k], normals_[k],
                                 p.v[i] - body.velocityAt(imageOf(images, p.x[i], body)), rp,
                                 p.mass[i], wave[m]});
        }
        if (law.resetsAllSlip()) { // also points the broad phase no longer reaches
            kept_.resize(contacts_.size());
            for (std::size_t k = 0; k < contacts_.size(); ++k)
                kept_[k] = slip[contacts_[k].particle];
            std::fill(slip.begin(), slip.end(), 0.0);
            for (std::size_t k = 0; k < contacts_.size(); ++k)
                slip[contacts_[k].particle] = kept_[k];
        }
        forces_.resize(contacts_.size());
        law.forces(contacts_, dt, slip, forces_);
        for (std::size_t k = 0; k < contacts_.size(); ++k) {
            const Index i = contacts_[k].particle;
            body.addForce(-forces_[k],
                          law.contactPoint(imageOf(images, p.x[i], body), contacts_[k]));
            const bool local = !law.gasifiedOnGrid() && gasified != nullptr && (*gasified)[i];
            (local ? localPoints_ : gridPoints_).push_back(i);
            (local ? localForces_ : gridForces_).push_back(forces_[k]);
        }
        numContacts_ += static_cast<Index>(contacts_.size());
        nearOf_.resize(bodies.size());
        phiOf_.resize(bodies.size());
        nearOf_[b].swap(near_);
        phiOf_[b].swap(phi_);
    }
}

template <int dim> void Coupling<dim>::applyLocalForces(Particles<dim>& p, double dt) const {
    for (std::size_t k = 0; k < localPoints_.size(); ++k) {
        const Index i = localPoints_[k];
        p.v[i] += (dt / p.mass[i]) * localForces_[k];
    }
}

template <int dim>
Index Coupling<dim>::enforceGap(Particles<dim>& p,
                                std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                                double maxDisplacement, double dt) const {
    Index moved = 0;
    double minGap = 1e300;
    double minGapBefore = 1e300; // the same before any point is projected: what the law achieved
    double pushed = 0.0;         // largest projection so far: points pushed out of one body move
    for (std::size_t b = 0; b < bodies.size() && b < nearOf_.size(); ++b) {
        if (!laws_[b]) continue;
        RigidBody<dim>& body = *bodies[b];
        const CouplingLaw<dim>& law = *laws_[b];
        const PeriodicLattice<dim>* images = imagesFor(body, searchReach(law));
        const std::vector<Index>& near = nearOf_[b];
        const std::vector<double>& phi0 = phiOf_[b];
        const double reach = maxDisplacement + pushed +
                             dt * (body.velocity().norm() +
                                   body.angularVelocity().norm() * body.shape().boundingRadius());
        const Index n = static_cast<Index>(near.size());
        impulses_.assign(n, Vec<dim>::Zero());
        const bool project = law.nonPenetrating();
        double push = 0.0;
        // One point; the reductions' variables are passed in (a thread's own copies).
        auto visit = [&](Index k, Index& nMoved, double& gapMin, double& gapMinBefore,
                         double& pushMax) {
            const Index i = near[k];
            const double gap = project ? law.minimumGap(radius(p.volume0[i])) : -1e300;
            if (phi0[k] - reach > std::max(gap, 0.0)) {
                gapMin = std::min(gapMin, phi0[k] - reach); // cannot be closer: skipped
                gapMinBefore = std::min(gapMinBefore, phi0[k] - reach);
                return;
            }
            Vec<dim> nk;
            const double phi = body.distance(imageOf(images, p.x[i], body), nk);
            gapMinBefore = std::min(gapMinBefore, phi);
            if (phi >= gap) {
                gapMin = std::min(gapMin, phi);
                return;
            }
            // Back to ξ_min along the normal; no approaching velocity. The momentum the point
            // loses goes to the body (below, in order: deterministic).
            p.x[i] += (gap - phi) * nk;
            pushMax = std::max(pushMax, gap - phi);
            const double vn = (p.v[i] - body.velocityAt(imageOf(images, p.x[i], body))).dot(nk);
            if (vn < 0) {
                p.v[i] -= vn * nk;
                impulses_[k] = p.mass[i] * vn * nk;
            }
            ++nMoved;
            Vec<dim> n2;
            gapMin = std::min(gapMin, body.distance(imageOf(images, p.x[i], body), n2));
        };
        // A short loop runs outside any parallel region: even a region of one thread costs a
        // futex system call (5–10 µs on the project's machine), once per body and step.
        if (worthThreads(n)) {
#pragma omp parallel for schedule(static) reduction(+ : moved)                                   \
    reduction(min : minGap, minGapBefore) reduction(max : push)
            for (Index k = 0; k < n; ++k)
                visit(k, moved, minGap, minGapBefore, push);
        } else {
            for (Index k = 0; k < n; ++k)
                visit(k, moved, minGap, minGapBefore, push);
        }
        for (Index k = 0; k < n; ++k)
            if (impulses_[k].squaredNorm() > 0)
                body.applyImpulse(impulses_[k], imageOf(images, p.x[near[k]], body));
        pushed += push;
    }
    minGap_ = minGap;
    minGapBefore_ = minGapBefore;
    return moved;
}

template <int dim>
void Coupling<dim>::nearPoints(const RigidBody<dim>& body, const PeriodicLattice<dim>* images,
                               const Particles<dim>& p, double reach, const BlockSort<dim>& sort,
                               const Grid<dim>& grid) {
    near_.clear();
    if (!images) {
        forParticlesNear(body, Vec<dim>::Zero(), p, reach, sort, grid,
                         [&](Index i) { near_.push_back(i); });
    } else {
        // Every image x_b + n∘L that is the nearest image of some point of the box [lo, hi)
        // (n from imageIndex(lo) to imageIndex(hi): at most two per axis for a centre in the
        // box); a point is kept for the image nearest it only, so it is visited once, with the
        // image that alone can touch it (imagesFor: R + r_p < L/2).
        const Vec<dim>& centre = body.position();
        const IVec<dim> first = images->imageIndex(grid.lo(), centre);
        const IVec<dim> last = images->imageIndex(grid.hi(), centre);
        IVec<dim> n = first;
        while (true) {
            const Vec<dim> shift = n.template cast<double>().cwiseProduct(images->period());
            forParticlesNear(body, shift, p, reach, sort, grid, [&](Index i) {
                if (images->imageIndex(p.x[i], centre) == n) near_.push_back(i);
            });
            int d = 0;
            while (d < dim && ++n[d] > last[d])
                n[d] = first[d], ++d;
            if (d == dim) break;
        }
    }
    const Index n = static_cast<Index>(near_.size());
    phi_.resize(n);
    normals_.resize(n);
    auto visit = [&](Index k) {
        phi_[k] = body.distance(imageOf(images, p.x[near_[k]], body), normals_[k]);
    };
    if (worthThreads(n)) { // a short loop outside any region (enforceGap)
#pragma omp parallel for schedule(static)
        for (Index k = 0; k < n; ++k)
            visit(k);
    } else {
        for (Index k = 0; k < n; ++k)
            visit(k);
    }
}

template <int dim>
void Coupling<dim>::declareState(Particles<dim>& p,
                                 const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies) {
    std::size_t coupled = 0;
    for (const auto& law : laws_)
        coupled += law != nullptr;
    slip_.assign(laws_.size(), 0);
    if (coupled > 0 && findTransPhaseFields(p)) // read by the gas volumes' relaxation
        nearBody_ = p.addFlag(FieldInfo{"nearBody", false, false});
    for (std::size_t b = 0; b < laws_.size(); ++b)
        if (laws_[b])
            slip_[b] = p.addScalar(
                {coupled == 1 ? "contactSlip" : "contactSlip_" + bodies[b]->name()}, 0.0);
}

template <int dim> void Coupling<dim>::keepNearBodyFlag(Particles<dim>& p) {
    const bool coupled =
        std::any_of(laws_.begin(), laws_.end(), [](const auto& l) { return l != nullptr; });
    if (coupled && !nearBody_) nearBody_ = p.addFlag(FieldInfo{"nearBody", false, false});
}

template <int dim> void Coupling<dim>::setParticles(const Particles<dim>& p, const Comm& comm) {
    maxRadius_ = 0;
    for (double v0 : p.volume0)
        maxRadius_ = std::max(maxRadius_, radius(v0));
    maxRadius_ = comm.max(maxRadius_);
}

template <int dim> double Coupling<dim>::stableDeltaT(double lightestMass, double maxWave) const {
    double dt = 1e300;
    for (const auto& law : laws_)
        if (law) dt = std::min(dt, law->stableDeltaT(lightestMass, maxWave));
    return dt;
}

template class Coupling<2>;
template class Coupling<3>;

} // namespace mpm
