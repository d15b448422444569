// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <array>
#include <cstddef>
#include <filesystem>
#include <vector>

namespace mpm::levelset {

/// An indexed triangle mesh (a surface read from STL, OBJ or PLY).
struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;

    std::size_t numTriangles() const { return triangles.size(); }
    Vec3 vertex(std::size_t t, int k) const {
        return vertices[static_cast<std::size_t>(triangles[t][static_cast<std::size_t>(k)])];
    }
    /// Arithmetic mean of the lengths of all edges (each triangle's three edges).
    double meanEdgeLength() const;
    /// Axis-aligned bounds of the vertices.
    void bounds(Vec3& lo, Vec3& hi) const;
    /// x ← Rᵀ (x − c): express the vertices in a frame with origin c and axes the columns of R.
    void toFrame(const Vec3& c, const Mat3& R);
};

/// Topological and geometric defects that make a signed distance or mass properties unreliable.
struct MeshDiagnostics {
    std::size_t boundaryEdges = 0;       ///< edges of one triangle only: the mesh is open
    std::size_t nonManifoldEdges = 0;    ///< edges shared by more than two triangles
    std::size_t degenerateTriangles = 0; ///< triangles of zero area (repeated or collinear corners)
    /// Edges whose two triangles run along it in the same direction: their windings disagree.
    std::size_t inconsistentEdges = 0;
    bool clean() const {
        return boundaryEdges == 0 && nonManifoldEdges == 0 && degenerateTriangles == 0 &&
               inconsistentEdges == 0;
    }
};

/// Make the winding consistent and outward: within each edge-connected component, triangles are
/// flipped to agree with their neighbours across two-triangle edges (breadth first from the
/// component's first triangle), then the whole component is flipped if its signed volume is
/// negative (inward). Returns the number of triangles flipped. Mass properties need this; the
/// sign of the distance (winding number) does not.
std::size_t orientOutward(TriangleMesh& mesh);

/// Read a surface with assimp (STL ascii and binary, OBJ, PLY, …): all meshes of the scene are
/// merged, faces triangulated, identical vertices joined (also across meshes) and every
/// coordinate multiplied by `scale`. Points and lines are ignored. Throws std::runtime_error
/// naming the file if it cannot be read or holds no triangle.
TriangleMesh readTriangleMesh(const std::filesystem::path& file, double scale = 1.0);

/// Count boundary, non-manifold and degenerate elements (edges keyed by vertex indices).
MeshDiagnostics diagnose(const TriangleMesh& mesh);

} // namespace mpm::levelset
