// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/ParticleSeeder.hpp"

#include "core/Constants.hpp"
#include "core/SymmetricEigen.hpp"
#include "particles/Region.hpp"
#include "particles/Seeding.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace mpm {

namespace {

/// Quadrature samples per Poisson-disk spacing along an axis for `volumes: voronoi`: about 900
/// samples a point in 3D, 400 in 2D (Voronoi volumes to ~1 % rms; SeedingTest).
template <int dim> constexpr int VoronoiSamplesPerSpacing = dim == 3 ? 8 : 16;

template <int dim> Vec<dim> toVec(const std::vector<double>& v) {
    Vec<dim> r;
    for (int d = 0; d < dim; ++d)
        r[d] = v[d];
    return r;
}

/// Initial velocity of a particle set: a vector, or {type: uniform, value} or
/// {type: axialMode, amplitude, direction, origin, length, mode}: the n-th mode of a bar fixed
/// at `origin`, v = A sin((2n - 1)π s / 2L) d with s = (x - origin)·d, or
/// {type: radialMode, amplitude, centre, radius}: the fundamental breathing mode of a ball (3D)
/// or cylinder (2D) of radius a with a free, incompressible-limit surface [002 Eq. 62],
/// v = A R(k r) r̂ with r = |x − centre|, R = j₁ (spherical Bessel), k = π/a in 3D and R = J₁,
/// k = j₀,₁/a (j₀,₁ = 2.40483, the first zero of J₀) in 2D; A < 0 compresses.
template <int dim> class InitialVelocity {
public:
    explicit InitialVelocity(const Dictionary& set) {
        if (!set.isDict("velocity")) {
            value_ = toVec<dim>(set.getVectorOr("velocity", std::vector<double>(dim, 0.0), dim));
            return;
        }
        const Dictionary d = set.subDict("velocity");
        const std::string type = d.getWord("type", {"uniform", "axialMode", "radialMode"});
        if (type == "uniform") {
            value_ = toVec<dim>(d.getVector("value", dim));
        } else if (type == "radialMode") {
            radial_ = true;
            amplitude_ = d.getScalar("amplitude");
            origin_ = toVec<dim>(d.getVector("centre", dim));
            length_ = d.getScalar("radius", Bounds::positive());
        } else {
            mode_ = true;
            amplitude_ = d.getScalar("amplitude");
            direction_ = toVec<dim>(d.getVector("direction", dim));
            if (direction_.norm() == 0) d.error("direction", "direction must not be zero");
            direction_.normalize();
            origin_ = toVec<dim>(d.getVectorOr("origin", std::vector<double>(dim, 0.0), dim));
            length_ = d.getScalar("length", Bounds::positive());
            n_ = d.getIntOr("mode", 1, Bounds::closed(1, 1000));
        }
        d.checkUnknownKeys();
    }
    Vec<dim> at(const Vec<dim>& x) const {
        if (radial_) {
            const Vec<dim> r = x - origin_;
            const double rn = r.norm();
            if (rn == 0.0) return Vec<dim>::Zero();
            const double R = dim == 3 ? std::sph_bessel(1, pi * rn / length_)
                                      : std::cyl_bessel_j(1.0, 2.404825557695773 * rn / length_);
            return amplitude_ * R / rn * r;
        }
        if (!mode_) return value_;
        const double s = (x - origin_).dot(direction_);
        return amplitude_ * std::sin((2 * n_ - 1) * pi * s / (2.0 * length_)) * direction_;
    }

private:
    Vec<dim> value_ = Vec<dim>::Zero();
    bool mode_ = false, radial_ = false;
    double amplitude_ = 0, length_ = 1;
    int n_ = 1;
    Vec<dim> direction_ = Vec<dim>::Zero(), origin_ = Vec<dim>::Zero();
};

} // namespace

template <int dim> void ParticleSeeder<dim>::seed(const Dictionary& sets, Particles<dim>& p) {
    Index nextId = 0;
    for (const std::string& setName : sets.keys()) {
        const Dictionary set = sets.subDict(setName);
        const std::string matName = set.getString("material");
        int mat = -1;
        for (std::size_t m = 0; m < materials_.size(); ++m)
            if (materials_[m]->name() == matName) mat = static_cast<int>(m);
        if (mat < 0) {
            std::string valid;
            for (const auto& m : materials_)
                valid += (valid.empty() ? "" : ", ") + m->name();
            set.error("material",
                      "unknown material '" + matName + "'; constant/materials defines: " + valid);
        }
        const auto region = Region<dim>::create(set.subDict("region"));
        {
            // Check before seeding: a region far larger than the grid would seed without bound.
            const auto box = region->bounds();
            const double tol = 1e-9 * grid_.h();
            for (int d = 0; d < dim; ++d)
                if (box.min()[d] < grid_.lo()[d] - tol || box.max()[d] > grid_.hi()[d] + tol) {
                    std::ostringstream os;
                    os << "the region extends outside the grid bounds ([" << box.min().transpose()
                       << "] – [" << box.max().transpose() << "] is not inside ["
                       << grid_.lo().transpose() << "] – [" << grid_.hi().transpose()
                       << "] of constant/grid)";
                    set.error("region", os.str());
                }
        }

        std::string method = "regular";
        int perDirection = 2;
        int perCell = dim == 2 ? 4 : 8;
        long rngSeed = 0;
        bool voronoi = false;
        if (set.has("seeding")) {
            const Dictionary sd = set.subDict("seeding");
            method = sd.getWordOr("method", "regular", {"regular", "poissonDisk"});
            if (method == "regular") {
                perDirection = sd.getIntOr("perDirection", 2, Bounds::closed(1, 8));
                if (sd.has("volumes"))
                    sd.error("volumes", "only poissonDisk seeding takes `volumes`: a regular "
                                        "lattice gives every point its sub-cell (h/n)^dim");
            } else {
                perCell = sd.getIntOr("perCell", perCell, Bounds::closed(1, 512));
                rngSeed = sd.getIntOr("seed", 0, Bounds::nonNegative());
                voronoi = sd.getWordOr("volumes", "equal", {"equal", "voronoi"}) == "voronoi";
            }
            sd.checkUnknownKeys();
        }
        const InitialVelocity<dim> velocity(set);

        // Initial stress: none, or geostatic σ_v = -ρ|g|(z_s - z), σ_h = K0 σ_v.
        bool geostatic = false;
        double K0 = materials_[mat]->defaultK0();
        double surface = 0;
        bool surfaceGiven = false;
        const std::vector<std::string> stressTypes{"none", "geostatic", "gravityPreload"};
        std::string stressType = "none";
        if (set.isDict("initialStress")) {
            const Dictionary is = set.subDict("initialStress");
            stressType = is.getWord("type", stressTypes);
            if (stressType == "geostatic") {
                K0 = is.getScalarOr("K0", K0, Bounds::nonNegative());
                surfaceGiven = is.has("surface");
                if (surfaceGiven) surface = is.getScalar("surface");
            } else if (stressType == "gravityPreload") {
                preload_.damping = is.getScalarOr("damping", 0.5, Bounds::halfOpen(0.0, 1.0));
                preload_.tolerance = is.getScalarOr("tolerance", 1e-4, {0.0, 1.0, false, false});
                preload_.maxSteps = is.getIntOr("maxSteps", 20000, Bounds::closed(1, 1e9));
            }
            is.checkUnknownKeys();
        } else {
            stressType = set.getWordOr("initialStress", "none", stressTypes);
        }
        const bool outsideBodies = set.getBoolOr("outsideBodies", false);
        if (outsideBodies && !bodyDistance_)
            set.error("outsideBodies", "the scene has no rigid bodies (constant/rigidBodies)");
        if (set.has("bodyClearance") && !outsideBodies)
            set.error("bodyClearance", "bodyClearance needs outsideBodies: yes");
        const double clearanceGiven = set.getScalarOr("bodyClearance", -1.0, Bounds::positive());
        const int minimumCluster = set.getIntOr("minimumCluster", 1, Bounds::closed(1, 1e9));
        geostatic = stressType == "geostatic";
        if (stressType == "gravityPreload") {
            if (gravity_.norm() == 0)
                set.error("initialStress", "a gravity preload needs gravity (constant/g)");
            preload_.requested = true;
        }
        set.checkUnknownKeys();

        std::vector<Vec<dim>> xs;
        double volume = 0;
        if (method == "regular") {
            xs = seedRegular<dim>(*region, grid_.origin(), grid_.h(), perDirection);
            volume = std::pow(grid_.h() / perDirection, dim);
        } else {
            xs = seedPoissonDisk<dim>(*region, poissonDiskSpacing(grid_.h(), perCell, dim),
                                      static_cast<std::uint64_t>(rngSeed));
            if (!xs.empty()) volume = region->volume() / static_cast<double>(xs.size());
        }
        if (outsideBodies) { // clear of every body by c (default half the point spacing)
            const double clearance =
                clearanceGiven > 0 ? clearanceGiven : 0.5 * std::pow(volume, 1.0 / dim);
            const std::size_t seeded = xs.size();
            xs.erase(
                std::remove_if(xs.begin(), xs.end(),
                               [&](const Vec<dim>& x) { return bodyDistance_(x) < clearance; }),
                xs.end());
            if (xs.empty())
                set.error("outsideBodies", "every one of the " + std::to_string(seeded) +
                                               " points of the region lies in or next to a body");
        }
        if (minimumCluster > 1) { // neighbours: within 1.5 spacings (diagonals of a lattice)
            const std::size_t seeded = xs.size();
            dropSmallClusters(xs, 1.5 * std::pow(volume, 1.0 / dim),
                              static_cast<std::size_t>(minimumCluster));
            if (xs.empty() && seeded > 0)
                set.error("minimumCluster", "every group of the " + std::to_string(seeded) +
                                                " points is smaller than " +
                                                std::to_string(minimumCluster));
        }
        if (xs.empty())
            set.error("region", "the region seeds no particles (is it smaller "
                                "than a cell, or outside the grid?)");
        // Each point's volume: equal shares of the region, or its Voronoi cell in the region
        // (outside the bodies) [002 §4.5].
        std::vector<double> volumes(xs.size(), volume);
        if (voronoi) {
            std::function<bool(const Vec<dim>&)> inBody;
            if (outsideBodies) inBody = [&](const Vec<dim>& x) { return bodyDistance_(x) < 0; };
            volumes = voronoiVolumes<dim>(*region, xs, poissonDiskSpacing(grid_.h(), perCell, dim),
                                          VoronoiSamplesPerSpacing<dim>, inBody);
        }
        for (const auto& x : xs)
            for (int d = 0; d < dim; ++d)
                if (x[d] < grid_.lo()[d] || x[d] > grid_.hi()[d]) {
                    std::ostringstream os;
                    os << "particles lie outside the grid bounds (a particle at (" << x.transpose()
                       << ") is outside [" << grid_.lo().transpose() << "] – ["
                       << grid_.hi().transpose() << "] of constant/grid)";
                    set.error("region", os.str());
                }

        Vec<dim> up = Vec<dim>::Zero();
        const double gNorm = gravity_.norm();
        if (geostatic) {
            if (gNorm == 0)
                set.error("initialStress", "a geostatic initial stress needs gravity (constant/g)");
            up = -gravity_ / gNorm;
            if (!surfaceGiven) {
                surface = -1e300;
                for (const auto& x : xs)
                    surface = std::max(surface, up.dot(x));
                surface += 0.5 * std::pow(volume, 1.0 / dim);
            }
        }

        const double rho = materials_[mat]->density();
        const std::size_t first = p.size();
        p.resize(first + xs.size());
        for (std::size_t k = 0; k < xs.size(); ++k) {
            const std::size_t i = first + k;
            p.x[i] = xs[k];
            p.v[i] = velocity.at(xs[k]);
            p.C[i].setZero();
            p.L[i].setZero();
            p.F[i].setIdentity();
            p.mass[i] = rho * volumes[k];
            p.volume0[i] = volumes[k];
            p.volume[i] = volumes[k];
            p.plasticStrain[i] = 0;
            p.id[i] = nextId++;
            p.material[i] = mat;
            Mat3 sigma0 = Mat3::Zero();
            if (geostatic) {
                const double sv = -rho * gNorm * std::max(0.0, surface - up.dot(xs[k]));
                Vec3 u = Vec3::Zero();
                u.template head<dim>() = up;
                sigma0 = K0 * sv * Mat3::Identity() + (1.0 - K0) * sv * u * u.transpose();
            }
            materials_[mat]->initialise(p, static_cast<Index>(i), sigma0);
            if (geostatic) {
                // Start from the elastic stretch of the prestress, F = (bᵉ)^½, so that J < 1:
                // the bed is compressed from its stress-free density like after a gravity
                // preload, and a trans-phase material is not at its critical density.
                Vec3 lam;
                Mat3 Q;
                symmetricEigen3(p.be[i], lam, Q);
                const Mat3 V = fromEigen(Q, lam.cwiseSqrt());
                p.F[i] = V.template topLeftCorner<dim, dim>();
                p.volume[i] = volumes[k] * p.F[i].determinant();
            }
        }
    }
    if (p.size() == 0) sets.error("", "constant/particles defines no particle sets");
    sets.checkUnknownKeys();
}

template class ParticleSeeder<2>;
template class ParticleSeeder<3>;

} // namespace mpm
