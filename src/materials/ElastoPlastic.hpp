// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/FlowRules.hpp"
#include "materials/HenckyLaw.hpp"
#include "materials/HypoelasticLaw.hpp"
#include "materials/Material.hpp"
#include "materials/Viscosity.hpp"
#include "transfers/PhaseDensity.hpp"

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

// Materials as a composition: elastic law × plastic flow × viscosity × options.
//
//  - Elastic law (a policy with static members): HypoelasticLaw (Jaumann rate, stress is the
//    state) or HenckyLaw (hyperelastic in bᵉ). Each owns its update kernels: the plain elastic
//    one for NoFlow, its return map for a flow functor.
//  - Plasticity (an object read from the dictionary): NoPlasticity, DruckerPragerPlasticity
//    (DruckerPrager.hpp), MuIPlasticity (MuI.hpp). It gives the per-step flow functor
//    (FlowRules.hpp), the tension cut-off and its K0. A new flow rule is a new Plasticity
//    class with the members of NoPlasticity and a flow functor with `beta`, `yield` and
//    `multiplier` that the laws' return maps accept, registered with MPM_REGISTER_PLASTICITY
//    like MuI.cpp (a missing member is a static_assert naming it).
//  - Viscosity (an object read from the dictionary, Viscosity.hpp): NoViscosity (the default:
//    every branch on it is `if constexpr`, so an inviscid material compiles to the per-point code
//    it had before the policy existed) or KelvinVoigtViscosity. A viscous composition carries σᵉ
//    beside σ, γ̇ᵖ and the flow state (ViscoelasticFields), runs the law's viscousUpdate (the
//    hypoelastic law only: ViscoelasticReturnMap.hpp), reads `criticalDensity` as the separation
//    density of that return map instead of the trans-phase keys, and takes its volume from the
//    rate. `viscoelasticMuI` = HypoelasticLaw × TanMuIPlasticity × KelvinVoigtViscosity
//    (ViscoelasticMuI.cpp, MPM_REGISTER_COMPOSITION).
//  - Options: the trans-phase relation [000 Eq. 10] (transPhase, criticalDensity) of plastic
//    materials, passed to the kernels as ρ_c (0: off).
// ElastoPlastic<dim, Law, Plasticity, Viscosity> is instantiated per combination; the `type:`
// factory (createElastoPlastic) picks one from `elasticity:` once at set-up, so the per-particle
// loops have neither virtual calls nor option branches.

namespace mpm {

/// No plastic flow (the elastic types linearElastic and henckyElastic). Reads no keys.
struct NoPlasticity {
    static constexpr bool plastic = false;

    NoPlasticity(const Dictionary& /*dict*/, const ElasticConstants& /*c*/, ElasticLaw /*law*/,
                 int /*dim*/) {}
    std::string describe() const { return {}; }
    NoFlow flow(double /*dt*/) const { return {}; }
    TensionCutoff cutoff() const { return {}; }
    /// ν/(1 − ν), the elastic coefficient of lateral earth pressure at rest.
    double defaultK0(const ElasticConstants& c) const { return c.nu / (1.0 - c.nu); }
};

/// `Trait<T>` is true when `expr` (an expression of T) is valid: the detection idiom, so that a
/// Plasticity or Law that lacks a member fails a static_assert that names it.
#define MPM_DETECT(Trait, expr)                                                                    \
    template <class T, class = void> struct Trait : std::false_type {};                            \
    template <class T> struct Trait<T, std::void_t<decltype(expr)>> : std::true_type {}

namespace detect {
MPM_DETECT(Plastic, bool{T::plastic});
MPM_DETECT(Describe, std::string(std::declval<const T&>().describe()));
MPM_DETECT(Flow, std::declval<const T&>().flow(0.0));
MPM_DETECT(Cutoff, TensionCutoff(std::declval<const T&>().cutoff()));
MPM_DETECT(PlasticK0,
           double(std::declval<const T&>().defaultK0(std::declval<const ElasticConstants&>())));
MPM_DETECT(Kind, ElasticLaw{T::kind});
MPM_DETECT(BatchedEnergy, bool{T::batchedEnergy});
MPM_DETECT(Initialise,
           T::initialise(std::declval<const ElasticConstants&>(), std::declval<Particles<2>&>(),
                         Index{}, std::declval<const Mat3&>()));
MPM_DETECT(Viscous, bool{T::viscous});
MPM_DETECT(PWaveViscosity, double(std::declval<const T&>().pWaveViscosity()));
MPM_DETECT(StrainEnergy, double(T::strainEnergy(std::declval<const ElasticConstants&>(),
                                                std::declval<const Particles<2>&>(), Index{})));
} // namespace detect

/// A material of elastic law `Law`, plasticity `Plasticity` and viscosity `Viscosity` (see
/// above).
/// Keys: density, E, nu, the plasticity's and the viscosity's keys and, for inviscid plastic
/// materials, transPhase (default true), criticalDensity ρ_c [kg/m³] (default: density, the
/// initial density [000 §3.1]) and gasVolume (neighbourhood | point, default neighbourhood with
/// the trans-phase relation: TransPhaseRule::relaxGasVolumes); for viscous ones criticalDensity
/// ρ_c [kg/m³] (default: density), the separation density of the viscous return map
/// [002 Eq. 46–47].
template <int dim, class Law, class Plasticity, class Viscosity = NoViscosity>
class ElastoPlastic : public Material<dim> {
    static_assert(detect::Plastic<Plasticity>::value,
                  "a Plasticity needs `static constexpr bool plastic` (see NoPlasticity)");
    static_assert(std::is_constructible_v<Plasticity, const Dictionary&, const ElasticConstants&,
                                          ElasticLaw, int>,
                  "a Plasticity needs a constructor (const Dictionary&, const ElasticConstants&, "
                  "ElasticLaw, int dim)");
    static_assert(detect::Describe<Plasticity>::value,
                  "a Plasticity needs `std::string describe() const`");
    static_assert(detect::Flow<Plasticity>::value,
                  "a Plasticity needs `flow(double dt) const` returning its flow functor");
    static_assert(detect::Cutoff<Plasticity>::value,
                  "a Plasticity needs `TensionCutoff cutoff() const`");
    static_assert(detect::PlasticK0<Plasticity>::value,
                  "a Plasticity needs `double defaultK0(const ElasticConstants&) const`");
    static_assert(detect::Kind<Law>::value, "a Law needs `static constexpr ElasticLaw kind`");
    static_assert(detect::BatchedEnergy<Law>::value,
                  "a Law needs `static constexpr bool batchedEnergy`");
    static_assert(detect::Initialise<Law>::value,
                  "a Law needs `static void initialise(const ElasticConstants&, Particles<dim>&, "
                  "Index, const Mat3& sigma0)`");
    static_assert(detect::StrainEnergy<Law>::value,
                  "a Law needs `static double strainEnergy(const ElasticConstants&, const "
                  "Particles<dim>&, Index)`");
    static_assert(detect::Viscous<Viscosity>::value,
                  "a Viscosity needs `static constexpr bool viscous` (see NoViscosity)");
    static_assert(
        std::is_constructible_v<Viscosity, const Dictionary&, const ElasticConstants&, double>,
        "a Viscosity needs a constructor (const Dictionary&, const ElasticConstants&, double "
        "density)");
    static_assert(detect::Describe<Viscosity>::value,
                  "a Viscosity needs `std::string describe() const`");
    static_assert(detect::PWaveViscosity<Viscosity>::value,
                  "a Viscosity needs `double pWaveViscosity() const`");
    static_assert(!Viscosity::viscous || Law::kind == ElasticLaw::hypoelastic,
                  "a viscous material needs the hypoelastic law (its viscousUpdate, "
                  "ViscoelasticReturnMap.hpp)");

public:
    ElastoPlastic(const Dictionary& dict, const std::string& name)
        : Material<dim>(dict, name), c_(dict), plasticity_(dict, c_, Law::kind, dim),
          viscosity_(dict, c_, this->density()) {
        if constexpr (Viscosity::viscous) {
            rhoC_ = dict.getScalarOr("criticalDensity", this->density(), Bounds::nonNegative());
        } else if constexpr (Plasticity::plastic) {
            const bool transPhase = dict.getBoolOr("transPhase", true);
            const double rhoC =
                dict.getScalarOr("criticalDensity", this->density(), Bounds::nonNegative());
            rhoC_ = transPhase ? rhoC : 0.0;
            gasVolumeFromNeighbourhood_ =
                dict.getWordOr("gasVolume", rhoC_ > 0.0 ? "neighbourhood" : "point",
                               {"point", "neighbourhood"}) == "neighbourhood";
            if (gasVolumeFromNeighbourhood_ && rhoC_ <= 0.0)
                dict.error("gasVolume",
                           "gasVolume: neighbourhood acts on gasified points and needs "
                           "the trans-phase relation (transPhase: true, "
                           "criticalDensity > 0)");
        }
    }

    /// √(M/ρ₀) [m/s], M = K + 4G/3.
    double waveSpeed() const override { return std::sqrt(c_.M / this->density()); }
    /// ϑ + 4η/3 [Pa·s] of the viscosity (0: inviscid), for the time-step limit [002 Eq. 79–80].
    double pWaveViscosity() const override { return viscosity_.pWaveViscosity(); }
    /// Viscous: σᵉ (`elasticStress`, restarted), γ̇ᵖ (`plasticStrainRate`) and the
    /// ViscoelasticState (`flowState`). Inviscid, with the trans-phase relation: the shared fields
    /// `phaseDensity` and `gasified` (transfers/PhaseDensity.hpp).
    void declareState(Particles<dim>& p) override {
        if constexpr (Viscosity::viscous) {
            fields_.elasticStress = p.addTensor(FieldInfo{"elasticStress"});
            fields_.strainRate = p.addScalar(FieldInfo{"plasticStrainRate", false, true});
            fields_.state = p.addFlag(FieldInfo{"flowState", false, true});
        } else if (rhoC_ > 0.0) {
            transPhaseFields(p);
        }
    }
    void initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const override {
        Law::initialise(c_, p, i, sigma0);
        if constexpr (Viscosity::viscous) {
            p.tensor(fields_.elasticStress)[i] = sigma0; // at rest: no viscous stress
            p.scalar(fields_.strainRate)[i] = 0.0;
            p.flag(fields_.state)[i] = elasticState;
        } else if (const auto f = findTransPhaseFields(p); f && rhoC_ > 0.0) {
            p.scalar(f->density)[i] = p.mass[i] / p.volume[i]; // a seeded point is dense
        }
    }
    Index updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const override {
        if constexpr (Viscosity::viscous) {
            return Law::viscousUpdate(p, ids, dt, c_, plasticity_.flow(dt), viscosity_, rhoC_,
                                      fields_);
        } else {
            TransPhaseRule phase{rhoC_, nullptr, p.mass.data(), p.volume.data(), nullptr};
            if (const auto f = findTransPhaseFields(p); f && rhoC_ > 0.0) {
                phase.density = p.scalar(f->density).data();
                phase.gasified = p.flag(f->gasified).data();
            }
            const Index bad =
                Law::update(p, ids, dt, c_, phase, plasticity_.flow(dt), plasticity_.cutoff());
            if (gasVolumeFromNeighbourhood_) phase.relaxGasVolumes(p, ids, nearBodyFlag(p));
            return bad;
        }
    }
    double defaultK0() const override { return plasticity_.defaultK0(c_); }
    /// The law's stored energy [J]; viscous: the complementary energy of σᵉ.
    double strainEnergy(const Particles<dim>& p, Index i) const override {
        if constexpr (Viscosity::viscous)
            return Law::complementaryEnergy(c_, p.tensor(fields_.elasticStress)[i], p.volume[i]);
        else
            return Law::strainEnergy(c_, p, i);
    }
    void strainEnergies(const Particles<dim>& p, const std::vector<Index>& ids,
                        std::vector<double>& out) const override {
        if constexpr (Law::batchedEnergy)
            Law::template strainEnergies<dim>(c_, p, ids, out);
        else
            Material<dim>::strainEnergies(p, ids, out);
    }
    std::string describe() const override {
        std::ostringstream os;
        os << Material<dim>::describe() << "    "
           << (Law::kind == ElasticLaw::hencky ? "Hencky" : "hypoelastic (Jaumann)")
           << " elasticity: K = " << c_.K << " Pa, G = " << c_.G << " Pa\n"
           << plasticity_.describe() << viscosity_.describe();
        if constexpr (Viscosity::viscous) {
            os << "    separation (no stress): p_tr <= 0 or density <= " << rhoC_ << " kg/m3\n";
        } else if constexpr (Plasticity::plastic) {
            os << "    K0 of a geostatic initial stress (1 - sin phi) = " << defaultK0() << '\n';
            if (rhoC_ > 0.0)
                os << "    trans-phase: critical density " << rhoC_ << " kg/m3, gasified volume "
                   << (gasVolumeFromNeighbourhood_
                           ? "from the neighbourhood's density (not within " +
                                 std::to_string(static_cast<int>(nearBodyCells)) +
                                 " cells of a body)"
                           : std::string("kept by each point"))
                   << '\n';
            else
                os << "    trans-phase: off\n";
        }
        return os.str();
    }
    /// The trans-phase ρ_c [kg/m³]; 0 for elastic materials and with transPhase: false.
    /// Viscous: 0, so that the coupling sends every point's contact force through the grid
    /// [000 Eq. 19–20]. Separation (ρ ≤ ρ_c or p_tr ≤ 0) is a state of the viscous stress,
    /// reached and left every few steps by points at a wall or a body, not a gas with its own
    /// contact rule; under pure FLIP a force added to a separated point's own velocity is never
    /// taken back (the silo floor rang up to 48 m/s).
    double criticalDensity() const override { return Viscosity::viscous ? 0.0 : rhoC_; }
    /// Viscous: the rate form never reads F, V ← V exp(Δt tr L) [002 Eq. 76].
    bool volumeFromRate() const override { return Viscosity::viscous; }
    /// ρ_c of the viscous return map's separation rule [002 Eq. 46–47] [kg/m³].
    /// (Viscous materials only.)
    double separationDensity() const { return rhoC_; }

    const ElasticConstants& elasticConstants() const { return c_; }
    const Plasticity& plasticity() const { return plasticity_; }
    const Viscosity& viscosity() const { return viscosity_; }
    static constexpr ElasticLaw elasticLaw() { return Law::kind; }

private:
    ElasticConstants c_;
    Plasticity plasticity_;
    /// ρ_c [kg/m³] in use: trans-phase (0: off), or the separation density when viscous
    double rhoC_ = 0.0;
    bool gasVolumeFromNeighbourhood_ = false; ///< `gasVolume: neighbourhood`
    // Last, so that an inviscid material's members keep their offsets (its code is unchanged).
    Viscosity viscosity_;
    ViscoelasticFields fields_; ///< state handles of a viscous material
};

/// The factory of a plastic `type:`: reads `elasticity: hencky | hypoelastic` (default
/// hencky) and builds ElastoPlastic with that law and `Plasticity`.
template <int dim, class Plasticity>
std::unique_ptr<Material<dim>> createElastoPlastic(const Dictionary& dict,
                                                   const std::string& name) {
    const std::string law = dict.getWordOr("elasticity", "hencky", {"hencky", "hypoelastic"});
    if (law == "hypoelastic")
        return std::make_unique<ElastoPlastic<dim, HypoelasticLaw, Plasticity>>(dict, name);
    return std::make_unique<ElastoPlastic<dim, HenckyLaw, Plasticity>>(dict, name);
}

/// Register the plastic material `name` of `Plasticity` (createElastoPlastic, in 2D and 3D) and
/// instantiate its four ElastoPlastic classes: the one line of a flow rule's .cpp, in namespace
/// mpm. MPM_REGISTER_PLASTICITY(MuIPlasticity, "muI").
#define MPM_REGISTER_PLASTICITY(Plasticity, name)                                                  \
    template class ElastoPlastic<2, HenckyLaw, Plasticity>;                                        \
    template class ElastoPlastic<3, HenckyLaw, Plasticity>;                                        \
    template class ElastoPlastic<2, HypoelasticLaw, Plasticity>;                                   \
    template class ElastoPlastic<3, HypoelasticLaw, Plasticity>;                                   \
    static const MaterialRegistry<2>::Add MPM_CONCAT(mpmRegistrar, __COUNTER__)(                   \
        name, createElastoPlastic<2, Plasticity>);                                                 \
    static const MaterialRegistry<3>::Add MPM_CONCAT(mpmRegistrar, __COUNTER__)(                   \
        name, createElastoPlastic<3, Plasticity>)

/// The factory of a composition of fixed law (a `type:` that reads no `elasticity:`).
template <int dim, class Law, class Plasticity, class Viscosity>
std::unique_ptr<Material<dim>> createComposition(const Dictionary& dict, const std::string& name) {
    return std::make_unique<ElastoPlastic<dim, Law, Plasticity, Viscosity>>(dict, name);
}

/// Register the material `name` = Law × Plasticity × Viscosity in 2D and 3D and instantiate its
/// two classes: one line in namespace mpm,
/// MPM_REGISTER_COMPOSITION(HypoelasticLaw, TanMuIPlasticity, KelvinVoigtViscosity,
/// "viscoelasticMuI").
#define MPM_REGISTER_COMPOSITION(Law, Plasticity, Viscosity, name)                                 \
    template class ElastoPlastic<2, Law, Plasticity, Viscosity>;                                   \
    template class ElastoPlastic<3, Law, Plasticity, Viscosity>;                                   \
    static const MaterialRegistry<2>::Add MPM_CONCAT(mpmRegistrar, __COUNTER__)(                   \
        name, createComposition<2, Law, Plasticity, Viscosity>);                                   \
    static const MaterialRegistry<3>::Add MPM_CONCAT(mpmRegistrar, __COUNTER__)(                   \
        name, createComposition<3, Law, Plasticity, Viscosity>)

} // namespace mpm
