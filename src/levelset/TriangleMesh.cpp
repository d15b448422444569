// SPDX-License-Identifier: GPL-3.0-or-later
#include "levelset/TriangleMesh.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace mpm::levelset {

double TriangleMesh::meanEdgeLength() const {
    if (triangles.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k)
            sum += (vertex(t, (k + 1) % 3) - vertex(t, k)).norm();
    }
    return sum / (3.0 * static_cast<double>(triangles.size()));
}

void TriangleMesh::bounds(Vec3& lo, Vec3& hi) const {
    lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (const Vec3& v : vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
}

void TriangleMesh::toFrame(const Vec3& c, const Mat3& R) {
    for (Vec3& v : vertices)
        v = R.transpose() * (v - c);
}

TriangleMesh readTriangleMesh(const std::filesystem::path& file, double scale) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        throw std::runtime_error("cannot read surface " + name + ": no such file");
    }
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* scene = importer.ReadFile(
        name, aiProcess_JoinIdenticalVertices | aiProcess_Triangulate | aiProcess_SortByPType);
    if (scene == nullptr) {
        throw std::runtime_error("cannot read surface " + name + ": " + importer.GetErrorString());
    }

    // Join identical vertices across meshes too (assimp joins them within one mesh only).
    TriangleMesh mesh;
    std::map<std::array<double, 3>, int> index;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* am = scene->mMeshes[m];
        std::vector<int> local(am->mNumVertices);
        for (unsigned v = 0; v < am->mNumVertices; ++v) {
            const aiVector3D& p = am->mVertices[v];
            const std::array<double, 3> key{scale * static_cast<double>(p.x),
                                            scale * static_cast<double>(p.y),
                                            scale * static_cast<double>(p.z)};
            auto [it, inserted] = index.emplace(key, static_cast<int>(mesh.vertices.size()));
            if (inserted) mesh.vertices.emplace_back(key[0], key[1], key[2]);
            local[v] = it->second;
        }
        for (unsigned f = 0; f < am->mNumFaces; ++f) {
            const aiFace& face = am->mFaces[f];
            if (face.mNumIndices != 3) continue;
            mesh.triangles.push_back(
                {local[face.mIndices[0]], local[face.mIndices[1]], local[face.mIndices[2]]});
        }
    }
    if (mesh.triangles.empty()) {
        throw std::runtime_error("cannot read surface " + name + ": no triangles");
    }
    return mesh;
}

MeshDiagnostics diagnose(const TriangleMesh& mesh) {
    MeshDiagnostics d;
    std::vector<std::pair<int, int>> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const Vec3 n =
            (mesh.vertex(t, 1) - mesh.vertex(t, 0)).cross(mesh.vertex(t, 2) - mesh.vertex(t, 0));
        const double scale = std::max({(mesh.vertex(t, 1) - mesh.vertex(t, 0)).squaredNorm(),
                                       (mesh.vertex(t, 2) - mesh.vertex(t, 0)).squaredNorm(),
                                       (mesh.vertex(t, 2) - mesh.vertex(t, 1)).squaredNorm()});
        // Zero area relative to the longest edge (1e-24 ≈ round-off of squared quantities).
        if (n.squaredNorm() <= 1e-24 * scale * scale) ++d.degenerateTriangles;
        for (int k = 0; k < 3; ++k) {
            const int a = tri[static_cast<std::size_t>(k)];
            const int b = tri[static_cast<std::size_t>((k + 1) % 3)];
            if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i])
            ++j;
        if (j - i == 1)
            ++d.boundaryEdges;
        else if (j - i > 2)
            ++d.nonManifoldEdges;
        i = j;
    }
    return d;
}

} // namespace mpm::levelset
