// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/HenckyElastic.hpp"
#include "core/Parallel.hpp"

#include "core/FastMath.hpp"
#include "core/SymmetricEigen.hpp"

#include <algorithm>
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
    // Particles go through in batches of Lanes so that the eigen-decompositions vectorise
    // across particles (DESIGN §7); the last batch is padded with copies of its first particle.
    constexpr int Lanes = 8;
    const Index n = static_cast<Index>(ids.size());
    const Index batches = (n + Lanes - 1) / Lanes;
    const double lambda = c_.lambda, twoG = 2.0 * c_.G;
    Index bad = n;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static) reduction(min : bad)
    for (Index b = 0; b < batches; ++b) {
        Mat3 be[Lanes], Q[Lanes];
        Vec3 lam[Lanes];
        Index idx[Lanes];
        for (int l = 0; l < Lanes; ++l) {
            const Index k = std::min(b * Lanes + l, n - 1);
            idx[l] = ids[k];
            const Mat3 f = Mat3::Identity() + dt * embed3<dim>(p.L[idx[l]]);
            be[l] = f * p.be[idx[l]] * f.transpose();
        }
        symmetricEigen3Batch<Lanes>(be, lam, Q);
        // ε = ½ ln bᵉ in principal axes, vectorised across the batch.
        double eps[3][Lanes];
#pragma omp simd
        for (int l = 0; l < Lanes; ++l)
            for (int a = 0; a < 3; ++a)
                eps[a][l] = 0.5 * fastLog(lam[l][a]);
        for (int l = 0; l < Lanes; ++l) {
            if (b * Lanes + l >= n) break;
            const Index i = idx[l];
            // τ = λ tr(ε) 1 + 2G ε [000 Eq. 4–5]; σ = τ/J with J = V/V⁰.
            const Vec3 e(eps[0][l], eps[1][l], eps[2][l]);
            const Vec3 tau = (lambda * e.sum()) * Vec3::Ones() + twoG * e;
            p.be[i] = be[l];
            p.stress[i] = fromEigen(Q[l], tau * (p.volume0[i] / p.volume[i]));
            if (!std::isfinite(p.stress[i].sum())) bad = std::min(bad, b * Lanes + l);
        }
    }
    return bad < n ? ids[bad] : -1;
}

template <int dim> double HenckyElastic<dim>::strainEnergy(const Particles<dim>& p, Index i) const {
    return energyDensity(c_, p.be[i]) * p.volume0[i];
}

template class HenckyElastic<2>;
template class HenckyElastic<3>;

MPM_REGISTER(MaterialRegistry<2>, HenckyElastic<2>, "henckyElastic");
MPM_REGISTER(MaterialRegistry<3>, HenckyElastic<3>, "henckyElastic");

} // namespace mpm
