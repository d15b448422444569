// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/Material.hpp"

namespace mpm {

/// Hypoelastic linear elasticity with the Jaumann rate [001 Eq. 25, 36]:
///   σ̇ = C : D + W σ - σ W,  C_ijkl = K δ_ij δ_kl + G (δ_ik δ_jl + δ_il δ_jk - ⅔ δ_ij δ_kl),
/// with D = sym L and W = skew L; integrated by forward Euler over the step.
/// Keys: density, E, nu.
template <int dim> class LinearElastic : public Material<dim> {
public:
    LinearElastic(const Dictionary& dict, const std::string& name);

    double waveSpeed() const override;
    void initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const override;
    Index updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const override;
    double defaultK0() const override { return c_.nu / (1.0 - c_.nu); }
    /// Complementary energy ½ σ : C⁻¹ : σ · V = (p²/(2K) + s:s/(4G)) V.
    double strainEnergy(const Particles<dim>& p, Index i) const override;

private:
    ElasticConstants c_;
};

} // namespace mpm
