// SPDX-License-Identifier: GPL-3.0-or-later
// Conformance of every registered shape: built from its schema's example (a level set from a
// sampled box), its signed distance is 1-Lipschitz, its normal is the gradient of φ, its volume,
// centroid and principal inertia agree with Monte Carlo quadrature over φ < 0, and its bounding
// radius encloses it. A shape the registry knows is tested here without a test of its own; a
// deliberately broken shape is caught by each check.
#include "core/Constants.hpp"
#include "core/KeySchema.hpp"
#include "levelset/LevelSetFile.hpp"
#include "rigid/Shape.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

/// What each check found wrong with a shape (empty: conforming).
struct Findings {
    std::vector<std::string> failed; ///< the names of the failed checks, with the numbers
    bool has(const std::string& check) const {
        return std::any_of(failed.begin(), failed.end(),
                           [&](const std::string& f) { return f.rfind(check, 0) == 0; });
    }
};

template <int dim> Findings check(const Shape<dim>& s) {
    Findings out;
    auto fail = [&](const std::string& what, double value) {
        out.failed.push_back(what + " (" + std::to_string(value) + ")");
    };
    const double R = s.boundingRadius();
    // A sampled φ (a level set) is the B-spline smoothing of its samples: its zero set rounds the
    // mesh's edges, so its mass properties (the mesh's) hold to the sampling (a box 8 spacings
    // thick: volume 1.6 %, inertia 3.2 % above φ < 0's), and its gradient is bounded by √dim,
    // not 1 (each partial derivative averages the samples' differences, each ≤ 1).
    const bool sampled = s.samplingSpacing() > 0.0;
    const double massTolerance = sampled ? 0.05 : 0.03;
    std::mt19937_64 rng(20261128);
    std::uniform_real_distribution<double> u(-R, R);
    auto point = [&] {
        Vec<dim> x;
        for (int d = 0; d < dim; ++d)
            x[d] = u(rng);
        return x;
    };
    Vec<dim> n;

    // Mass properties by Monte Carlo over the cube [−R, R]^dim, and every inside point within R.
    constexpr int Samples = 400000;
    const double cube = std::pow(2.0 * R, dim);
    int inside = 0;
    Vec<dim> first = Vec<dim>::Zero();
    Mat<dim> second = Mat<dim>::Zero();
    double farthest = 0.0;
    for (int k = 0; k < Samples; ++k) {
        const Vec<dim> x = point();
        if (s.distance(x, n) >= 0.0) continue;
        ++inside;
        first += x;
        second += x * x.transpose();
        farthest = std::max(farthest, x.norm());
    }
    const double volume = cube * inside / Samples;
    if (std::fabs(volume / s.volume() - 1.0) > massTolerance) fail("volume", volume / s.volume());
    const Vec<dim> centroid = first / std::max(inside, 1);
    if (centroid.norm() > 0.02 * R) fail("centroid", centroid.norm() / R);
    if (farthest > R) fail("bounding radius", farthest / R);
    // Inertia per unit density: J = tr(S) − S_kk about the body axes (S = ∫ x xᵀ dV); in 2D the
    // polar moment tr(S).
    const Mat<dim> S = second * (cube / Samples);
    const Vec3 I = s.unitInertia();
    if constexpr (dim == 2) {
        if (std::fabs(S.trace() / I[2] - 1.0) > massTolerance) fail("inertia", S.trace() / I[2]);
    } else {
        for (int k = 0; k < 3; ++k)
            if (std::fabs((S.trace() - S(k, k)) / I[k] - 1.0) > massTolerance)
                fail("inertia", (S.trace() - S(k, k)) / I[k]);
        const double off = std::max({std::fabs(S(0, 1)), std::fabs(S(0, 2)), std::fabs(S(1, 2))});
        if (off > 0.02 * I.maxCoeff()) fail("inertia off the body axes", off / I.maxCoeff());
    }
    std::vector<Vec3> surface;
    std::vector<std::vector<int>> cells;
    s.surface(surface, cells);
    for (const Vec3& p : surface)
        if (p.template head<dim>().norm() > R * (1.0 + 1e-12))
            fail("bounding radius (surface)", p.template head<dim>().norm() / R);

    // 1-Lipschitz: |φ(x) − φ(y)| ≤ |x − y| (√dim |x − y| for a sampled φ, above).
    double worst = 0.0;
    for (int k = 0; k < 20000; ++k) {
        const Vec<dim> x = point(), y = x + 0.1 * (point() - x);
        worst = std::max(worst, std::fabs(s.distance(x, n) - s.distance(y, n)) / (x - y).norm());
    }
    if (worst > (sampled ? std::sqrt(double(dim)) : 1.0 + 1e-9)) fail("Lipschitz", worst);

    // n = ∇φ by central differences, outside the shape (where φ is smooth for a convex shape);
    // allowed off at 2 % of the points (the medial axis of a concave one, cell faces of a
    // sampled one).
    const double step = sampled ? 1e-3 * s.samplingSpacing() : 1e-6 * R;
    int tried = 0, off = 0;
    for (int k = 0; k < 4000; ++k) {
        const Vec<dim> x = point();
        if (s.distance(x, n) < 0.05 * R) continue;
        Vec<dim> grad, ignored;
        for (int d = 0; d < dim; ++d) {
            const Vec<dim> e = step * Vec<dim>::Unit(d);
            grad[d] = (s.distance(x + e, ignored) - s.distance(x - e, ignored)) / (2.0 * step);
        }
        ++tried;
        if ((grad.normalized() - n).norm() > 1e-4) ++off;
    }
    if (tried < 100 || off > 0.02 * tried) fail("normal", static_cast<double>(off) / tried);
    return out;
}

/// Examples for the dimension a type's schema example is not written in.
const std::map<std::string, std::string>& otherDimensionExamples() {
    static const std::map<std::string, std::string> e{
        {"box", "{type: box, size: [0.1, 0.05, 0.03]}"},
        {"sphere", "{type: sphere, radius: 0.019}"},
        {"disk", "{type: disk, radius: 0.019}"}};
    return e;
}

/// A box of half extents (0.2, 0.12, 0.08) m sampled on a 0.02 m grid, as surfaceToLevelSet
/// writes it.
std::string writeBoxLevelSet(const test::TempDir& dir) {
    levelset::LevelSet ls;
    const Vec3 h(0.2, 0.12, 0.08);
    ls.grid.origin = Vec3::Constant(-0.3);
    ls.grid.spacing = 0.02;
    ls.grid.dims = {31, 31, 31};
    ls.grid.values.resize(ls.grid.numPoints());
    for (int k = 0; k < 31; ++k)
        for (int j = 0; j < 31; ++j)
            for (int i = 0; i < 31; ++i) {
                const Vec3 q = ls.grid.point(i, j, k).cwiseAbs() - h;
                ls.grid.values[ls.grid.index(i, j, k)] =
                    q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
            }
    ls.volume = 8.0 * h.prod();
    ls.principalMoments =
        ls.volume / 3.0 *
        Vec3(h[1] * h[1] + h[2] * h[2], h[0] * h[0] + h[2] * h[2], h[0] * h[0] + h[1] * h[1]);
    const auto file = dir / "box.vti";
    levelset::writeVti(file, ls, true);
    return "{type: levelSet, file: " + file.string() + "}";
}

template <int dim> std::unique_ptr<Shape<dim>> build(const std::string& example) {
    return Shape<dim>::create(Dictionary::fromString(example, "constant/rigidBodies"));
}

TEST(ShapeConformance, EveryRegisteredShapeConforms) {
    const auto* family = ModelCatalogue::find("shapes");
    ASSERT_NE(family, nullptr);
    const test::TempDir dir;
    int tested = 0;
    for (const auto& [type, dims] : ModelCatalogue::types(*family)) {
        if (type.rfind("test", 0) == 0) continue; // shapes the unit tests register
        ASSERT_TRUE(family->schemas.count(type)) << type << " has no MPM_SCHEMA (and no example)";
        const TypeSchema& schema = family->schemas.at(type);
        const int onlyDim = ModelCatalogue::onlyDim(*family, type);
        for (const int dim : dims) {
            std::string example = schema.example;
            if (type == "levelSet")
                example = writeBoxLevelSet(dir);
            else if ((onlyDim == 0 ? 2 : onlyDim) != dim)
                example = otherDimensionExamples().at(type); // a new type: add its example here
            const Findings f = dim == 2 ? check(*build<2>(example)) : check(*build<3>(example));
            EXPECT_TRUE(f.failed.empty()) << type << " (" << dim << "D): " << f.failed.front();
            ++tested;
        }
    }
    EXPECT_GE(tested, 6); // box 2D/3D, sphere 3D, disk 2D, spheropolygon 2D, levelSet 3D
}

/// A sphere with one thing deliberately wrong.
class BrokenSphere : public Shape<3> {
public:
    enum class Flaw { inertia, boundingRadius, normal, distance };
    explicit BrokenSphere(Flaw flaw) : flaw_(flaw) {}
    double distance(const Vec3& x, Vec3& normal) const override {
        normal = x.normalized();
        if (flaw_ == Flaw::normal) normal = Vec3(normal.y(), normal.z(), normal.x());
        return flaw_ == Flaw::distance ? 1.5 * (x.norm() - r_) : x.norm() - r_;
    }
    double volume() const override { return 4.0 / 3.0 * pi * r_ * r_ * r_; }
    Vec3 unitInertia() const override {
        return Vec3::Constant((flaw_ == Flaw::inertia ? 1.1 : 1.0) * 0.4 * volume() * r_ * r_);
    }
    double boundingRadius() const override { return flaw_ == Flaw::boundingRadius ? 0.9 * r_ : r_; }
    void surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const override {
        points = {Vec3(r_, 0, 0), Vec3(0, r_, 0), Vec3(0, 0, r_)};
        cells = {{0, 1, 2}};
    }

private:
    Flaw flaw_;
    double r_ = 0.1;
};

TEST(ShapeConformance, EachCheckCatchesABrokenShape) {
    using F = BrokenSphere::Flaw;
    EXPECT_TRUE(check(BrokenSphere(F::inertia)).has("inertia"));
    EXPECT_TRUE(check(BrokenSphere(F::boundingRadius)).has("bounding radius"));
    EXPECT_TRUE(check(BrokenSphere(F::normal)).has("normal"));
    EXPECT_TRUE(check(BrokenSphere(F::distance)).has("Lipschitz"));
}

} // namespace
} // namespace mpm
