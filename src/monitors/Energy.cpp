// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"
#include "solver/Reduce.hpp"

namespace mpm {

/// `type: energy`: kinetic Σ ½ m v² (+ rigid bodies' ½ m v² + ½ ωᵀIω), strain Σ ψ V (each
/// material's stored energy), gravitational -Σ m g·x of particles and bodies (zero at the
/// origin) and their total [J] (per metre in 2D).
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
        const double strain = deterministicSum(static_cast<Index>(p.size()), [&](Index i) {
            return s.materials[p.material[i]]->strainEnergy(p, i);
        });
        const double gravitational = deterministicSum(static_cast<Index>(p.size()), [&](Index i) {
            return -p.mass[i] * s.gravity.dot(p.x[i]);
        });
        double bodyKinetic = 0, bodyGravitational = 0;
        for (const auto& b : s.bodies) {
            bodyKinetic += b->kineticEnergy();
            bodyGravitational -= b->mass() * s.gravity.dot(b->position());
        }
        const double k = kinetic + bodyKinetic, g = gravitational + bodyGravitational;
        return {k, strain, g, k + strain + g};
    }
};

MPM_REGISTER(FunctionObjectRegistry<2>, Energy<2>, "energy");
MPM_REGISTER(FunctionObjectRegistry<3>, Energy<3>, "energy");

} // namespace mpm
