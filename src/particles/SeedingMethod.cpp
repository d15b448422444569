// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/SeedingMethod.hpp"

#include "case/Selection.hpp"
#include "particles/Seeding.hpp"

#include <cmath>
#include <cstdint>

namespace mpm {

namespace {

/// Quadrature samples per Poisson-disk spacing along an axis for `volumes: voronoi`: about 900
/// samples a point in 3D, 400 in 2D (Voronoi volumes to ~1 % rms; SeedingTest).
template <int dim> constexpr int VoronoiSamplesPerSpacing = dim == 3 ? 8 : 16;

/// n^dim points per cell at its sub-cell centres, V_p = (h/n)^dim.
template <int dim> class RegularSeeding : public SeedingMethod<dim> {
public:
    explicit RegularSeeding(const Dictionary& d)
        : perDirection_(d.getIntOr("perDirection", 2, Bounds::closed(1, 8))) {
        if (d.has("volumes"))
            d.error("volumes", "only poissonDisk seeding takes `volumes`: a regular lattice gives "
                               "every point its sub-cell (h/n)^dim");
    }
    std::vector<Vec<dim>> positions(const Region<dim>& region, const Vec<dim>& origin,
                                    double h) const override {
        return seedRegular<dim>(region, origin, h, perDirection_);
    }
    double nominalVolume(const Region<dim>& /*region*/, double h,
                         std::size_t /*n*/) const override {
        return std::pow(h / perDirection_, dim);
    }

private:
    int perDirection_;
};

/// Bridson's Poisson-disk points at least f h / perCell^(1/dim) apart, V_p = region volume / N
/// or the point's Voronoi cell [002 §4.5].
template <int dim> class PoissonDiskSeeding : public SeedingMethod<dim> {
public:
    explicit PoissonDiskSeeding(const Dictionary& d)
        : perCell_(d.getIntOr("perCell", dim == 2 ? 4 : 8, Bounds::closed(1, 512))),
          seed_(d.getIntOr("seed", 0, Bounds::nonNegative())),
          voronoi_(d.getWordOr("volumes", "equal", {"equal", "voronoi"}) == "voronoi") {}
    std::vector<Vec<dim>> positions(const Region<dim>& region, const Vec<dim>& /*origin*/,
                                    double h) const override {
        return seedPoissonDisk<dim>(region, poissonDiskSpacing(h, perCell_, dim),
                                    static_cast<std::uint64_t>(seed_));
    }
    double nominalVolume(const Region<dim>& region, double /*h*/, std::size_t n) const override {
        return n == 0 ? 0.0 : region.volume() / static_cast<double>(n);
    }
    std::vector<double> volumes(const Region<dim>& region, const std::vector<Vec<dim>>& xs,
                                double nominal, double h,
                                const std::function<bool(const Vec<dim>&)>& inBody) const override {
        if (!voronoi_) return SeedingMethod<dim>::volumes(region, xs, nominal, h, inBody);
        return voronoiVolumes<dim>(region, xs, poissonDiskSpacing(h, perCell_, dim),
                                   VoronoiSamplesPerSpacing<dim>, inBody);
    }

private:
    int perCell_;
    long seed_;
    bool voronoi_;
};

MPM_FAMILY_INFO("seedingMethods",
                {"<set>.seeding.method in constant/particles",
                 "7. constant/particles",
                 {{"method", "word", "-", "regular", "how the region is filled"}}});
MPM_FAMILY_DIMS(SeedingMethodRegistry, "seedingMethods");

MPM_REGISTER_DIMS(SeedingMethodRegistry, RegularSeeding, "regular");
MPM_REGISTER_DIMS(SeedingMethodRegistry, PoissonDiskSeeding, "poissonDisk");
MPM_SCHEMA("seedingMethods", "regular",
           {"n points per cell and direction at the sub-cell centres, V_p = (h/n)^dim",
            {{"perDirection", "integer", "-", "2", "n in [1, 8]"}},
            "{method: regular, perDirection: 2}"});
MPM_SCHEMA("seedingMethods", "poissonDisk",
           {"Bridson's Poisson-disk points, deterministic for a seed",
            {{"perCell", "integer", "-", "4 (2D), 8 (3D)", "target points per cell, [1, 512]"},
             {"seed", "integer", "-", "0", "random seed (>= 0)"},
             {"volumes", "word", "-", "equal",
              "equal (region volume / N) or voronoi (each point's Voronoi cell) [002 §4.5]"}},
            "{method: poissonDisk, perCell: 6, seed: 1}"});

} // namespace

template <int dim>
std::vector<double>
SeedingMethod<dim>::volumes(const Region<dim>& /*region*/, const std::vector<Vec<dim>>& xs,
                            double nominal, double /*h*/,
                            const std::function<bool(const Vec<dim>&)>& /*inBody*/) const {
    return std::vector<double>(xs.size(), nominal);
}

template <int dim>
std::unique_ptr<SeedingMethod<dim>> SeedingMethod<dim>::create(const Dictionary& set) {
    const Dictionary sd = set.has("seeding") ? set.subDict("seeding")
                                             : Dictionary::fromString("{}", "constant/particles");
    auto method = selectByWord<SeedingMethodRegistry<dim>>(sd, "method", "regular");
    sd.checkUnknownKeys();
    return method;
}

template class SeedingMethod<2>;
template class SeedingMethod<3>;

} // namespace mpm
