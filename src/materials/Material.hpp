// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "core/Parallel.hpp"
#include "core/Types.hpp"
#include "particles/Particles.hpp"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// Elastic constants from E and ν, checked on input (E > 0, -1 < ν < 0.5).
struct ElasticConstants {
    double E = 0, nu = 0;
    double lambda = 0; ///< Lamé's first parameter [Pa]
    double G = 0;      ///< shear modulus [Pa]
    double K = 0;      ///< bulk modulus [Pa]
    double M = 0;      ///< constrained (P-wave) modulus K + 4G/3 [Pa]

    explicit ElasticConstants(const Dictionary& dict);
    ElasticConstants(double youngs, double poisson);
};

/// The elastic law of a material (ElastoPlastic.hpp): hypoelastic Jaumann-rate linear elasticity
/// [001 Eq. 25, 36] or Hencky hyperelasticity in bᵉ [000 Eq. 4–5].
enum class ElasticLaw { hypoelastic, hencky };

/// A constitutive model. One object serves all particles of one named material; the solver
/// calls it once per step with their indices (no per-particle virtual call, docs/architecture.md).
template <int dim> class Material {
public:
    Material(const Dictionary& dict, std::string name);
    virtual ~Material() = default;

    const std::string& name() const { return name_; }
    /// Density at seeding ρ₀ [kg/m³].
    double density() const { return density_; }
    /// Largest elastic wave speed at density ρ₀, √(M/ρ₀) [m/s], for the CFL limit.
    virtual double waveSpeed() const = 0;
    /// Viscosity a P wave feels, ϑ + 4η/3 [Pa·s] (0: inviscid, the default).
    virtual double pWaveViscosity() const { return 0.0; }
    /// Factor by which viscosity shortens the explicit step on a grid of spacing h [m]
    /// [002 Eq. 79–80]: Δt_cr = h/c (√(ϑ̂² + 1) − ϑ̂), ϑ̂ = ϑ_P/(h √(M ρ₀)), with
    /// ϑ_P = pWaveViscosity() and √(M ρ₀) = ρ₀ c. 1 when inviscid (the CFL limit h/c); h ρ₀ c/(2
    /// ϑ_P) when the viscosity dominates (Δt_cr → h² ρ₀/(2 ϑ_P)).
    double viscousStepFactor(double h) const {
        const double thetaHat = pWaveViscosity() / (h * density() * waveSpeed());
        return 1.0 / (std::sqrt(thetaHat * thetaHat + 1.0) + thetaHat); // no cancellation
    }

    /// Declare the per-particle state this model keeps beyond the common fields (Particles::
    /// addScalar, addTensor, addFlag), keeping the handles; called once before seeding or restart.
    virtual void declareState(Particles<dim>& /*p*/) {}

    /// Set the state of freshly seeded particles with Cauchy stress σ₀ (zero for none).
    virtual void initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const = 0;

    /// Advance the stress of `ids` over dt from the velocity gradient p.L (F and V are already
    /// updated by the solver). Returns the first particle whose stress is not finite, or -1.
    virtual Index updateStress(Particles<dim>& p, const std::vector<Index>& ids,
                               double dt) const = 0;

    /// Coefficient of lateral earth pressure at rest used when a geostatic initial stress gives
    /// no K0: ν/(1 - ν) for elastic models.
    virtual double defaultK0() const = 0;

    /// Stored elastic energy of particle i [J] (per metre of depth in 2D).
    virtual double strainEnergy(const Particles<dim>& p, Index i) const = 0;

    /// strainEnergy of the particles `ids` into out[i] (out has an entry per particle): one
    /// call per material, the particles in parallel. Models whose energy needs an
    /// eigen-decomposition override it with a batched one.
    virtual void strainEnergies(const Particles<dim>& p, const std::vector<Index>& ids,
                                std::vector<double>& out) const {
        const Index n = static_cast<Index>(ids.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
        for (Index k = 0; k < n; ++k)
            out[ids[k]] = strainEnergy(p, ids[k]);
    }

    /// The stress is a rate form that never reads F: the volume then follows
    /// V ← V exp(Δt tr L) [002 Eq. 76], positive even in a step whose 1 + Δt L inverts (a point
    /// of a granular gas), and F is only written. False (the default): V = det F V⁰, and
    /// det F ≤ 0 stops the run.
    virtual bool volumeFromRate() const {
        return false;
    }

    /// Trans-phase critical density ρ_c [kg/m³] [000 Eq. 10, 18–19]: a point whose current
    /// density ρ_p = m_p/V_p is below ρ_c is gasified (grains out of contact, bulk modulus 0):
    /// it carries no stress and takes no coupling contact force. 0 (the default): never.
    virtual double criticalDensity() const {
        return 0.0;
    }

    /// The constants this model derives from its keys, for the log at start: indented lines
    /// (the base: ρ₀ and the wave speed).
    virtual std::string describe() const;

    /// Build the material named `name` from its dictionary (`type:` picks the model).
    static std::unique_ptr<Material> create(const Dictionary& dict, const std::string& name);
    /// Every material of constant/materials, in file order (none is an InputError).
    static std::vector<std::unique_ptr<Material>> createAll(const Dictionary& materials);

private:
    std::string name_;
    double density_;
};

template <int dim> using MaterialRegistry = Registry<Material<dim>, const std::string&>;

/// Embed a dim×dim tensor in 3×3 (plane strain: zero third row and column).
template <int dim> inline Mat3 embed3(const Mat<dim>& a) {
    Mat3 r = Mat3::Zero();
    r.template topLeftCorner<dim, dim>() = a;
    return r;
}

} // namespace mpm
