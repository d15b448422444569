// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/LinearElastic.hpp"
#include "core/Parallel.hpp"

#include <cmath>

namespace mpm {

template <int dim>
LinearElastic<dim>::LinearElastic(const Dictionary& dict, const std::string& name)
    : Material<dim>(dict, name), c_(dict) {}

template <int dim> double LinearElastic<dim>::waveSpeed() const {
    return std::sqrt(c_.M / this->density());
}

template <int dim>
void LinearElastic<dim>::initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const {
    p.be[i] = Mat3::Identity();
    p.stress[i] = sigma0;
}

template <int dim>
Index LinearElastic<dim>::updateStress(Particles<dim>& p, const std::vector<Index>& ids,
                                       double dt) const {
    const Index n = static_cast<Index>(ids.size());
    Index bad = n;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : bad)
    for (Index k = 0; k < n; ++k) {
        const Index i = ids[k];
        const Mat3 L = embed3<dim>(p.L[i]);
        const Mat3 D = 0.5 * (L + L.transpose());
        const Mat3 W = 0.5 * (L - L.transpose());
        const Mat3& s = p.stress[i];
        const double trD = D.trace();
        const Mat3 rate =
            (c_.K - 2.0 * c_.G / 3.0) * trD * Mat3::Identity() + 2.0 * c_.G * D + W * s - s * W;
        p.stress[i] = s + dt * rate;

        if (!std::isfinite(p.stress[i].sum())) bad = std::min(bad, k);
    }
    return bad < n ? ids[bad] : -1;
}

template <int dim> double LinearElastic<dim>::strainEnergy(const Particles<dim>& p, Index i) const {
    const Mat3& s = p.stress[i];
    const double pr = s.trace() / 3.0;
    const Mat3 dev = s - pr * Mat3::Identity();
    return (pr * pr / (2.0 * c_.K) + dev.squaredNorm() / (4.0 * c_.G)) * p.volume[i];
}

template class LinearElastic<2>;
template class LinearElastic<3>;

MPM_REGISTER(MaterialRegistry<2>, LinearElastic<2>, "linearElastic");
MPM_REGISTER(MaterialRegistry<3>, LinearElastic<3>, "linearElastic");

} // namespace mpm
