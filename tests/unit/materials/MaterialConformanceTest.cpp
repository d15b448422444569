// SPDX-License-Identifier: GPL-3.0-or-later
// Every material the registry knows, built from its schema's example in 2D and 3D (and with
// `elasticity: hypoelastic` where it takes that key), keeps the contract of Material<dim>: no
// stress at rest, objectivity, a non-finite stress reported, and a restart that loses nothing.
// A new material needs no test of its own here.
#include "MaterialTestSupport.hpp"
#include "case/Registry.hpp"
#include "core/KeySchema.hpp"
#include "io/ParticleIO.hpp"
#include "materials/Material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm {
namespace {

constexpr double dt = 1e-5;

/// Every registered material as (name, example): the schema's example, and with
/// `elasticity: hypoelastic` for a type that reads that key.
std::vector<std::pair<std::string, std::string>> examples() {
    std::vector<std::pair<std::string, std::string>> out;
    const auto* family = ModelCatalogue::find("materials");
    if (!family) return out;
    for (const auto& [type, dims] : ModelCatalogue::types(*family)) {
        if (type.compare(0, 4, "test") == 0) continue;
        const auto it = family->schemas.find(type);
        const std::string example = it == family->schemas.end() ? "" : it->second.example;
        out.emplace_back(type, example);
        bool hasElasticity = false;
        for (const KeyInfo& k : it == family->schemas.end() ? KeyList{} : it->second.keys)
            hasElasticity = hasElasticity || k.name == "elasticity";
        if (hasElasticity && example.size() > 1)
            out.emplace_back(type + " (hypoelastic)",
                             example.substr(0, example.size() - 1) + ", elasticity: hypoelastic}");
    }
    return out;
}

/// `n` points at rest of material `m`: F = bᵉ = 1, σ = 0, V = V⁰, state declared and initialised.
template <int dim> Particles<dim> atRest(Material<dim>& m, int n) {
    Particles<dim> p = test::restingParticles<dim>(n, 1e-6, 1e-6 * m.density(), 0.0);
    m.declareState(p);
    for (int i = 0; i < n; ++i) {
        p.material[i] = 0;
        m.initialise(p, i, Mat3::Zero());
    }
    return p;
}

/// One step as the solver takes it: F and V from L, then the stress. The first point whose
/// stress is not finite, or -1.
template <int dim> Index step(const Material<dim>& m, Particles<dim>& p) {
    p.updateDeformation(dt, {static_cast<char>(m.volumeFromRate())});
    std::vector<Index> ids(p.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
        ids[i] = static_cast<Index>(i);
    return m.updateStress(p, ids, dt);
}

/// The unit spin K about z (2D) or about (1, 2, 3)/√14 (3D): L = ω K spins at rate ω.
template <int dim> Mat<dim> axisSpin() {
    Mat<dim> w = Mat<dim>::Zero();
    if constexpr (dim == 2) {
        w << 0, -1, 1, 0;
    } else {
        const Vec<3> a = Vec<3>(1, 2, 3).normalized();
        w << 0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0;
    }
    return w;
}

/// The restart fields of `p`, byte for byte.
template <int dim>
std::map<std::string, std::vector<unsigned char>> restartBytes(Particles<dim>& p) {
    std::map<std::string, std::vector<unsigned char>> out;
    p.forEachField([&](const FieldInfo& info, auto& a) {
        if (!info.restart) return;
        auto& bytes = out[info.name];
        bytes.resize(a.size() * sizeof(a[0]));
        if (!bytes.empty())
            std::memcpy(bytes.data(), static_cast<const void*>(a.data()), bytes.size());
    });
    return out;
}

template <int dim> std::unique_ptr<Material<dim>> build(const std::string& example) {
    return Material<dim>::create(Dictionary::fromString(example, "constant/materials"), "m");
}

/// The findings for one material in dimension dim; empty when it conforms.
template <int dim> std::vector<std::string> check(const std::string& example) {
    std::vector<std::string> failed;
    auto m = build<dim>(example);

    // At rest (F = I, stress-free start): no stress.
    {
        Particles<dim> p = atRest(*m, 1);
        if (step(*m, p) != -1 || p.stress[0].norm() != 0.0)
            failed.push_back("stress at rest: |σ| = " + std::to_string(p.stress[0].norm()));
    }

    // Objectivity: two points deformed alike, then the second spun by θ about an axis while the
    // first rests: σ₂ = R σ₁ Rᵀ.
    {
        Particles<dim> p = atRest(*m, 2);
        Mat<dim> L = Mat<dim>::Zero();
        L(0, 0) = -2.0;
        L(1, 1) = -1.0;
        L(0, 1) = 0.8;
        L(1, 0) = -0.3;
        for (int s = 0; s < 500; ++s) { // 1 % compression, and shear
            p.L[0] = p.L[1] = L;
            step(*m, p);
        }
        const double theta = 0.2, rate = 5.0; // rad, rad/s: 4000 steps of ω Δt = 5e-5
        const Mat<dim> W = rate * axisSpin<dim>();
        for (int s = 0; s < static_cast<int>(std::lround(theta / (rate * dt))); ++s) {
            p.L[0].setZero();
            p.L[1] = W;
            step(*m, p);
        }
        // Rodrigues: R = 1 + sin θ K + (1 − cos θ) K² (in 2D K² is −1 in the plane).
        const Mat<dim> K = axisSpin<dim>();
        Mat3 R = Mat3::Identity();
        R.template topLeftCorner<dim, dim>() +=
            std::sin(theta) * K + (1.0 - std::cos(theta)) * K * K;
        const Mat3 expected = R * p.stress[0] * R.transpose();
        const double scale = p.stress[0].norm();
        const double error = (p.stress[1] - expected).norm();
        if (!(scale > 0.0) || !(error <= 5e-3 * scale))
            failed.push_back(
                "objectivity: |σ₂ − R σ₁ Rᵀ| / |σ₁| = " + std::to_string(error / scale) +
                " (|σ₁| = " + std::to_string(scale) + " Pa)");
    }

    // A non-finite velocity gradient: updateStress names the point rather than going on.
    {
        Particles<dim> p = atRest(*m, 3);
        p.L[1](0, 0) = std::numeric_limits<double>::quiet_NaN();
        const Index bad = step(*m, p);
        if (bad != 1)
            failed.push_back("NaN in L of point 1: updateStress returned " + std::to_string(bad));
    }

    // Restart: the declared state read back bit for bit into a fresh material, and the next
    // step of both identical.
    {
        Particles<dim> p = atRest(*m, 2);
        Mat<dim> L = Mat<dim>::Zero();
        L(0, 0) = -3.0;
        L(0, 1) = 2.0;
        for (int s = 0; s < 300; ++s) {
            p.L[0] = L;
            p.L[1] = -0.5 * L;
            step(*m, p);
        }
        const io::PointCloud cloud = io::toPointCloud(p);
        auto fresh = build<dim>(example);
        Particles<dim> q;
        fresh->declareState(q);
        io::fromPointCloud(cloud, q, "restart");
        if (restartBytes(p) != restartBytes(q))
            failed.push_back("restart: a field differs when read back");
        for (std::size_t i = 0; i < 2; ++i)
            q.L[i] = p.L[i];
        step(*m, p);
        step(*fresh, q);
        if (restartBytes(p) != restartBytes(q))
            failed.push_back("restart: the step after the restart differs");
    }
    return failed;
}

TEST(MaterialConformance, EveryRegisteredMaterialConforms) {
    int tested = 0;
    for (const auto& [name, example] : examples()) {
        ASSERT_FALSE(example.empty()) << name << " has no MPM_SCHEMA example";
        for (const int dim : {2, 3}) {
            const std::vector<std::string> f = dim == 2 ? check<2>(example) : check<3>(example);
            for (const std::string& why : f)
                ADD_FAILURE() << name << " (" << dim << "D): " << why;
            ++tested;
        }
    }
    EXPECT_GE(tested, 14); // 5 types in 2D and 3D, druckerPrager and muI also hypoelastic
}

} // namespace
} // namespace mpm
