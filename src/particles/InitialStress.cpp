// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/InitialStress.hpp"

#include "case/Registry.hpp"
#include "case/Selection.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mpm {

namespace {

/// σ₀ = 0.
template <int dim> class NoInitialStress : public InitialStress<dim> {
public:
    NoInitialStress(const Dictionary& /*d*/, double /*K0*/, const Vec<dim>& /*gravity*/) {}
};

/// Geostatic: σ_v = −ρ |g| max(0, z_s − z) along up = −g/|g|, σ_h = K0 σ_v; the surface z_s is
/// given or the highest point plus half a spacing. The points start from the prestress' elastic
/// stretch, so the bed is compressed from its stress-free density as after a gravity preload.
template <int dim> class GeostaticStress : public InitialStress<dim> {
public:
    GeostaticStress(const Dictionary& d, double K0, const Vec<dim>& gravity)
        : K0_(d.getScalarOr("K0", K0, Bounds::nonNegative())), surfaceGiven_(d.has("surface")),
          surface_(surfaceGiven_ ? d.getScalar("surface") : 0.0), gNorm_(gravity.norm()),
          up_(gNorm_ > 0 ? Vec<dim>(-gravity / gNorm_) : Vec<dim>::Zero()) {}
    bool needsGravity() const override { return true; }
    void place(const std::vector<Vec<dim>>& xs, double spacing) override {
        if (surfaceGiven_) return;
        surface_ = -1e300;
        for (const auto& x : xs)
            surface_ = std::max(surface_, up_.dot(x));
        surface_ += 0.5 * spacing;
    }
    Mat3 at(const Vec<dim>& x, double rho) const override {
        const double sv = -rho * gNorm_ * std::max(0.0, surface_ - up_.dot(x));
        Vec3 u = Vec3::Zero();
        u.template head<dim>() = up_;
        return K0_ * sv * Mat3::Identity() + (1.0 - K0_) * sv * u * u.transpose();
    }
    bool prestretches() const override { return true; }

private:
    double K0_;
    bool surfaceGiven_;
    double surface_;
    double gNorm_;
    Vec<dim> up_;
};

/// σ₀ = 0, and the solver runs a damped settling under gravity before the run [000 §4.2].
template <int dim> class GravityPreloadStress : public InitialStress<dim> {
public:
    GravityPreloadStress(const Dictionary& d, double /*K0*/, const Vec<dim>& /*gravity*/) {
        settings_.requested = true;
        settings_.damping = d.getScalarOr("damping", 0.5, Bounds::halfOpen(0.0, 1.0));
        settings_.tolerance = d.getScalarOr("tolerance", 1e-4, {0.0, 1.0, false, false});
        settings_.maxSteps = d.getIntOr("maxSteps", 20000, Bounds::closed(1, 1e9));
    }
    bool needsGravity() const override { return true; }
    PreloadSettings preload() const override { return settings_; }

private:
    PreloadSettings settings_;
};

MPM_FAMILY_INFO("initialStress",
                {"<set>.initialStress (a word, or .type of a map) in constant/particles",
                 "7. constant/particles",
                 {{"type", "word", "-", "none", "the initial stress"}}});
MPM_FAMILY_DIMS(InitialStressRegistry, "initialStress");

MPM_REGISTER_DIMS(InitialStressRegistry, NoInitialStress, "none");
MPM_REGISTER_DIMS(InitialStressRegistry, GeostaticStress, "geostatic");
MPM_REGISTER_DIMS(InitialStressRegistry, GravityPreloadStress, "gravityPreload");
MPM_SCHEMA("initialStress", "none", {"zero stress", {}, "{type: none}"});
MPM_SCHEMA("initialStress", "geostatic",
           {"sigma_v = -rho |g| (z_s - z), sigma_h = K0 sigma_v; F = (b^e)^(1/2) of the prestress",
            {{"K0", "scalar", "-", "the material's (1 - sin phi, nu/(1 - nu))",
              "coefficient of earth pressure at rest (>= 0)"},
             {"surface", "scalar", "m", "the highest point + half a spacing",
              "z_s, the free surface along -g"}},
            "{type: geostatic, K0: 0.5}"});
MPM_SCHEMA("initialStress", "gravityPreload",
           {"settle under gravity with local damping before the run [000 §4.2]",
            {{"damping", "scalar", "-", "0.5", "local damping alpha in [0, 1) during the preload"},
             {"tolerance", "scalar", "-", "1e-4",
              "stop when the kinetic energy stays <= tolerance x its peak, in (0, 1)"},
             {"maxSteps", "integer", "-", "20000", "at most this many steps, [1, 1e9]"}},
            "{type: gravityPreload, damping: 0.5}"});

} // namespace

template <int dim>
std::unique_ptr<InitialStress<dim>> InitialStress<dim>::create(const Dictionary& set, double K0,
                                                               const Vec<dim>& gravity) {
    const Dictionary d =
        set.isDict("initialStress")
            ? set.subDict("initialStress")
            : Dictionary::fromString(
                  "type: " + set.getWordOr("initialStress", "none",
                                           registeredWords<InitialStressRegistry<dim>>()),
                  "constant/particles");
    auto stress = InitialStressRegistry<dim>::create(d, K0, gravity);
    if (stress->needsGravity() && gravity.norm() == 0)
        set.error("initialStress",
                  "the initial stress '" + d.getString("type") + "' needs gravity (constant/g)");
    return stress;
}

template class InitialStress<2>;
template class InitialStress<3>;

} // namespace mpm
