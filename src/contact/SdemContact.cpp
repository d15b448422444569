// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/SdemContact.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "rigid/SpheroPolygon.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

SdemContact::SdemContact(const Dictionary& dict)
    : kn_(dict.getScalar("kn", Bounds::positive())),
      kt_(dict.getScalarOr("kt", kn_, Bounds::nonNegative())),
      mu_(dict.getScalarOr("friction", 0.0, Bounds::nonNegative())),
      dashpot_(
          dict.getScalarOr("restitution", 1.0, Bounds::closed(RestitutionDashpot::lowest, 1.0))),
      vdGiven_(dict.getScalarOr("verletDistance", 0.0, Bounds::positive())), file_(dict.fileName()),
      line_(dict.line("type")) {
    dict.checkUnknownKeys();
}

double SdemContact::dashpot(double m) const {
    return dashpot_.coefficient(kn_, m);
}

double SdemContact::stableDeltaT(const BodyList& bodies) const {
    return contactStepLimit(bodies, kn_);
}

Vec<2> SdemContact::separation(const RigidBody<2>& a, const RigidBody<2>& b) const {
    const auto* lattice = this->periodic_;
    if (!lattice) return a.position() - b.position();
    const double reach = a.shape().boundingRadius() + b.shape().boundingRadius();
    for (int d = 0; d < 2; ++d)
        if (lattice->periodic(d) && 2 * reach >= lattice->period()[d])
            return a.position() - b.position(); // where they lie (a body spanning the box)
    return lattice->separation(a.position(), b.position());
}

void SdemContact::check(const BodyList& bodies) {
    if (vd_ > 0) return;
    double rMin = 1e300;
    for (const auto& b : bodies) {
        if (!b->shape().spheroPolygon())
            throw InputError(file_, line_, "type",
                             "sdem contact needs spheropolygon bodies (spheropolygon, box or "
                             "disk); body '" +
                                 b->name() + "' has another shape");
        rMin = std::min(rMin, b->shape().boundingRadius());
    }
    vd_ = vdGiven_ > 0 ? vdGiven_ : 0.1 * rMin;
}

std::vector<std::array<int, 2>> SdemContact::allNear(const BodyList& bodies) const {
    std::vector<std::array<int, 2>> near;
    const int n = static_cast<int>(bodies.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            const RigidBody<2>& a = *bodies[i];
            const RigidBody<2>& b = *bodies[j];
            if (a.motion() == Motion::Fixed && b.motion() == Motion::Fixed) continue;
            const double reach = a.shape().boundingRadius() + b.shape().boundingRadius() + vd_;
            if (separation(a, b).squaredNorm() < reach * reach) near.push_back({i, j});
        }
    return near;
}

const std::vector<std::array<int, 2>>& SdemContact::neighbours(const BodyList& bodies) {
    check(bodies);
    bool rebuild = built_.size() != bodies.size();
    for (std::size_t b = 0; b < bodies.size() && !rebuild; ++b) {
        const Vec<2>& x = bodies[b]->position();
        const Vec<2> moved =
            this->periodic_ ? this->periodic_->separation(x, built_[b]) : Vec<2>(x - built_[b]);
        rebuild = moved.squaredNorm() > 0.25 * vd_ * vd_;
    }
    if (!rebuild) return pairs_;
    pairs_.clear(); // the candidates (binned: O(N log N)) within reach, in pair order
    for (const auto& [i, j] : candidatePairs(bodies, vd_, this->periodic_ != nullptr)) {
        const RigidBody<2>& a = *bodies[i];
        const RigidBody<2>& b = *bodies[j];
        const double reach = a.shape().boundingRadius() + b.shape().boundingRadius() + vd_;
        if (separation(a, b).squaredNorm() < reach * reach) pairs_.push_back({i, j});
    }
    built_.clear();
    for (const auto& b : bodies)
        built_.push_back(b->position());
    ++builds_;
    for (const auto& [i, j] : pairs_) {
        if (bodies[i]->shape().spheroPolygon()->radius > 0 ||
            bodies[j]->shape().spheroPolygon()->radius > 0 || !warned_.insert({i, j}).second)
            continue;
        warning() << file_ << ": sdem contact: bodies '" << bodies[i]->name() << "' and '"
                  << bodies[j]->name()
                  << "' both have sphero-radius 0 (a box has a = 0): they cannot touch under "
                     "this law (give one a spheropolygon with radius > 0)\n";
    }
    return pairs_;
}

void SdemContact::vertexEdge(BodyList& bodies, int v, int e, const Vec<2>& shiftV,
                             const ContactHistory<2>& history, ContactHistory<2>& next, double dt) {
    RigidBody<2>& bv = *bodies[v];
    RigidBody<2>& be = *bodies[e];
    const SpheroPolygon& sv = *bv.shape().spheroPolygon();
    const SpheroPolygon& se = *be.shape().spheroPolygon();
    const double reach = sv.radius + se.radius;
    // Edge end points in the world frame, and ρ² = max |Y_k − c_e|²: every point of an edge lies
    // within ρ of the edge body's centroid c_e (convexity).
    std::vector<Vec<2>>& ye = edgeEnds_;
    ye.resize(se.vertices.size());
    double rho2 = 0;
    for (std::size_t k = 0; k < ye.size(); ++k) {
        ye[k] = be.position() + be.rotation() * se.vertices[k];
        rho2 = std::max(rho2, (ye[k] - be.position()).squaredNorm());
    }
    // A vertex with |V − c_e| ≥ ρ + a_i + a_j + m has d(V, E) ≥ a_i + a_j for every edge (ξ ≤ 0,
    // no contact) and skips the edge loop; m = 1e-10 × the coordinates' size covers the rounding
    // of d and ρ (≈ 1e-15 of it), so a skipped vertex is one whose every ξ computes ≤ 0.
    const Vec<2>& ce = be.position();
    const double rho = std::sqrt(rho2);
    const double size = ce.cwiseAbs().maxCoeff() + bv.position().cwiseAbs().maxCoeff() +
                        shiftV.cwiseAbs().maxCoeff() + bv.shape().boundingRadius() + rho + reach;
    const double far = rho + reach + 1e-10 * size;
    for (int k = 0; k < static_cast<int>(sv.vertices.size()); ++k) {
        const Vec<2> x = bv.position() + shiftV + bv.rotation() * sv.vertices[k];
        if ((x - ce).squaredNorm() >= far * far) continue;
        for (int l = 0; l < se.edgeCount(); ++l) {
            Vec<2> y;
            const double d = closestOnSegment(x, ye[l], ye[se.edgeEnd(l)], y);
            const double xi = reach - d;
            if (xi <= 0) continue;
            Vec<2> n;
            if (d > 1e-12 * reach) {
                n = (x - y) / d;
            } else { // the vertex on the edge: push apart along the centroids
                const Vec<2> c = bv.position() + shiftV - be.position();
                n = c.norm() > 0 ? Vec<2>(c.normalized()) : Vec<2>::UnitX();
            }
            const Vec<2> p = x - (sv.radius - 0.5 * xi) * n; // [001 Eq. 41]
            const Vec<2> pv = p - shiftV;                    // on the vertex body's side
            const Vec<2> vRel = bv.velocityAt(pv) - be.velocityAt(p);
            const double vn = vRel.dot(n);
            double fn = kn_ * xi;
            if (dashpot_.any()) fn = std::max(0.0, fn - dashpot(reducedMass(bv, be)) * vn);
            const std::array<int, 4> key{v, e, k, l};
            Vec<2> dt_ = Vec<2>::Zero();
            if (const auto it = history.find(key); it != history.end()) dt_ = it->second;
            const Vec<2> ft = tangentialSpring(dt_, n, vRel, vn, kt_, mu_, fn, dt); // capped
            next[key] = dt_;
            const Vec<2> f = fn * n + ft;
            bv.addForce(f, pv);
            be.addForce(-f, p);
        }
    }
}

void SdemContact::addForces(BodyList& bodies, ContactHistory<2>& history, double dt) {
    ContactHistory<2> next;
    for (const auto& [i, j] : neighbours(bodies)) {
        // Body i's image nearest body j (periodic), as an offset of its centroid.
        const Vec<2> shift =
            separation(*bodies[i], *bodies[j]) - (bodies[i]->position() - bodies[j]->position());
        vertexEdge(bodies, i, j, shift, history, next, dt);
        // Body j's vertices against i's edges: j seen from i's image, i.e. j shifted by −shift.
        vertexEdge(bodies, j, i, -shift, history, next, dt);
    }
    history.swap(next);
}

MPM_REGISTER_ONLY(2, BodyContactRegistry, SdemContact, "sdem");
MPM_SCHEMA("bodyContact", "sdem",
           {"spheropolygon DEM, vertex-edge pairs [001 §3.2] (spheropolygons, boxes, disks)",
            {{"kn", "scalar", "N/m per metre", "required", "normal stiffness k_n (> 0)"},
             {"kt", "scalar", "N/m per metre", "kn", "tangential stiffness k_t (≥ 0)"},
             {"friction", "scalar", "-", "0", "Coulomb μ (≥ 0)"},
             {"restitution", "scalar", "-", "1", "e in [0.14, 1]; 1: no dashpot"},
             {"verletDistance", "scalar", "m", "0.1 R_min", "neighbour-list margin V_d (> 0)"}},
            "{type: sdem, kn: 6.0e6, kt: 3.0e5, friction: 0.2}",
            "spheropolygon DEM is a 2D contact law: use linearSpring"});

} // namespace mpm
