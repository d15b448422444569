// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/Viscosity.hpp"

#include "core/Constants.hpp"

#include <cmath>
#include <sstream>

namespace mpm {

double restitutionViscosity(double restitution, double grainDiameter, double pWaveModulus,
                            double bulkDensity) {
    const double halfPi = 0.5 * pi;
    return 0.237 * grainDiameter * std::sqrt(pWaveModulus * bulkDensity) *
           std::pow(std::fabs(std::log(restitution)), halfPi);
}

double continuumRestitution(double zeta) {
    if (zeta < 1.0)
        return std::exp(-zeta * (pi - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta));
    if (zeta == 1.0) return std::exp(-2.0);
    const double r = std::sqrt(zeta * zeta - 1.0);
    return std::exp(-(2.0 * zeta / r) * std::atanh(r / zeta));
}

namespace {

/// ϑ from the keys naming the damping; at most one of restitution and bulkViscosity.
double readBulkViscosity(const Dictionary& dict, const ElasticConstants& c, double density) {
    if (dict.has("restitution")) {
        if (dict.has("bulkViscosity"))
            dict.error("bulkViscosity",
                       "give either restitution (ϑ and η from [002 Eq. 40, 42]) or "
                       "bulkViscosity (and shearViscosity), not both");
        if (dict.has("shearViscosity"))
            dict.error("shearViscosity", "restitution gives η = (G/K) ϑ [002 Eq. 42]; give "
                                         "bulkViscosity instead of restitution to set η");
        const double e = dict.getScalar("restitution", {0.0, 1.0, false, true});
        return restitutionViscosity(e, dict.getScalar("grainDiameter", Bounds::positive()), c.M,
                                    density);
    }
    return dict.getScalarOr("bulkViscosity", 0.0, Bounds::nonNegative());
}

} // namespace

KelvinVoigtViscosity::KelvinVoigtViscosity(const Dictionary& dict, const ElasticConstants& c,
                                           double density)
    : bulk_(readBulkViscosity(dict, c, density)),
      shear_(dict.getScalarOr("shearViscosity", c.G / c.K * bulk_, Bounds::nonNegative())) {}

std::string KelvinVoigtViscosity::describe() const {
    std::ostringstream os;
    os << "    Kelvin-Voigt viscosity: bulk " << bulk_ << " Pa s, shear " << shear_
       << " Pa s (P wave " << pWaveViscosity() << " Pa s)\n";
    return os.str();
}

Mat3 KelvinVoigtViscosity::stress(const Mat3& D) const {
    const double trD = D.trace();
    const Mat3 dev = D - (trD / 3.0) * Mat3::Identity();
    Mat3 s;
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            s(r, k) = (r == k ? volumetric(trD) : 0.0) + deviatoric(dev(r, k));
    return s;
}

} // namespace mpm
