// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/InitialVelocity.hpp"

#include "case/DictionaryVectors.hpp"
#include "case/Registry.hpp"
#include "core/Constants.hpp"

#include <cmath>
#include <vector>

namespace mpm {

namespace {

/// v = value everywhere.
template <int dim> class UniformVelocity : public InitialVelocity<dim> {
public:
    explicit UniformVelocity(const Vec<dim>& value) : value_(value) {}
    explicit UniformVelocity(const Dictionary& d) : value_(readVec<dim>(d, "value")) {}
    Vec<dim> at(const Vec<dim>& /*x*/) const override { return value_; }

private:
    Vec<dim> value_;
};

/// The n-th mode of a bar fixed at `origin`: v = A sin((2n − 1)π s / 2L) d, s = (x − origin)·d.
template <int dim> class AxialModeVelocity : public InitialVelocity<dim> {
public:
    explicit AxialModeVelocity(const Dictionary& d)
        : amplitude_(d.getScalar("amplitude")), direction_(readVec<dim>(d, "direction")),
          origin_(readVecOr<dim>(d, "origin", Vec<dim>::Zero())),
          length_(d.getScalar("length", Bounds::positive())),
          n_(d.getIntOr("mode", 1, Bounds::closed(1, 1000))) {
        if (direction_.norm() == 0) d.error("direction", "direction must not be zero");
        direction_.normalize();
    }
    Vec<dim> at(const Vec<dim>& x) const override {
        const double s = (x - origin_).dot(direction_);
        return amplitude_ * std::sin((2 * n_ - 1) * pi * s / (2.0 * length_)) * direction_;
    }

private:
    double amplitude_;
    Vec<dim> direction_, origin_;
    double length_;
    int n_;
};

/// The fundamental breathing mode of a ball (3D) or cylinder (2D) of radius a with a free,
/// incompressible-limit surface [002 Eq. 62]: v = A R(k r) r̂, r = |x − centre|; R = j₁
/// (spherical Bessel), k = π/a in 3D; R = J₁, k = j₀,₁/a (j₀,₁ = 2.40483, the first zero of J₀)
/// in 2D. A < 0 compresses.
template <int dim> class RadialModeVelocity : public InitialVelocity<dim> {
public:
    explicit RadialModeVelocity(const Dictionary& d)
        : amplitude_(d.getScalar("amplitude")), centre_(readVec<dim>(d, "centre")),
          radius_(d.getScalar("radius", Bounds::positive())) {}
    Vec<dim> at(const Vec<dim>& x) const override {
        const Vec<dim> r = x - centre_;
        const double rn = r.norm();
        if (rn == 0.0) return Vec<dim>::Zero();
        const double R = dim == 3 ? std::sph_bessel(1, pi * rn / radius_)
                                  : std::cyl_bessel_j(1.0, 2.404825557695773 * rn / radius_);
        return amplitude_ * R / rn * r;
    }

private:
    double amplitude_;
    Vec<dim> centre_;
    double radius_;
};

MPM_FAMILY_INFO("initialVelocity",
                {"<set>.velocity.type in constant/particles (or a vector: uniform)",
                 "7. constant/particles",
                 {{"type", "word", "-", "required", "the velocity field"}}});
MPM_FAMILY_DIMS(InitialVelocityRegistry, "initialVelocity");

MPM_REGISTER_DIMS(InitialVelocityRegistry, UniformVelocity, "uniform");
MPM_REGISTER_DIMS(InitialVelocityRegistry, AxialModeVelocity, "axialMode");
MPM_REGISTER_DIMS(InitialVelocityRegistry, RadialModeVelocity, "radialMode");
MPM_SCHEMA("initialVelocity", "uniform",
           {"the same velocity everywhere (as the vector form)",
            {{"value", "vector", "m/s", "required", "the velocity"}},
            "{type: uniform, value: [0, -2]}"});
MPM_SCHEMA("initialVelocity", "axialMode",
           {"the n-th mode of a bar fixed at origin: v = A sin((2n - 1) pi s / 2L) d",
            {{"amplitude", "scalar", "m/s", "required", "A"},
             {"direction", "vector", "-", "required", "d, the bar's axis (normalised; not zero)"},
             {"length", "scalar", "m", "required", "L, the bar's length (> 0)"},
             {"origin", "vector", "m", "0", "the fixed end; s = (x - origin) . d"},
             {"mode", "integer", "-", "1", "n in [1, 1000]"}},
            "{type: axialMode, amplitude: 0.01, direction: [1, 0], length: 1}"});
MPM_SCHEMA("initialVelocity", "radialMode",
           {"the breathing mode of a ball (3D) or cylinder (2D) [002 Eq. 62]: v = A R(k r) r/|r|",
            {{"amplitude", "scalar", "m/s", "required", "A (< 0 compresses)"},
             {"centre", "vector", "m", "required", "the centre"},
             {"radius", "scalar", "m", "required", "a, the radius (> 0)"}},
            "{type: radialMode, amplitude: -0.1, centre: [0.5, 0.5], radius: 0.2}"});

} // namespace

template <int dim>
std::unique_ptr<InitialVelocity<dim>> InitialVelocity<dim>::create(const Dictionary& set) {
    if (set.isDict("velocity"))
        return InitialVelocityRegistry<dim>::create(set.subDict("velocity"));
    return std::make_unique<UniformVelocity<dim>>(
        readVecOr<dim>(set, "velocity", Vec<dim>::Zero()));
}

template class InitialVelocity<2>;
template class InitialVelocity<3>;

} // namespace mpm
