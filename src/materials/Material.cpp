// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/Material.hpp"

#include "case/Registry.hpp"

#include <sstream>

namespace mpm {

ElasticConstants::ElasticConstants(double youngs, double poisson) : E(youngs), nu(poisson) {
    G = E / (2.0 * (1.0 + nu));
    lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    K = E / (3.0 * (1.0 - 2.0 * nu));
    M = K + 4.0 * G / 3.0;
}

ElasticConstants::ElasticConstants(const Dictionary& dict)
    : ElasticConstants(dict.getScalar("E", Bounds::positive()),
                       dict.getScalar("nu", {-1.0, 0.5, false, false})) {}

template <int dim>
Material<dim>::Material(const Dictionary& dict, std::string name)
    : name_(std::move(name)), density_(dict.getScalar("density", Bounds::positive())) {}

template <int dim> std::string Material<dim>::describe() const {
    std::ostringstream os;
    os << "    density " << density_ << " kg/m3, P-wave speed " << waveSpeed() << " m/s\n";
    return os.str();
}

template <int dim>
std::unique_ptr<Material<dim>> Material<dim>::create(const Dictionary& dict,
                                                     const std::string& name) {
    return MaterialRegistry<dim>::create(dict, name);
}

template <int dim>
std::vector<std::unique_ptr<Material<dim>>> Material<dim>::createAll(const Dictionary& materials) {
    std::vector<std::unique_ptr<Material<dim>>> all;
    for (const std::string& name : materials.keys())
        all.push_back(create(materials.subDict(name), name));
    if (all.empty()) materials.error("", "no materials are defined");
    return all;
}

template class Material<2>;
template class Material<3>;

MPM_FAMILY_INFO("materials",
                {"<material>.type in constant/materials",
                 "6. constant/materials",
                 {{"type", "word", "-", "required", "the model"},
                  {"density", "scalar", "kg/m³", "required", "initial density ρ₀ (> 0)"}}});
MPM_FAMILY_DIMS(MaterialRegistry, "materials");

} // namespace mpm
