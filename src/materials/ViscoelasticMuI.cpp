// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/ViscoelasticMuI.hpp"

#include "core/Constants.hpp"
#include "core/Parallel.hpp"
#include "materials/FlowRules.hpp"
#include "materials/HenckyBatch.hpp"
#include "materials/MaterialKeys.hpp"

#include <algorithm>
#include <cmath>

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

/// Rodrigues' coefficients of exp([w]×) = 1 + a [w]× + b [w]×², from t² = |w|²:
/// a = sin t / t, b = (1 − cos t)/t²; by their series below t = 0.1 (the next terms, t¹⁰/11! and
/// t¹⁰/12!, are under 3·10⁻¹⁸).
void rodrigues(double t2, double& a, double& b) {
    if (t2 < 1e-2) {
        a = 1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0)));
        b = 0.5 - t2 / 24.0 * (1.0 - t2 / 30.0 * (1.0 - t2 / 56.0 * (1.0 - t2 / 90.0)));
        return;
    }
    const double t = std::sqrt(t2);
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
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
    // Points go through in batches of Lanes in structure-of-arrays form, so that the update
    // vectorises across points (as HenckyBatch, whose lane-to-tensor helper stores the results);
    // the three outcomes are selected per lane.
    // Symmetric tensors are kept as their six entries (00 11 22 01 02 12).
    constexpr int Lanes = 8;
    const Index n = static_cast<Index>(ids.size());
    const Index batches = (n + Lanes - 1) / Lanes;
    const double lambda = c_.lambda, G = c_.G;
    const double theta = bulkViscosity_, eta = shearViscosity_;
    const double Gt = G + eta / dt; // G̃ [Eq. 55]
    const double alphaCoef = I0_ * Gt * dt / (grainDiameter_ * std::sqrt(grainDensity_)); // α/√p
    const double muS = muS_, mu2 = mu2_, rhoC = rhoC_;
    std::vector<Mat3>& sigmaE = p.tensor(elasticStress_);
    std::vector<double>& rate = p.scalar(strainRate_);
    std::vector<int>& state = p.flag(state_);
    Index bad = n;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static) reduction(min : bad)
    for (Index b = 0; b < batches; ++b) {
        Index idx[Lanes];
        alignas(64) double d[6][Lanes], w[3][Lanes], se[6][Lanes], rho[Lanes], ra[Lanes], rb[Lanes];
        for (int l = 0; l < Lanes; ++l) {
            const Index i = ids[std::min(b * Lanes + l, n - 1)];
            idx[l] = i;
            const Mat3 L = embed3<dim>(p.L[i]);
            // D = sym L, Δt W = [w]× with W = skw L.
            d[0][l] = L(0, 0), d[1][l] = L(1, 1), d[2][l] = L(2, 2);
            d[3][l] = 0.5 * (L(0, 1) + L(1, 0));
            d[4][l] = 0.5 * (L(0, 2) + L(2, 0));
            d[5][l] = 0.5 * (L(1, 2) + L(2, 1));
            w[0][l] = dt * (0.5 * (L(2, 1) - L(1, 2)));
            w[1][l] = dt * (0.5 * (L(0, 2) - L(2, 0)));
            w[2][l] = dt * (0.5 * (L(1, 0) - L(0, 1)));
            rodrigues(w[0][l] * w[0][l] + w[1][l] * w[1][l] + w[2][l] * w[2][l], ra[l], rb[l]);
            const Mat3& S = sigmaE[i];
            se[0][l] = S(0, 0), se[1][l] = S(1, 1), se[2][l] = S(2, 2);
            se[3][l] = S(0, 1), se[4][l] = S(0, 2), se[5][l] = S(1, 2);
            rho[l] = p.mass[i] / p.volume[i];
        }
        alignas(64) double sig[6][Lanes], sigE[6][Lanes], gdot[Lanes], st[Lanes];
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            // 1. Objective elastic trial [Eq. 52]: σᵉ rotated by Q = exp(Δt W) (Rodrigues,
            //    [w]×² = w wᵀ − |w|² 1), the increment ℂ : Δt D taken at the end of the step (not
            //    half-rotated): the return is implicit, and in fast flow the stress must align
            //    with the rate it returns to (docs/viscoelastic.md §5).
            const double wx = w[0][l], wy = w[1][l], wz = w[2][l];
            const double a = ra[l], bb = rb[l], t2 = wx * wx + wy * wy + wz * wz;
            const double Q[3][3] = {
                {1.0 + bb * (wx * wx - t2), -a * wz + bb * wx * wy, a * wy + bb * wx * wz},
                {a * wz + bb * wx * wy, 1.0 + bb * (wy * wy - t2), -a * wx + bb * wy * wz},
                {-a * wy + bb * wx * wz, a * wx + bb * wy * wz, 1.0 + bb * (wz * wz - t2)}};
            const double S[3][3] = {{se[0][l], se[3][l], se[4][l]},
                                    {se[3][l], se[1][l], se[5][l]},
                                    {se[4][l], se[5][l], se[2][l]}};
            double M[3][3]; // Q σᵉ
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    M[r][c] = Q[r][0] * S[0][c] + Q[r][1] * S[1][c] + Q[r][2] * S[2][c];
            auto rot = [&](int r, int c) { // (Q σᵉ Qᵀ)_rc
                return M[r][0] * Q[c][0] + M[r][1] * Q[c][1] + M[r][2] * Q[c][2];
            };
            const double trD = d[0][l] + d[1][l] + d[2][l];
            const double diagE = dt * lambda * trD, twoGdt = 2.0 * G * dt;
            double e[6] = {
                rot(0, 0) + diagE + twoGdt * d[0][l], rot(1, 1) + diagE + twoGdt * d[1][l],
                rot(2, 2) + diagE + twoGdt * d[2][l], rot(0, 1) + twoGdt * d[3][l],
                rot(0, 2) + twoGdt * d[4][l],         rot(1, 2) + twoGdt * d[5][l]};
            // 2. Viscoelastic trial [Eq. 51]: σ_tr = σᵉ_tr + ϑ tr D 1 + 2η D_dev.
            const double trThird = trD / 3.0;
            double dev[6]; // D_dev
            for (int k = 0; k < 6; ++k)
                dev[k] = d[k][l] - (k < 3 ? trThird : 0.0);
            double tr[6];
            for (int k = 0; k < 6; ++k)
                tr[k] = e[k] + (k < 3 ? theta * trD : 0.0) + 2.0 * eta * dev[k];
            const double pTr = -(tr[0] + tr[1] + tr[2]) / 3.0;
            double s[6]; // deviator of the trial
            for (int k = 0; k < 6; ++k)
                s[k] = tr[k] + (k < 3 ? pTr : 0.0);
            const double tauTr = std::sqrt(0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] +
                                                  2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
            // 3.–5. Separated [Eq. 46–47], below the static yield surface [Eq. 53], or the
            //        modified radial return [Eq. 55–60] (computed in every lane, selected).
            const bool separated = (pTr <= 0.0) | (rho[l] <= rhoC);
            const bool flowing = !separated & (tauTr > muS * pTr);
            const double alpha = alphaCoef * std::sqrt(pTr > 0.0 ? pTr : 0.0);
            const double S0 = muS * pTr, S2 = mu2 * pTr;
            const double B = S2 + tauTr + alpha, H = S2 * tauTr + S0 * alpha;
            const double disc = B * B - 4.0 * H;
            const double tau = 2.0 * H / (B + std::sqrt(disc > 0.0 ? disc : 0.0));
            const double gammaDot = flowing ? (tauTr - tau) / (Gt * dt) : 0.0;
            const double scale = tau / tauTr;
            // 6. Elastic stress for the next step [Eq. 61]: Dᵖ = γ̇ᵖ N/√2, N = s/|s|.
            const double dpScale = 0.5 * gammaDot / tauTr;
            for (int k = 0; k < 6; ++k) {
                const double sf = scale * s[k] - (k < 3 ? pTr : 0.0);
                const double ef =
                    sf - (k < 3 ? theta * trD : 0.0) - 2.0 * eta * (dev[k] - dpScale * s[k]);
                sig[k][l] = separated ? 0.0 : (flowing ? sf : tr[k]);
                sigE[k][l] = separated ? 0.0 : (flowing ? ef : e[k]);
            }
            gdot[l] = gammaDot;
            st[l] = separated ? 2.0 : (flowing ? 1.0 : 0.0);
        }
        for (int l = 0; l < Lanes; ++l) {
            if (b * Lanes + l >= n) break;
            const Index i = idx[l];
            p.stress[i] = HenckyBatch<Lanes>::tensor(sig, l);
            sigmaE[i] = HenckyBatch<Lanes>::tensor(sigE, l);
            state[i] = st[l] == 2.0 ? separatedState : (st[l] == 1.0 ? flowingState : elasticState);
            rate[i] = gdot[l];
            p.plasticStrain[i] += gdot[l] * dt;
            // Checked on the lanes, not re-read from the tensors just stored.
            double sum = gdot[l];
            for (int k = 0; k < 6; ++k)
                sum += sig[k][l] + sigE[k][l];
            if (!std::isfinite(sum)) bad = std::min(bad, b * Lanes + l);
        }
    }
    return bad < n ? ids[bad] : -1;
}

template class ViscoelasticMuI<2>;
template class ViscoelasticMuI<3>;

MPM_REGISTER_DIMS(MaterialRegistry, ViscoelasticMuI, "viscoelasticMuI");
MPM_SCHEMA("materials", "viscoelasticMuI",
           {"viscoelastic μ(I) of [002], damped through the grains' coefficient of restitution",
            elasticKeys() +
                KeyList{{"frictionAngle", "scalar", "deg", "required",
                         "φ_s: μ_s = tan φ_s, in (0, 90)"},
                        {"frictionAngle2", "scalar", "deg", "required",
                         "φ₂: μ₂ = tan φ₂, in (frictionAngle, 90)"},
                        {"I0", "scalar", "-", "0.278", "I₀ of μ(I) (> 0)"},
                        {"grainDiameter", "scalar", "m", "required", "grain size d (> 0)"},
                        {"grainDensity", "scalar", "kg/m³", "required",
                         "grain density ρ_s (> 0; φ₀ = density/ρ_s)"},
                        {"restitution", "scalar", "-", "none",
                         "e in (0, 1]: ϑ and η from [002 Eq. 40, 42]; not with bulkViscosity"},
                        {"bulkViscosity", "scalar", "Pa·s", "0",
                         "ϑ (≥ 0) directly (not with restitution)"},
                        {"shearViscosity", "scalar", "Pa·s", "(G/K) ϑ",
                         "η (≥ 0) directly (not with restitution)"},
                        {"criticalDensity", "scalar", "kg/m³", "density",
                         "ρ_c (≥ 0): a point with ρ ≤ ρ_c carries no stress"}},
            "{type: viscoelasticMuI, density: 1500, E: 1.0e6, nu: 0.3, frictionAngle: 20.9, "
            "frictionAngle2: 32.8, grainDiameter: 0.001, grainDensity: 2500, restitution: 0.5}"});

} // namespace mpm
