// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/ViscoelasticMuI.hpp"

#include "core/Parallel.hpp"
#include "materials/FlowRules.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

double restitutionViscosity(double restitution, double grainDiameter, double pWaveModulus,
                            double bulkDensity) {
    const double halfPi = 0.5 * 3.14159265358979323846;
    return 0.237 * grainDiameter * std::sqrt(pWaveModulus * bulkDensity) *
           std::pow(std::fabs(std::log(restitution)), halfPi);
}

double continuumRestitution(double zeta) {
    const double pi = 3.14159265358979323846;
    if (zeta < 1.0)
        return std::exp(-zeta * (pi - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta));
    if (zeta == 1.0) return std::exp(-2.0);
    const double r = std::sqrt(zeta * zeta - 1.0);
    return std::exp(-(2.0 * zeta / r) * std::atanh(r / zeta));
}

namespace {

/// exp(A) of a skew-symmetric A = [w]× by Rodrigues' formula: a rotation.
Mat3 rotationOf(const Mat3& A) {
    const double t2 = A(2, 1) * A(2, 1) + A(0, 2) * A(0, 2) + A(1, 0) * A(1, 0); // |w|²
    const Mat3 A2 = A * A;
    if (t2 < 1e-12) // series to O(θ⁴): exact to round-off for θ < 1e-6
        return Mat3::Identity() + (1.0 - t2 / 6.0) * A + (0.5 - t2 / 24.0) * A2;
    const double t = std::sqrt(t2);
    return Mat3::Identity() + (std::sin(t) / t) * A + ((1.0 - std::cos(t)) / t2) * A2;
}

/// The keys naming the damping; at most one of restitution and bulkViscosity.
double readBulkViscosity(const Dictionary& dict, const ElasticConstants& c, double density,
                         double grainDiameter) {
    if (dict.has("restitution")) {
        if (dict.has("bulkViscosity"))
            dict.error("bulkViscosity",
                       "give either restitution (ϑ and η from [002 Eq. 40, 42]) or "
                       "bulkViscosity (and shearViscosity), not both");
        if (dict.has("shearViscosity"))
            dict.error("shearViscosity", "restitution gives η = (G/K) ϑ [002 Eq. 42]; give "
                                         "bulkViscosity instead of restitution to set η");
        const double e = dict.getScalar("restitution", {0.0, 1.0, false, true});
        return restitutionViscosity(e, grainDiameter, c.M, density);
    }
    return dict.getScalarOr("bulkViscosity", 0.0, Bounds::nonNegative());
}

} // namespace

template <int dim>
ViscoelasticMuI<dim>::ViscoelasticMuI(const Dictionary& dict, const std::string& name)
    : Material<dim>(dict, name), c_(dict),
      muS_(std::tan(dict.getScalar("frictionAngle", {0.0, 90.0, false, false}) * degree)),
      mu2_(std::tan(
          dict.getScalar("frictionAngle2", {std::atan(muS_) / degree, 90.0, false, false}) *
          degree)),
      I0_(dict.getScalarOr("I0", 0.278, Bounds::positive())),
      grainDiameter_(dict.getScalar("grainDiameter", Bounds::positive())),
      grainDensity_(dict.getScalar("grainDensity", Bounds::positive())),
      bulkViscosity_(readBulkViscosity(dict, c_, this->density(), grainDiameter_)),
      shearViscosity_(
          dict.getScalarOr("shearViscosity", c_.G / c_.K * bulkViscosity_, Bounds::nonNegative())),
      rhoC_(dict.getScalarOr("criticalDensity", this->density(), Bounds::nonNegative())) {}

template <int dim> double ViscoelasticMuI<dim>::waveSpeed() const {
    return std::sqrt(c_.M / this->density());
}

template <int dim> void ViscoelasticMuI<dim>::declareState(Particles<dim>& p) {
    elasticStress_ = p.addTensor(FieldInfo{"elasticStress"});
    strainRate_ = p.addScalar(FieldInfo{"plasticStrainRate", false, true});
    state_ = p.addFlag(FieldInfo{"flowState", false, true});
}

template <int dim>
void ViscoelasticMuI<dim>::initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const {
    p.be[i] = Mat3::Identity();
    p.stress[i] = sigma0;
    p.tensor(elasticStress_)[i] = sigma0; // at rest: no viscous stress
    p.scalar(strainRate_)[i] = 0.0;
    p.flag(state_)[i] = elasticState;
}

template <int dim> double ViscoelasticMuI<dim>::defaultK0() const {
    return 1.0 - std::sin(std::atan(muS_));
}

template <int dim>
double ViscoelasticMuI<dim>::strainEnergy(const Particles<dim>& p, Index i) const {
    const Mat3& s = p.tensor(elasticStress_)[i];
    const double pr = s.trace() / 3.0;
    const Mat3 dev = s - pr * Mat3::Identity();
    return (pr * pr / (2.0 * c_.K) + dev.squaredNorm() / (4.0 * c_.G)) * p.volume[i];
}

template <int dim>
Index ViscoelasticMuI<dim>::updateStress(Particles<dim>& p, const std::vector<Index>& ids,
                                         double dt) const {
    const Index n = static_cast<Index>(ids.size());
    const double lambda = c_.lambda, G = c_.G;
    const double theta = bulkViscosity_, eta = shearViscosity_;
    const double Gt = G + eta / dt; // G̃ [Eq. 55]
    const double alphaCoef = I0_ * Gt * dt / (grainDiameter_ * std::sqrt(grainDensity_)); // α/√p
    std::vector<Mat3>& sigmaE = p.tensor(elasticStress_);
    std::vector<double>& rate = p.scalar(strainRate_);
    std::vector<int>& state = p.flag(state_);
    Index bad = n;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : bad)
    for (Index k = 0; k < n; ++k) {
        const Index i = ids[k];
        const Mat3 L = embed3<dim>(p.L[i]);
        const Mat3 D = 0.5 * (L + L.transpose());
        const Mat3 W = 0.5 * (L - L.transpose());
        const double trD = D.trace();
        const Mat3 Ddev = D - (trD / 3.0) * Mat3::Identity();
        // 1. Objective elastic trial [Eq. 52]: σᵉ rotated by Q = exp(Δt W), the increment
        //    ℂ : Δt D taken at the end of the step (not half-rotated, Q½ Δt D Q½ᵀ): the return
        //    is implicit, and in fast flow the stress must align with the rate it returns to
        //    (docs/viscoelastic.md §1, "why the increment is not rotated").
        const Mat3 Q = rotationOf(dt * W);
        const Mat3 eTrial =
            Q * sigmaE[i] * Q.transpose() + dt * (lambda * trD * Mat3::Identity() + 2.0 * G * D);
        // 2. Viscoelastic trial [Eq. 51].
        const Mat3 trial = eTrial + theta * trD * Mat3::Identity() + 2.0 * eta * Ddev;
        const double pTr = -trial.trace() / 3.0;
        const Mat3 s = trial + pTr * Mat3::Identity();
        const double tauTr = std::sqrt(0.5 * s.squaredNorm());
        double gammaDot = 0.0;
        if (pTr <= 0.0 || p.mass[i] / p.volume[i] <= rhoC_) { // 3. separation [Eq. 46–47]
            p.stress[i].setZero();
            sigmaE[i].setZero();
            state[i] = separatedState;
        } else if (tauTr <= muS_ * pTr) { // 4. below the static yield surface [Eq. 53]
            p.stress[i] = trial;
            sigmaE[i] = eTrial;
            state[i] = elasticState;
        } else { // 5. modified radial return [Eq. 55–60]
            const double alpha = alphaCoef * std::sqrt(pTr);
            const double S0 = muS_ * pTr, S2 = mu2_ * pTr;
            const double B = S2 + tauTr + alpha, H = S2 * tauTr + S0 * alpha;
            const double tau = 2.0 * H / (B + std::sqrt(std::max(B * B - 4.0 * H, 0.0)));
            gammaDot = (tauTr - tau) / (Gt * dt);
            p.stress[i] = (tau / tauTr) * s - pTr * Mat3::Identity();
            // 6. Elastic stress for the next step [Eq. 61]: Dᵖ = γ̇ᵖ N/√2, N = s/|s|.
            const Mat3 Dp = (0.5 * gammaDot / tauTr) * s;
            sigmaE[i] = p.stress[i] - theta * trD * Mat3::Identity() - 2.0 * eta * (Ddev - Dp);
            state[i] = flowingState;
        }
        rate[i] = gammaDot;
        p.plasticStrain[i] += gammaDot * dt;
        if (!std::isfinite(p.stress[i].sum() + sigmaE[i].sum() + gammaDot)) bad = std::min(bad, k);
    }
    return bad < n ? ids[bad] : -1;
}

template class ViscoelasticMuI<2>;
template class ViscoelasticMuI<3>;

MPM_REGISTER(MaterialRegistry<2>, ViscoelasticMuI<2>, "viscoelasticMuI");
MPM_REGISTER(MaterialRegistry<3>, ViscoelasticMuI<3>, "viscoelasticMuI");

} // namespace mpm
