// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/Coupling.hpp"

#include <cmath>

namespace mpm {

template <int dim>
Coupling<dim>::Coupling(std::vector<std::unique_ptr<CouplingLaw<dim>>> laws)
    : laws_(std::move(laws)) {}

template <int dim>
template <class Fn>
void Coupling<dim>::forParticlesNear(const RigidBody<dim>& body, double reach,
                                     const BlockSort<dim>& sort, const Grid<dim>& grid,
                                     Fn&& fn) const {
    // Block range of the ball's bounding box, one cell of margin for motion within the step.
    const Vec<dim>& centre = body.position();
    const double radius = body.shape().boundingRadius() + reach;
    const double size = Grid<dim>::BlockSize * grid.h();
    // One cell for the motion within the step, one of margin for a sampled distance field.
    const double cull = 0.5 * size * std::sqrt(double(dim)) + 2.0 * grid.h() + reach;
    IVec<dim> lo, hi;
    for (int d = 0; d < dim; ++d) {
        lo[d] = std::max(0, static_cast<int>(std::floor(
                                (centre[d] - radius - grid.h() - grid.origin()[d]) / size)));
        hi[d] = std::min(grid.blocks()[d] - 1,
                         static_cast<int>(std::floor(
                             (centre[d] + radius + grid.h() - grid.origin()[d]) / size)));
        if (hi[d] < lo[d]) return;
    }
    const auto& order = sort.order();
    IVec<dim> c = lo;
    while (true) {
        Index b = 0;
        for (int d = dim - 1; d >= 0; --d)
            b = b * grid.blocks()[d] + c[d];
        if (sort.start(b) < sort.start(b + 1)) {
            Vec<dim> blockCentre;
            for (int d = 0; d < dim; ++d)
                blockCentre[d] = grid.origin()[d] + (c[d] + 0.5) * size;
            Vec<dim> normal;
            if (body.distance(blockCentre, normal) <= cull) {
                for (Index j = sort.start(b); j < sort.start(b + 1); ++j)
                    fn(order[j]);
            }
        }
        int d = 0;
        while (d < dim && ++c[d] > hi[d])
            c[d] = lo[d], ++d;
        if (d == dim) break;
    }
}

template <int dim>
void Coupling<dim>::computeForces(const Particles<dim>& p, std::vector<double>& slip,
                                  const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                                  const std::vector<double>& wave,
                                  const std::vector<double>& criticalDensity,
                                  const BlockSort<dim>& sort, const Grid<dim>& grid, double dt) {
    gridPoints_.clear();
    gridForces_.clear();
    localPoints_.clear();
    localForces_.clear();
    numContacts_ = 0;
    const double rpMax = maxRadius_;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (!laws_[b]) continue;
        RigidBody<dim>& body = *bodies[b];
        contacts_.clear();
        forParticlesNear(body, rpMax, sort, grid, [&](Index i) {
            const double rp = radius(p.volume0[i]);
            Vec<dim> n;
            const double phi = body.distance(p.x[i], n);
            if (phi >= rp) {
                slip[i] = 0; // out of contact: the slip history restarts
                return;
            }
            const int m = p.material[i];
            contacts_.push_back(
                {i, phi, n, p.v[i] - body.velocityAt(p.x[i]), rp, p.mass[i], wave[m]});
        });
        forces_.resize(contacts_.size());
        laws_[b]->forces(contacts_, dt, slip, forces_);
        for (std::size_t k = 0; k < contacts_.size(); ++k) {
            const Index i = contacts_[k].particle;
            body.addForce(-forces_[k], p.x[i]);
            const int m = p.material[i];
            const bool gasified = p.mass[i] < criticalDensity[m] * p.volume[i];
            (gasified ? localPoints_ : gridPoints_).push_back(i);
            (gasified ? localForces_ : gridForces_).push_back(forces_[k]);
        }
        numContacts_ += static_cast<Index>(contacts_.size());
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
                                const BlockSort<dim>& sort, const Grid<dim>& grid) const {
    Index moved = 0;
    minGap_ = 1e300;
    const double rpMax = maxRadius_;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (!laws_[b]) continue;
        RigidBody<dim>& body = *bodies[b];
        const CouplingLaw<dim>& law = *laws_[b];
        forParticlesNear(body, rpMax, sort, grid, [&](Index i) {
            Vec<dim> n;
            const double phi = body.distance(p.x[i], n);
            if (law.nonPenetrating()) {
                const double gap = law.minimumGap(radius(p.volume0[i]));
                if (phi < gap) {
                    // Back to ξ_min along the normal; no approaching velocity.
                    // The momentum the point loses goes to the body.
                    p.x[i] += (gap - phi) * n;
                    const double vn = (p.v[i] - body.velocityAt(p.x[i])).dot(n);
                    if (vn < 0) {
                        p.v[i] -= vn * n;
                        body.applyImpulse(p.mass[i] * vn * n, p.x[i]);
                    }
                    ++moved;
                    Vec<dim> n2;
                    minGap_ = std::min(minGap_, body.distance(p.x[i], n2));
                    return;
                }
            }
            minGap_ = std::min(minGap_, phi);
        });
    }
    return moved;
}

template <int dim> void Coupling<dim>::setParticles(const Particles<dim>& p) {
    maxRadius_ = 0;
    for (double v0 : p.volume0)
        maxRadius_ = std::max(maxRadius_, radius(v0));
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
