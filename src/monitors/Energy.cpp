// SPDX-License-Identifier: GPL-3.0-or-later
#include "forces/BodyAcceleration.hpp"
#include "monitors/FunctionObject.hpp"
#include "solver/Reduce.hpp"
#include "solver/StateMeasures.hpp"

namespace mpm {

/// `type: energy`: kinetic Σ ½ m v² (+ rigid bodies' ½ m v² + ½ ωᵀIω), strain Σ ψ V (each
/// material's stored energy), gravitational and their total [J] (per metre in 2D).
///
/// Gravitational: for a constant body acceleration g (constant/g without `type:`, or any
/// field whose g does not vary) the potential −Σ m g·x of particles and bodies (zero at the
/// origin). A time-varying g(t) has no potential; the column is then −W, with
/// W = ∫ Σ m g(t)·v dt the work the field has done on particles and bodies since the start
/// (State::accelerationWork, accumulated by the solver), so that total = kinetic + strain − W
/// stays constant for an undamped elastic body. For a constant g the two columns differ only
/// by the constant −Σ m g·x₀ of the initial state.
template <int dim> class Energy final : public FunctionObject<dim> {
public:
    Energy(const Dictionary& dict, const std::string& name) : FunctionObject<dim>(dict, name) {}

protected:
    std::vector<std::string> columns(const State<dim>&) const override {
        return {"kinetic", "strain", "gravitational", "total"};
    }
    std::vector<double> values(const State<dim>& s) const override {
        const auto& p = s.particles;
        const double kinetic = deterministicSum(static_cast<Index>(p.size()), [&](Index i) {
            return 0.5 * p.mass[i] * p.v[i].squaredNorm();
        });
        const double strain = totalStrainEnergy(p, s.materials);
        double bodyKinetic = 0;
        double sums[3] = {kinetic, strain, 0.0}; // this rank's points, then every rank's
        for (const auto& b : s.bodies)
            bodyKinetic += b->kineticEnergy();
        if (!s.acceleration.isConstant()) {
            s.comm.sum(sums, 2);
            const double k = sums[0] + bodyKinetic;
            const double g = -s.accelerationWork;
            return {k, sums[1], g, k + sums[1] + g};
        }
        const Vec<dim> gravity = s.acceleration.at(s.time);
        sums[2] = deterministicSum(static_cast<Index>(p.size()),
                                   [&](Index i) { return -p.mass[i] * gravity.dot(p.x[i]); });
        s.comm.sum(sums, 3);
        const double k = sums[0] + bodyKinetic;
        double bodyGravitational = 0;
        for (const auto& b : s.bodies)
            bodyGravitational -= b->mass() * gravity.dot(b->position());
        const double g = sums[2] + bodyGravitational;
        return {k, sums[1], g, k + sums[1] + g};
    }
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, Energy, "energy");
MPM_SCHEMA("functionObjects", "energy",
           {"kinetic, strain, gravitational and total energy [J] (J/m in 2D)",
            {},
            "{type: energy}"});

} // namespace mpm
