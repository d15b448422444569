// SPDX-License-Identifier: GPL-3.0-or-later
#include "levelset/MassProperties.hpp"

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <stdexcept>

namespace mpm::levelset {

namespace {

/// Eberly's subexpressions: f1 = Σw, f2 = Σ w_i w_j (i ≤ j), f3 = Σ w_i w_j w_k, g_i = f2 + w_i (f1
/// + w_i).
struct Sub {
    double f1, f2, f3, g0, g1, g2;
};

Sub subexpressions(double w0, double w1, double w2) {
    Sub s{};
    const double t0 = w0 + w1;
    s.f1 = t0 + w2;
    const double t1 = w0 * w0;
    const double t2 = t1 + w1 * t0;
    s.f2 = t2 + w2 * s.f1;
    s.f3 = w0 * t1 + w1 * t2 + w2 * s.f2;
    s.g0 = s.f2 + w0 * (s.f1 + w0);
    s.g1 = s.f2 + w1 * (s.f1 + w1);
    s.g2 = s.f2 + w2 * (s.f1 + w2);
    return s;
}

} // namespace

MassProperties computeMassProperties(const TriangleMesh& mesh) {
    Vec3 ref = Vec3::Zero();
    for (const Vec3& v : mesh.vertices)
        ref += v;
    if (!mesh.vertices.empty()) ref /= static_cast<double>(mesh.vertices.size());

    // ∫1, ∫x, ∫y, ∫z, ∫x², ∫y², ∫z², ∫xy, ∫yz, ∫zx (before the constant factors).
    std::array<double, 10> in{};
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3 p0 = mesh.vertex(t, 0) - ref;
        const Vec3 p1 = mesh.vertex(t, 1) - ref;
        const Vec3 p2 = mesh.vertex(t, 2) - ref;
        const Vec3 d = (p1 - p0).cross(p2 - p0);
        const Sub x = subexpressions(p0.x(), p1.x(), p2.x());
        const Sub y = subexpressions(p0.y(), p1.y(), p2.y());
        const Sub z = subexpressions(p0.z(), p1.z(), p2.z());
        in[0] += d.x() * x.f1;
        in[1] += d.x() * x.f2;
        in[2] += d.y() * y.f2;
        in[3] += d.z() * z.f2;
        in[4] += d.x() * x.f3;
        in[5] += d.y() * y.f3;
        in[6] += d.z() * z.f3;
        in[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
        in[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
        in[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
    }
    constexpr std::array<double, 10> mult{1.0 / 6,  1.0 / 24, 1.0 / 24,  1.0 / 24,  1.0 / 60,
                                          1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
    for (std::size_t i = 0; i < in.size(); ++i)
        in[i] *= mult[i];
    if (in[0] < 0.0) {
        for (double& v : in)
            v = -v; // wound inside-out
    }
    const double m = in[0];
    if (!(m > 0.0) || !std::isfinite(m)) {
        throw std::runtime_error("the surface encloses no volume");
    }

    MassProperties mp;
    mp.volume = m;
    const Vec3 c(in[1] / m, in[2] / m, in[3] / m); // relative to ref
    mp.centroid = ref + c;
    Mat3& I = mp.inertia;
    I(0, 0) = in[5] + in[6] - m * (c.y() * c.y() + c.z() * c.z());
    I(1, 1) = in[4] + in[6] - m * (c.z() * c.z() + c.x() * c.x());
    I(2, 2) = in[4] + in[5] - m * (c.x() * c.x() + c.y() * c.y());
    I(0, 1) = I(1, 0) = -(in[7] - m * c.x() * c.y());
    I(1, 2) = I(2, 1) = -(in[8] - m * c.y() * c.z());
    I(0, 2) = I(2, 0) = -(in[9] - m * c.z() * c.x());

    const Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
    mp.principalMoments = eig.eigenvalues();
    mp.rotation = eig.eigenvectors();
    if (mp.rotation.determinant() < 0.0) mp.rotation.col(2) *= -1.0;
    return mp;
}

} // namespace mpm::levelset
