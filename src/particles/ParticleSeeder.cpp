// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/ParticleSeeder.hpp"

#include "core/SymmetricEigen.hpp"
#include "particles/InitialStress.hpp"
#include "particles/InitialVelocity.hpp"
#include "particles/Region.hpp"
#include "particles/Seeding.hpp"
#include "particles/SeedingMethod.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace mpm {

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

        const auto method = SeedingMethod<dim>::create(set);
        const auto velocity = InitialVelocity<dim>::create(set);

        const auto stress = InitialStress<dim>::create(set, materials_[mat]->defaultK0(), gravity_);
        if (stress->preload().requested) preload_ = stress->preload();
        const bool outsideBodies = set.getBoolOr("outsideBodies", false);
        if (outsideBodies && !bodyDistance_)
            set.error("outsideBodies", "the scene has no rigid bodies (constant/rigidBodies)");
        if (set.has("bodyClearance") && !outsideBodies)
            set.error("bodyClearance", "bodyClearance needs outsideBodies: yes");
        const double clearanceGiven = set.getScalarOr("bodyClearance", -1.0, Bounds::positive());
        const int minimumCluster = set.getIntOr("minimumCluster", 1, Bounds::closed(1, 1e9));
        set.checkUnknownKeys();

        std::vector<Vec<dim>> xs = method->positions(*region, grid_.origin(), grid_.h());
        const double volume = method->nominalVolume(*region, grid_.h(), xs.size());
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
        std::function<bool(const Vec<dim>&)> inBody;
        if (outsideBodies) inBody = [&](const Vec<dim>& x) { return bodyDistance_(x) < 0; };
        const std::vector<double> volumes = method->volumes(*region, xs, volume, grid_.h(), inBody);
        for (const auto& x : xs)
            for (int d = 0; d < dim; ++d)
                if (x[d] < grid_.lo()[d] || x[d] > grid_.hi()[d]) {
                    std::ostringstream os;
                    os << "particles lie outside the grid bounds (a particle at (" << x.transpose()
                       << ") is outside [" << grid_.lo().transpose() << "] – ["
                       << grid_.hi().transpose() << "] of constant/grid)";
                    set.error("region", os.str());
                }

        stress->place(xs, std::pow(volume, 1.0 / dim));

        const double rho = materials_[mat]->density();
        const std::size_t first = p.size();
        p.resize(first + xs.size());
        for (std::size_t k = 0; k < xs.size(); ++k) {
            const std::size_t i = first + k;
            p.x[i] = xs[k];
            p.v[i] = velocity->at(xs[k]);
            p.C[i].setZero();
            p.L[i].setZero();
            p.F[i].setIdentity();
            p.mass[i] = rho * volumes[k];
            p.volume0[i] = volumes[k];
            p.volume[i] = volumes[k];
            p.plasticStrain[i] = 0;
            p.id[i] = nextId++;
            p.material[i] = mat;
            const Mat3 sigma0 = stress->at(xs[k], rho);
            materials_[mat]->initialise(p, static_cast<Index>(i), sigma0);
            if (stress->prestretches()) {
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
