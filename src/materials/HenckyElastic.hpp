// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/Material.hpp"

namespace mpm {

/// Hencky hyperelasticity in the elastic left Cauchy–Green tensor bᵉ [000 Eq. 4–5]:
///   ψ = ½ λ (ln Jᵉ)² + G tr(εᵉ²),  εᵉ = ½ ln bᵉ,  τ = 2bᵉ ∂ψ/∂bᵉ = λ tr(εᵉ) 1 + 2G εᵉ,  σ = τ/J.
/// bᵉ is advanced by the incremental deformation f = 1 + Δt L: bᵉ ← f bᵉ fᵀ.
/// Keys: density, E, nu.
template <int dim> class HenckyElastic : public Material<dim> {
public:
    HenckyElastic(const Dictionary& dict, const std::string& name);

    double waveSpeed() const override;
    void initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const override;
    Index updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const override;
    double defaultK0() const override { return c_.nu / (1.0 - c_.nu); }
    double strainEnergy(const Particles<dim>& p, Index i) const override;

    /// Kirchhoff stress τ(bᵉ) [Pa].
    static Mat3 kirchhoff(const ElasticConstants& c, const Mat3& be);
    /// Energy density ψ(bᵉ) per unit reference volume [J/m³] [000 Eq. 5].
    static double energyDensity(const ElasticConstants& c, const Mat3& be);
    /// bᵉ = exp(2ε) with ε = C⁻¹:τ, the elastic strain of a prescribed Kirchhoff stress.
    static Mat3 leftCauchyGreenFromStress(const ElasticConstants& c, const Mat3& tau);

private:
    ElasticConstants c_;
};

} // namespace mpm
