// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/HenckyLaw.hpp"

#include "core/SymmetricEigen.hpp"

#include <cmath>

namespace mpm {

Mat3 HenckyLaw::kirchhoff(const ElasticConstants& c, const Mat3& be) {
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(be, lam, Q);
    const Vec3 eps = 0.5 * lam.array().log().matrix();
    const double tr = eps.sum();
    const Vec3 tau = (c.lambda * tr) * Vec3::Ones() + 2.0 * c.G * eps;
    return fromEigen(Q, tau);
}

double HenckyLaw::energyDensity(const ElasticConstants& c, const Mat3& be) {
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(be, lam, Q);
    const Vec3 eps = 0.5 * lam.array().log().matrix();
    const double tr = eps.sum();
    return 0.5 * c.lambda * tr * tr + c.G * eps.squaredNorm();
}

Mat3 HenckyLaw::leftCauchyGreenFromStress(const ElasticConstants& c, const Mat3& tau) {
    // ε = (τ - λ tr(ε) 1)/(2G) with tr(ε) = tr(τ)/(3K).
    const double trEps = tau.trace() / (3.0 * c.K);
    const Mat3 eps = (tau - c.lambda * trEps * Mat3::Identity()) / (2.0 * c.G);
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(eps, lam, Q);
    return fromEigen(Q, (2.0 * lam).array().exp().matrix());
}

} // namespace mpm
