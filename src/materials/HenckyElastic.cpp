// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/HenckyElastic.hpp"

#include "core/SymmetricEigen.hpp"

#include <cmath>

namespace mpm {

template <int dim>
HenckyElastic<dim>::HenckyElastic(const Dictionary& dict, const std::string& name)
    : Material<dim>(dict, name), c_(dict) {}

template <int dim> double HenckyElastic<dim>::waveSpeed() const {
    return std::sqrt(c_.M / this->density());
}

template <int dim> Mat3 HenckyElastic<dim>::kirchhoff(const ElasticConstants& c, const Mat3& be) {
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(be, lam, Q);
    const Vec3 eps = 0.5 * lam.array().log().matrix();
    const double tr = eps.sum();
    const Vec3 tau = (c.lambda * tr) * Vec3::Ones() + 2.0 * c.G * eps;
    return fromEigen(Q, tau);
}

template <int dim>
double HenckyElastic<dim>::energyDensity(const ElasticConstants& c, const Mat3& be) {
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(be, lam, Q);
    const Vec3 eps = 0.5 * lam.array().log().matrix();
    const double tr = eps.sum();
    return 0.5 * c.lambda * tr * tr + c.G * eps.squaredNorm();
}

template <int dim>
Mat3 HenckyElastic<dim>::leftCauchyGreenFromStress(const ElasticConstants& c, const Mat3& tau) {
    // ε = (τ - λ tr(ε) 1)/(2G) with tr(ε) = tr(τ)/(3K).
    const double trEps = tau.trace() / (3.0 * c.K);
    const Mat3 eps = (tau - c.lambda * trEps * Mat3::Identity()) / (2.0 * c.G);
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(eps, lam, Q);
    return fromEigen(Q, (2.0 * lam).array().exp().matrix());
}

template <int dim>
void HenckyElastic<dim>::initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const {
    p.be[i] = sigma0.isZero(0) ? Mat3::Identity() : leftCauchyGreenFromStress(c_, sigma0);
    p.stress[i] = sigma0;
}

template <int dim>
Index HenckyElastic<dim>::updateStress(Particles<dim>& p, const std::vector<Index>& ids,
                                       double dt) const {
    const Index n = static_cast<Index>(ids.size());
    Index bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
    for (Index k = 0; k < n; ++k) {
        const Index i = ids[k];
        const Mat3 f = Mat3::Identity() + dt * embed3<dim>(p.L[i]);
        const Mat3 be = f * p.be[i] * f.transpose();
        p.be[i] = be;
        p.stress[i] = kirchhoff(c_, be) / p.F[i].determinant();

        if (!std::isfinite(p.stress[i].sum())) bad = std::min(bad, k);
    }
    return bad < n ? ids[bad] : -1;
}

template <int dim>
double HenckyElastic<dim>::strainEnergy(const Particles<dim>& p, Index i) const {
    return energyDensity(c_, p.be[i]) * p.volume0[i];
}

template class HenckyElastic<2>;
template class HenckyElastic<3>;

MPM_REGISTER(MaterialRegistry<2>, HenckyElastic<2>, "henckyElastic");
MPM_REGISTER(MaterialRegistry<3>, HenckyElastic<3>, "henckyElastic");

} // namespace mpm
