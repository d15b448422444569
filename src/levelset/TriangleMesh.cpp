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
#include <tuple>
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
    std::vector<std::tuple<int, int, int>> directed; // (min, max, 1 if it runs min → max)
    directed.reserve(3 * mesh.triangles.size());
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
            if (a != b) directed.emplace_back(std::min(a, b), std::max(a, b), a < b ? 1 : 0);
        }
    }
    std::sort(directed.begin(), directed.end());
    for (std::size_t i = 0; i < directed.size();) {
        std::size_t j = i;
        const auto key = [&](std::size_t k) {
            return std::make_pair(std::get<0>(directed[k]), std::get<1>(directed[k]));
        };
        while (j < directed.size() && key(j) == key(i))
            ++j;
        if (j - i == 1)
            ++d.boundaryEdges;
        else if (j - i > 2)
            ++d.nonManifoldEdges;
        else if (std::get<2>(directed[i]) == std::get<2>(directed[i + 1]))
            ++d.inconsistentEdges;
        i = j;
    }
    return d;
}

std::size_t orientOutward(TriangleMesh& mesh) {
    const std::size_t n = mesh.triangles.size();
    // Two-triangle edges: (a, b, triangle) sorted, pairs of equal (a, b) are neighbours.
    std::vector<std::tuple<int, int, std::size_t>> edges;
    edges.reserve(3 * n);
    for (std::size_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.triangles[t][static_cast<std::size_t>(k)];
            const int b = mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
            if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b), t);
        }
    std::sort(edges.begin(), edges.end());
    std::vector<std::vector<std::size_t>> neighbours(n);
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
               std::get<1>(edges[j]) == std::get<1>(edges[i]))
            ++j;
        if (j - i == 2) {
            neighbours[std::get<2>(edges[i])].push_back(std::get<2>(edges[i + 1]));
            neighbours[std::get<2>(edges[i + 1])].push_back(std::get<2>(edges[i]));
        }
        i = j;
    }
    // +1 if triangle t runs along a→b.
    const auto direction = [&](std::size_t t, int a, int b) {
        const auto& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k)
            if (tri[static_cast<std::size_t>(k)] == a &&
                tri[static_cast<std::size_t>((k + 1) % 3)] == b)
                return 1;
        return -1;
    };
    std::vector<char> seen(n, 0), flipped(n, 0);
    for (std::size_t seed = 0; seed < n; ++seed) {
        if (seen[seed]) continue;
        std::vector<std::size_t> component{seed};
        seen[seed] = 1;
        for (std::size_t q = 0; q < component.size(); ++q) {
            const std::size_t t = component[q];
            for (const std::size_t u : neighbours[t]) {
                if (seen[u]) continue;
                seen[u] = 1;
                // The shared edge: t and u must run along it in opposite directions.
                const auto& tt = mesh.triangles[t];
                for (int k = 0; k < 3; ++k) {
                    const int a = tt[static_cast<std::size_t>(k)];
                    const int b = tt[static_cast<std::size_t>((k + 1) % 3)];
                    const auto& tu = mesh.triangles[u];
                    const bool shared = (tu[0] == a || tu[1] == a || tu[2] == a) &&
                                        (tu[0] == b || tu[1] == b || tu[2] == b);
                    if (!shared || a == b) continue;
                    if (direction(u, a, b) == 1) {
                        std::swap(mesh.triangles[u][1], mesh.triangles[u][2]);
                        flipped[u] ^= 1;
                    }
                    break;
                }
                component.push_back(u);
            }
        }
        double volume = 0.0; // 6 V = Σ a · (b × c)
        for (const std::size_t t : component)
            volume += mesh.vertex(t, 0).dot(mesh.vertex(t, 1).cross(mesh.vertex(t, 2)));
        if (volume < 0.0) {
            for (const std::size_t t : component) {
                std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
                flipped[t] ^= 1;
            }
        }
    }
    return static_cast<std::size_t>(std::count(flipped.begin(), flipped.end(), 1));
}

} // namespace mpm::levelset
