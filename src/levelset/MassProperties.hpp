// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "levelset/TriangleMesh.hpp"

namespace mpm::levelset {

/// Volume, centroid and inertia (unit density) of the solid bounded by a closed triangle mesh.
struct MassProperties {
    double volume = 0.0;
    Vec3 centroid = Vec3::Zero();
    /// Inertia tensor about the centroid, in the mesh frame: I = ∫ (|r|² 1 − r rᵀ) dV, r = x − c.
    Mat3 inertia = Mat3::Zero();
    /// Eigenvalues of `inertia`, ascending.
    Vec3 principalMoments = Vec3::Zero();
    /// Columns: the principal axes (right-handed, det R = +1). A point of the body frame maps to
    /// the mesh frame by x = c + R X, and back by X = Rᵀ (x − c); Rᵀ I R = diag(moments).
    Mat3 rotation = Mat3::Identity();
};

/// Mass properties by the divergence theorem: volume integrals of 1, x, x² and xy become sums
/// over signed tetrahedra (origin, triangle) — D. Eberly, "Polyhedral Mass Properties
/// (Revisited)", Geometric Tools 2002, after B. Mirtich, J. Graphics Tools 1(2), 1996.
/// Coordinates are taken relative to the vertex mean to limit cancellation. A mesh wound
/// inside-out (negative volume) is flipped. Throws std::runtime_error if the volume is zero.
MassProperties computeMassProperties(const TriangleMesh& mesh);

} // namespace mpm::levelset
