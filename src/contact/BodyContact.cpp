// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/BodyContact.hpp"

#include "contact/ContactForce.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mpm {

template <int dim>
std::unique_ptr<BodyContactLaw<dim>> BodyContactLaw<dim>::create(const Dictionary& dict) {
    return BodyContactRegistry<dim>::create(dict);
}

MPM_FAMILY_INFO("bodyContact", {"type in constant/bodyContact",
                                "8. constant/rigidBodies",
                                {{"type", "word", "-", "required", "the body-body contact law"}}});
MPM_FAMILY_DIMS(BodyContactRegistry, "bodyContact");

template <int dim>
void ContactProbes<dim>::update(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies) {
    if (points.size() == bodies.size()) return;
    points.resize(bodies.size());
    radii.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b)
        bodies[b]->shape().contactProbes(points[b], radii[b]);
}

template <int dim>
std::vector<std::array<int, 2>>
candidatePairs(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies, double margin,
               bool periodic) {
    const int n = static_cast<int>(bodies.size());
    std::vector<std::array<int, 2>> pairs;
    auto both = [&](int i, int j) {
        return bodies[i]->motion() == Motion::Fixed && bodies[j]->motion() == Motion::Fixed;
    };
    if (periodic || n <= 2) { // every pair
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j)
                if (!both(i, j)) pairs.push_back({i, j});
        return pairs;
    }
    std::vector<double> radius(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        radius[static_cast<std::size_t>(i)] = bodies[i]->shape().boundingRadius();
    std::vector<double> sorted = radius;
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
    const double large = 4.0 * sorted[static_cast<std::size_t>(n / 2)];
    double rSmall = 0;
    for (double r : radius)
        if (r <= large) rSmall = std::max(rSmall, r);
    const double cell = 2.0 * rSmall + margin;
    // Small bodies sorted by cell key (coordinates packed 21 bits each), then index.
    auto coord = [&](int i, int d) {
        return static_cast<std::int64_t>(std::floor(bodies[i]->position()[d] / cell));
    };
    auto key = [](const std::array<std::int64_t, 3>& c) {
        constexpr std::int64_t Bias = std::int64_t(1) << 20, Mask = (std::int64_t(1) << 21) - 1;
        return ((c[0] + Bias) & Mask) | (((c[1] + Bias) & Mask) << 21) |
               (((c[2] + Bias) & Mask) << 42);
    };
    std::vector<std::pair<std::int64_t, int>> binned;
    std::vector<int> big;
    for (int i = 0; i < n; ++i) {
        if (radius[static_cast<std::size_t>(i)] > large) {
            big.push_back(i);
            continue;
        }
        std::array<std::int64_t, 3> c{0, 0, 0};
        for (int d = 0; d < dim; ++d)
            c[static_cast<std::size_t>(d)] = coord(i, d);
        binned.emplace_back(key(c), i);
    }
    std::sort(binned.begin(), binned.end());
    for (const auto& [k, i] : binned) {
        std::array<std::int64_t, 3> c{0, 0, 0};
        for (int d = 0; d < dim; ++d)
            c[static_cast<std::size_t>(d)] = coord(i, d);
        for (int m = 0; m < (dim == 2 ? 9 : 27); ++m) { // the 3^dim neighbouring cells
            std::array<std::int64_t, 3> o = c;
            for (int d = 0, code = m; d < dim; ++d, code /= 3)
                o[static_cast<std::size_t>(d)] += code % 3 - 1;
            const std::int64_t ok = key(o);
            auto at = std::lower_bound(binned.begin(), binned.end(), std::make_pair(ok, i + 1));
            for (; at != binned.end() && at->first == ok; ++at)
                if (!both(i, at->second)) pairs.push_back({i, at->second});
        }
    }
    for (int b : big)
        for (int i = 0; i < n; ++i)
            if (i != b && !both(i, b) && (radius[static_cast<std::size_t>(i)] <= large || i > b))
                pairs.push_back({std::min(i, b), std::max(i, b)});
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

template <int dim>
void findProbeContacts(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                       const ContactProbes<dim>& probes, std::vector<ProbeContact<dim>>& contacts,
                       const PeriodicLattice<dim>* periodic) {
    contacts.clear();
    for (const auto& [i, j] : candidatePairs(bodies, 0.0, periodic != nullptr)) {
        const RigidBody<dim>& a = *bodies[i];
        const RigidBody<dim>& b = *bodies[j];
        const double reach = a.shape().boundingRadius() + b.shape().boundingRadius();
        // Minimum image only where one image alone can touch (2 reach < L).
        bool image = periodic != nullptr;
        for (int d = 0; d < dim && image; ++d)
            image = !periodic->periodic(d) || 2 * reach < periodic->period()[d];
        const Vec<dim> ab =
            image ? periodic->separation(a.position(), b.position()) : a.position() - b.position();
        if (ab.squaredNorm() >= reach * reach) continue;
        const bool aProbes = probes.points[i].size() <= probes.points[j].size();
        const RigidBody<dim>& prober = aProbes ? a : b;
        const RigidBody<dim>& target = aProbes ? b : a;
        const std::vector<Vec<dim>>& points = probes.points[aProbes ? i : j];
        const std::vector<double>& radii = probes.radii[aProbes ? i : j];
        // The prober's image nearest the target, and back: shift = x_p − image.
        const Vec<dim> origin =
            image ? periodic->imageNear(prober.position(), target.position()) : prober.position();
        const Vec<dim> shift = prober.position() - origin;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Vec<dim> x = origin + prober.rotation() * points[k];
            Vec<dim> normal;
            const double overlap = radii[k] - target.distance(x, normal);
            if (overlap <= 0) continue;
            const Vec<dim> c = x - (radii[k] - 0.5 * overlap) * normal;
            contacts.push_back({aProbes ? i : j, aProbes ? j : i, static_cast<int>(k), overlap,
                                normal, c, image ? Vec<dim>(c + shift) : c});
        }
    }
}

namespace {

/// Linear spring contact [001 Eq. 38–43]: f_n = k_n δ (− c v_n with the optional dashpot),
/// tangential spring ξ ← P(ξ) + v_t Δt (P: projection on the current tangent plane),
/// f_t = −k_t ξ capped at μ f_n (ξ scaled back to the cap: sliding) (tangentialSpring). The
/// dashpot from a restitution e: c = 2 ζ √(k_n m*) (reducedMass), with ζ such that a head-on
/// collision with this law leaves at e times its impact speed (RestitutionDashpot: the exact
/// restitution of the cut dashpot, so e ∈ [0.14, 1]). Keys: normalStiffness k_n [N/m],
/// tangentialStiffness k_t (default k_n) [N/m], friction μ (default 0), restitution e ∈ [0.14, 1]
/// (default 1: none). In 2D forces are per metre of depth and stiffnesses per metre too.
template <int dim> class LinearSpringContact final : public BodyContactLaw<dim> {
public:
    using typename BodyContactLaw<dim>::BodyList;

    explicit LinearSpringContact(const Dictionary& dict)
        : kn_(dict.getScalar("normalStiffness", Bounds::positive())),
          kt_(dict.getScalarOr("tangentialStiffness", kn_, Bounds::nonNegative())),
          mu_(dict.getScalarOr("friction", 0.0, Bounds::nonNegative())),
          dashpot_(dict.getScalarOr("restitution", 1.0,
                                    Bounds::closed(RestitutionDashpot::lowest, 1.0))) {
        dict.checkUnknownKeys();
    }

    void addForces(BodyList& bodies, ContactHistory<dim>& history, double dt) override {
        probes_.update(bodies);
        findProbeContacts(bodies, probes_, contacts_, this->periodic_);
        ContactHistory<dim> next;
        for (const ProbeContact<dim>& c : contacts_) {
            RigidBody<dim>& p = *bodies[c.prober];
            RigidBody<dim>& t = *bodies[c.target];
            const Vec<dim> vRel = p.velocityAt(c.proberPoint) - t.velocityAt(c.point);
            const double vn = vRel.dot(c.normal);
            double fn = kn_ * c.overlap;
            if (dashpot_.any()) fn -= dashpot_.coefficient(kn_, reducedMass(p, t)) * vn;
            fn = std::max(fn, 0.0); // no attraction
            Vec<dim> xi = Vec<dim>::Zero();
            const auto key = std::array<int, 4>{c.prober, c.target, c.probe, 0};
            if (const auto it = history.find(key); it != history.end()) xi = it->second;
            const Vec<dim> ft = tangentialSpring(xi, c.normal, vRel, vn, kt_, mu_, fn, dt);
            next[key] = xi;
            const Vec<dim> f = fn * c.normal + ft;
            p.addForce(f, c.proberPoint);
            t.addForce(-f, c.point);
        }
        history.swap(next);
    }

    double stableDeltaT(const BodyList& bodies) const override {
        return contactStepLimit(bodies, kn_); // [001 Eq. 51]
    }

private:
    double kn_, kt_, mu_;
    RestitutionDashpot dashpot_;
    ContactProbes<dim> probes_;
    std::vector<ProbeContact<dim>> contacts_;
};

} // namespace

MPM_REGISTER_DIMS(BodyContactRegistry, LinearSpringContact, "linearSpring");
MPM_SCHEMA("bodyContact", "linearSpring",
           {"linear springs with friction and restitution, any shapes",
            {{"normalStiffness", "scalar", "N/m (per metre in 2D)", "required", "k_n (> 0)"},
             {"tangentialStiffness", "scalar", "N/m (per metre in 2D)", "normalStiffness",
              "k_t (≥ 0)"},
             {"friction", "scalar", "-", "0", "Coulomb μ (≥ 0)"},
             {"restitution", "scalar", "-", "1", "e in [0.14, 1]; 1: no dashpot"}},
            "{type: linearSpring, normalStiffness: 1.0e7, friction: 0.4, restitution: 0.5}"});

template class BodyContactLaw<2>;
template class BodyContactLaw<3>;
template struct ContactProbes<2>;
template struct ContactProbes<3>;
template std::vector<std::array<int, 2>>
candidatePairs(const std::vector<std::unique_ptr<RigidBody<2>>>&, double, bool);
template std::vector<std::array<int, 2>>
candidatePairs(const std::vector<std::unique_ptr<RigidBody<3>>>&, double, bool);
template void findProbeContacts(const std::vector<std::unique_ptr<RigidBody<2>>>&,
                                const ContactProbes<2>&, std::vector<ProbeContact<2>>&,
                                const PeriodicLattice<2>*);
template void findProbeContacts(const std::vector<std::unique_ptr<RigidBody<3>>>&,
                                const ContactProbes<3>&, std::vector<ProbeContact<3>>&,
                                const PeriodicLattice<3>*);

} // namespace mpm
