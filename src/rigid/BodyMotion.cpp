// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/BodyMotion.hpp"

#include "case/DictionaryVectors.hpp"
#include "case/Registry.hpp"
#include "case/Selection.hpp"
#include "core/Format.hpp"
#include "rigid/RigidBody.hpp"

#include <string>
#include <vector>

namespace mpm {

namespace {

/// Number of angular-velocity components: 3 in 3D, 1 (about z) in 2D.
template <int dim> constexpr int nOmega() {
    return dim == 3 ? 3 : 1;
}

/// The top-level `velocity` of a body entry, zero when absent.
template <int dim> Vec<dim> bodyVelocity(const Dictionary& body) {
    return readVecOr<dim>(body, "velocity", Vec<dim>::Zero());
}

/// Refuse the body entry's `velocity` and `angularVelocity` (`why`: what to do instead).
void refuseTwist(const Dictionary& body, const std::string& motion, const std::string& why) {
    for (const char* key : {"velocity", "angularVelocity"})
        if (body.has(key)) body.error(key, "not used with motion " + motion + why);
}

/// Integrated from gravity and the coupling forces: central difference in translation,
/// Walton–Braun in rotation [004 Eq. 16–32] (RigidBody::integrate).
template <int dim> class FreeMotion : public BodyMotion<dim> {
public:
    explicit FreeMotion(const Dictionary& /*motion*/) {}
    Motion kind() const override { return Motion::Free; }
    void start(const Dictionary& body, RigidBody<dim>& b) const override {
        Vec3 omega = Vec3::Zero();
        if constexpr (dim == 3) {
            if (body.has("angularVelocity")) omega = readVec<3>(body, "angularVelocity");
        } else {
            omega[2] = body.getScalarOr("angularVelocity", 0.0);
        }
        b.setVelocities(bodyVelocity<dim>(body), omega);
    }
    void advance(RigidBody<dim>& body, double dt, double /*t*/,
                 const Vec<dim>& gravity) const override {
        body.integrate(dt, gravity);
    }
    void applyImpulse(RigidBody<dim>& body, const Vec<dim>& J, const Vec<dim>& at) const override {
        body.addLinearImpulse(J);
        body.addAngularImpulse(J, at);
    }
};

/// Never moves.
template <int dim> class FixedMotion : public BodyMotion<dim> {
public:
    explicit FixedMotion(const Dictionary& /*motion*/) {}
    Motion kind() const override { return Motion::Fixed; }
    void start(const Dictionary& body, RigidBody<dim>& /*b*/) const override {
        refuseTwist(body, "fixed", " (a fixed body never moves)");
    }
    void advance(RigidBody<dim>& body, double /*dt*/, double /*t*/,
                 const Vec<dim>& /*gravity*/) const override {
        body.hold();
    }
    void applyImpulse(RigidBody<dim>& /*body*/, const Vec<dim>& /*J*/,
                      const Vec<dim>& /*at*/) const override {}
};

/// A twist given in time: rows (t, v…, ω…) interpolated linearly, held beyond the first and
/// last rows; one row for a constant twist. Prescribed motions give v and ω (world frame),
/// driven ones ω only (v stored as 0).
template <int dim> class TwistTable {
public:
    TwistTable(const Dictionary& m, bool withVelocity) {
        const int nVelocity = withVelocity ? dim : 0;
        const int columns = 1 + nVelocity + nOmega<dim>();
        const auto store = [&](const std::vector<double>& row) {
            std::vector<double> full(row.begin(), row.begin() + 1 + nVelocity);
            full.resize(1 + dim, 0.0);
            full.insert(full.end(), row.begin() + 1 + nVelocity, row.end());
            rows_.push_back(full);
        };
        if (m.has("table")) {
            for (const char* key : {"velocity", "angularVelocity"})
                if (m.has(key))
                    m.error(key, "give either a table or velocity/angularVelocity, not both");
            const std::vector<std::vector<double>> rows = m.vectorList("table", columns);
            if (rows.empty()) m.error("table", "the table needs at least one row");
            for (std::size_t i = 1; i < rows.size(); ++i)
                if (!(rows[i][0] > rows[i - 1][0]))
                    m.error("table", "rows must be sorted by strictly increasing time; row " +
                                         std::to_string(i) + " (t = " + fullPrecision(rows[i][0]) +
                                         ") is not after row " + std::to_string(i - 1));
            for (const auto& row : rows)
                store(row);
            return;
        }
        std::vector<double> row{0.0};
        if (withVelocity) {
            const std::vector<double> v =
                m.getVectorOr("velocity", std::vector<double>(dim, 0.0), dim);
            row.insert(row.end(), v.begin(), v.end());
        }
        if constexpr (dim == 3) {
            const std::vector<double> w = withVelocity
                                              ? m.getVectorOr("angularVelocity", {0.0, 0.0, 0.0}, 3)
                                              : m.getVector("angularVelocity", 3);
            row.insert(row.end(), w.begin(), w.end());
        } else {
            row.push_back(withVelocity ? m.getScalarOr("angularVelocity", 0.0)
                                       : m.getScalar("angularVelocity"));
        }
        store(row);
    }

    /// v and the world ω at time t.
    void at(double t, Vec<dim>& v, Vec3& omega) const {
        std::size_t i0 = 0;
        std::size_t i1 = 0;
        double w = 0.0; // weight of row i1
        if (t <= rows_.front()[0]) {
            i0 = i1 = 0;
        } else if (t >= rows_.back()[0]) {
            i0 = i1 = rows_.size() - 1;
        } else {
            i1 = 1;
            while (rows_[i1][0] < t)
                ++i1;
            i0 = i1 - 1;
            w = (t - rows_[i0][0]) / (rows_[i1][0] - rows_[i0][0]);
        }
        const auto value = [&](std::size_t c) {
            return (1.0 - w) * rows_[i0][c] + w * rows_[i1][c];
        };
        for (int d = 0; d < dim; ++d)
            v[d] = value(1 + d);
        omega.setZero();
        if constexpr (dim == 3) {
            for (int d = 0; d < 3; ++d)
                omega[d] = value(1 + dim + d);
        } else {
            omega[2] = value(1 + dim);
        }
    }

private:
    std::vector<std::vector<double>> rows_;
};

/// v and ω from the table at t + Δt/2; x^{n+1} = x^n + Δt v^{n+½}, the rotation by the exact
/// exponential of ω^{n+½} Δt (RigidBody::moveWith). Forces and impulses do not move it.
template <int dim> class PrescribedMotion : public BodyMotion<dim> {
public:
    explicit PrescribedMotion(const Dictionary& m) : table_(m, true) {}
    Motion kind() const override { return Motion::Prescribed; }
    void start(const Dictionary& body, RigidBody<dim>& b) const override {
        refuseTwist(body, "prescribed", "; give it in the prescribed motion instead");
        Vec<dim> v;
        Vec3 omega;
        table_.at(0.0, v, omega);
        b.setVelocities(v, omega);
    }
    void advance(RigidBody<dim>& body, double dt, double t,
                 const Vec<dim>& /*gravity*/) const override {
        Vec<dim> v;
        Vec3 omega;
        table_.at(t + 0.5 * dt, v, omega);
        body.moveWith(v, omega, dt);
    }
    void applyImpulse(RigidBody<dim>& /*body*/, const Vec<dim>& /*J*/,
                      const Vec<dim>& /*at*/) const override {}

private:
    TwistTable<dim> table_;
};

/// ω from the table at t + Δt/2, the translation free: v^{n+½} = v^{n-½} + Δt (f/m + g)
/// [004 Eq. 19]; an impulse changes v only.
template <int dim> class DrivenMotion : public BodyMotion<dim> {
public:
    explicit DrivenMotion(const Dictionary& m) : table_(m, false) {}
    Motion kind() const override { return Motion::Driven; }
    void start(const Dictionary& body, RigidBody<dim>& b) const override {
        const Vec<dim> v = bodyVelocity<dim>(body);
        if (body.has("angularVelocity"))
            body.error("angularVelocity", "not used with motion driven; give it in the motion");
        Vec<dim> unused;
        Vec3 omega;
        table_.at(0.0, unused, omega);
        b.setVelocities(v, omega);
    }
    void advance(RigidBody<dim>& body, double dt, double t,
                 const Vec<dim>& gravity) const override {
        Vec<dim> unused;
        Vec3 omega;
        table_.at(t + 0.5 * dt, unused, omega);
        body.moveWith(body.freeVelocity(dt, gravity), omega, dt);
    }
    void applyImpulse(RigidBody<dim>& body, const Vec<dim>& J,
                      const Vec<dim>& /*at*/) const override {
        body.addLinearImpulse(J);
    }

private:
    TwistTable<dim> table_;
};

MPM_FAMILY_INFO("bodyMotions", {"<body>.motion (a word, or .type of a map) in constant/rigidBodies",
                                "8. constant/rigidBodies",
                                {{"type", "word", "-", "free", "how the body moves"}}});
MPM_FAMILY_DIMS(BodyMotionRegistry, "bodyMotions");

MPM_REGISTER_DIMS(BodyMotionRegistry, FreeMotion, "free");
MPM_REGISTER_DIMS(BodyMotionRegistry, FixedMotion, "fixed");
MPM_REGISTER_DIMS(BodyMotionRegistry, PrescribedMotion, "prescribed");
MPM_REGISTER_DIMS(BodyMotionRegistry, DrivenMotion, "driven");
MPM_SCHEMA("bodyMotions", "free",
           {"moved by gravity and the coupling and contact forces (the body's velocity and "
            "angularVelocity are its initial twist)",
            {},
            "{type: free}"});
MPM_SCHEMA("bodyMotions", "fixed", {"never moves (terrain, walls, baffles)", {}, "{type: fixed}"});
MPM_SCHEMA("bodyMotions", "prescribed",
           {"velocity and angular velocity given, constant or as a table in time",
            {{"velocity", "vector", "m/s", "0", "v (not with table)"},
             {"angularVelocity", "vector (2D: scalar)", "rad/s", "0",
              "omega, world frame (not with table)"},
             {"table", "list of [t, v..., omega...]", "s, m/s, rad/s", "none",
              "linear in t, rows strictly increasing, held beyond the ends"}},
            "{type: prescribed, velocity: [0, -0.01]}"});
MPM_SCHEMA("bodyMotions", "driven",
           {"angular velocity given, translation free (a driven wheel)",
            {{"angularVelocity", "vector (2D: scalar)", "rad/s", "required without table",
              "omega, world frame"},
             {"table", "list of [t, omega...]", "s, rad/s", "none",
              "linear in t, rows strictly increasing, held beyond the ends"}},
            "{type: driven, angularVelocity: 2}"});

} // namespace

template <int dim>
std::unique_ptr<BodyMotion<dim>> BodyMotion<dim>::create(const Dictionary& body) {
    if (body.isDict("motion")) return BodyMotionRegistry<dim>::create(body.subDict("motion"));
    const std::string word =
        body.getWordOr("motion", "free", registeredWords<BodyMotionRegistry<dim>>());
    const auto* family = ModelCatalogue::find("bodyMotions");
    if (const auto keys = ModelCatalogue::keys("bodyMotions", word); keys && keys->size() > 1)
        body.error("motion", word + " motion takes keys: write it as a map, e.g. " +
                                 family->schemas.at(word).example);
    return BodyMotionRegistry<dim>::create(
        Dictionary::fromString("type: " + word, "constant/rigidBodies"));
}

template class BodyMotion<2>;
template class BodyMotion<3>;

} // namespace mpm
