// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"
#include "solver/Reduce.hpp"

namespace mpm {

/// `type: centreOfMass`: total mass M = Σ m_p [kg] (kg/m in 2D), centre of mass
/// x_c = Σ m_p x_p / M [m] and its velocity v_c = Σ m_p v_p / M [m/s] of the material points,
/// or of those of one material (`material: <name>`). Mass is conserved by MPM, so M changes
/// only when points leave through an open face.
template <int dim> class CentreOfMass final : public FunctionObject<dim> {
public:
    CentreOfMass(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name), materialName_(dict.getStringOr("material", "")) {}

protected:
    void initialise(const State<dim>& s, const Time&) override {
        if (materialName_.empty()) return;
        std::string known;
        for (std::size_t m = 0; m < s.materials.size(); ++m) {
            if (s.materials[m]->name() == materialName_) material_ = static_cast<int>(m);
            known += (m > 0 ? ", " : "") + s.materials[m]->name();
        }
        if (material_ < 0) {
            this->dict().error("material", "no material named '" + materialName_ +
                                               "' in constant/materials (known: " + known + ")");
        }
    }
    std::vector<std::string> columns(const State<dim>&) const override {
        const char* axes = "xyz";
        std::vector<std::string> c{"mass"};
        for (int d = 0; d < dim; ++d)
            c.push_back(std::string(1, axes[d]));
        for (int d = 0; d < dim; ++d)
            c.push_back(std::string("v") + axes[d]);
        return c;
    }
    std::vector<double> values(const State<dim>& s) const override {
        const auto& p = s.particles;
        const Index n = static_cast<Index>(p.size());
        const auto massOf = [&](Index i) {
            return material_ < 0 || p.material[i] == material_ ? p.mass[i] : 0.0;
        };
        std::vector<double> row{deterministicSum(n, massOf)};
        for (int d = 0; d < dim; ++d)
            row.push_back(deterministicSum(n, [&](Index i) { return massOf(i) * p.x[i][d]; }));
        for (int d = 0; d < dim; ++d)
            row.push_back(deterministicSum(n, [&](Index i) { return massOf(i) * p.v[i][d]; }));
        s.comm.sum(row.data(), static_cast<int>(row.size())); // every rank's points
        const double mass = row[0];
        for (std::size_t k = 1; k < row.size(); ++k)
            row[k] = mass > 0 ? row[k] / mass : 0.0;
        return row;
    }

private:
    std::string materialName_;
    int material_ = -1;
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, CentreOfMass, "centreOfMass");
MPM_SCHEMA("functionObjects", "centreOfMass",
           {"mass, centre of mass and its velocity",
            {{"material", "string", "-", "all points", "the material to report"}},
            "{type: centreOfMass, material: sand}"});

} // namespace mpm
