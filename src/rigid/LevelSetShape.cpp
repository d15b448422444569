// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/LevelSetShape.hpp"

#include "kernels/Kernels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace mpm {

namespace {

/// Quadratic B-spline weights along one axis at xh (grid units, in [0, n − 1]) with the ghost
/// node folded in: the stencil's node −1 or n is a linear extrapolation of the two nodes inside,
/// so its weight w goes to them as +2w (nearest) and −w (next). idx are valid node indices.
void axisWeights(double xh, int n, std::array<int, 3>& idx, std::array<double, 3>& w,
                 std::array<double, 3>& dw) {
    xh = std::clamp(xh, 0.0, static_cast<double>(n - 1));
    double wk[3], dwk[3];
    const int base = QuadraticBSplineKernel{}.eval(xh, wk, dwk);
    for (int k = 0; k < 3; ++k) {
        idx[k] = base + k;
        w[k] = wk[k];
        dw[k] = dwk[k];
    }
    if (base < 0) { // node −1: φ_{-1} = 2φ_0 − φ_1 (stencil −1, 0, 1)
        w[1] += 2.0 * w[0];
        w[2] -= w[0];
        dw[1] += 2.0 * dw[0];
        dw[2] -= dw[0];
        idx[0] = 0;
        w[0] = dw[0] = 0.0;
    }
    if (base + 2 > n - 1) { // node n: φ_n = 2φ_{n-1} − φ_{n-2} (stencil n − 2, n − 1, n)
        w[1] += 2.0 * w[2];
        w[0] -= w[2];
        dw[1] += 2.0 * dw[2];
        dw[0] -= dw[2];
        idx[2] = n - 1;
        w[2] = dw[2] = 0.0;
    }
}

[[noreturn]] void bad(const std::string& why) {
    throw std::runtime_error(why);
}

} // namespace

LevelSetShape::LevelSetShape(const Dictionary& dict) {
    const std::string name = dict.getString("file");
    // Relative paths are taken from the case directory (Dictionary::getPath).
    const std::filesystem::path path = dict.getPath("file");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        dict.error("file", "level-set file '" + name + "' not found (tried " + path.string() +
                               "; run surfaceToLevelSet -case <case> first)");
    dict.checkUnknownKeys();
    try {
        ls_ = levelset::readVti(path);
        setup();
    } catch (const std::runtime_error& e) {
        dict.error("file", e.what());
    }
}

LevelSetShape::LevelSetShape(levelset::LevelSet levelSet) : ls_(std::move(levelSet)) {
    setup();
}

void LevelSetShape::setup() {
    const auto& g = ls_.grid;
    for (int d = 0; d < 3; ++d) {
        if (g.dims[d] < 2) bad("the level-set grid needs at least 2 nodes along every axis");
    }
    if (!(g.spacing > 0.0)) bad("the level-set grid spacing must be > 0");
    if (g.values.size() != g.numPoints()) bad("phi does not match the grid dimensions");
    if (!(ls_.volume > 0.0)) bad("the level set's volume must be > 0");
    if (std::none_of(g.values.begin(), g.values.end(), [](double v) { return v < 0.0; })) {
        bad("no grid node is inside the body (phi < 0)");
    }
    lo_ = g.origin;
    hi_ = g.origin + g.spacing * Vec3(g.dims[0] - 1, g.dims[1] - 1, g.dims[2] - 1);
    boundingRadius_ = 0.0;
    for (int c = 0; c < 8; ++c) {
        const Vec3 corner((c & 1) ? hi_[0] : lo_[0], (c & 2) ? hi_[1] : lo_[1],
                          (c & 4) ? hi_[2] : lo_[2]);
        boundingRadius_ = std::max(boundingRadius_, corner.norm());
    }
    buildSurface();
}

double LevelSetShape::interpolate(const Vec3& x, Vec3& gradient) const {
    const auto& g = ls_.grid;
    const double invH = 1.0 / g.spacing;
    std::array<std::array<int, 3>, 3> idx;
    std::array<std::array<double, 3>, 3> w, dw;
    for (int d = 0; d < 3; ++d) {
        axisWeights((x[d] - g.origin[d]) * invH, g.dims[d], idx[d], w[d], dw[d]);
    }
    double phi = 0.0;
    Vec3 grad = Vec3::Zero();
    for (int c = 0; c < 3; ++c) {
        for (int b = 0; b < 3; ++b) {
            for (int a = 0; a < 3; ++a) {
                const double v = g.values[g.index(idx[0][a], idx[1][b], idx[2][c])];
                phi += w[0][a] * w[1][b] * w[2][c] * v;
                grad[0] += dw[0][a] * w[1][b] * w[2][c] * v;
                grad[1] += w[0][a] * dw[1][b] * w[2][c] * v;
                grad[2] += w[0][a] * w[1][b] * dw[2][c] * v;
            }
        }
    }
    gradient = grad * invH;
    return phi;
}

double LevelSetShape::distance(const Vec3& x, Vec3& normal) const {
    const Vec3 p = x.cwiseMax(lo_).cwiseMin(hi_);
    Vec3 grad;
    double phi = interpolate(p, grad);
    const Vec3 r = x - p;
    const double out = r.norm();
    if (out > 0.0) { // outside the grid box: φ(p) + |x − p|
        phi += out;
        for (int d = 0; d < 3; ++d) {
            if (r[d] != 0.0) grad[d] = r[d] / out;
        }
    }
    const double gn = grad.norm();
    normal = gn > 0.0 ? Vec3(grad / gn) : Vec3::UnitX(); // |∇φ| = 0: no preferred direction
    return phi;
}

void LevelSetShape::surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const {
    points = surfacePoints_;
    cells = surfaceCells_;
}

void LevelSetShape::buildSurface() {
    surfacePoints_.clear();
    surfaceCells_.clear();
    const auto& g = ls_.grid;
    // Kuhn triangulation of the cube (corner c at offset (c&1, c&2, c&4)): one tetrahedron per
    // axis order, 0 → e_a → e_a + e_b → 7; all share the diagonal 0–7.
    static constexpr int tets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                       {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
    std::unordered_map<std::uint64_t, int> edgeVertex; // (node a, node b), a < b → point
    const auto total = static_cast<std::uint64_t>(g.numPoints());
    const auto vertexOn = [&](std::size_t a, std::size_t b, const Vec3& xa, const Vec3& xb,
                              double pa, double pb) {
        // A node with φ = 0 exactly is the vertex itself, shared by all its edges.
        if (pa == 0.0) b = a;
        if (pb == 0.0) a = b;
        if (a > b) std::swap(a, b);
        const std::uint64_t key = static_cast<std::uint64_t>(a) * total + b;
        const auto it = edgeVertex.find(key);
        if (it != edgeVertex.end()) return it->second;
        const double t = pa / (pa - pb);
        surfacePoints_.push_back(xa + t * (xb - xa));
        const int id = static_cast<int>(surfacePoints_.size()) - 1;
        edgeVertex.emplace(key, id);
        return id;
    };
    for (int k = 0; k + 1 < g.dims[2]; ++k) {
        for (int j = 0; j + 1 < g.dims[1]; ++j) {
            for (int i = 0; i + 1 < g.dims[0]; ++i) {
                std::array<std::size_t, 8> node;
                std::array<double, 8> phi;
                bool anyIn = false, anyOut = false;
                for (int c = 0; c < 8; ++c) {
                    node[c] = g.index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                    phi[c] = g.values[node[c]];
                    (phi[c] < 0.0 ? anyIn : anyOut) = true;
                }
                if (!anyIn || !anyOut) continue;
                for (const auto& tet : tets) {
                    Vec3 x[4];
                    double p[4];
                    std::size_t n[4];
                    int in[4], out[4], nIn = 0, nOut = 0;
                    for (int v = 0; v < 4; ++v) {
                        const int c = tet[v];
                        x[v] = g.point(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                        p[v] = phi[c];
                        n[v] = node[c];
                        if (p[v] < 0.0) {
                            in[nIn++] = v;
                        } else {
                            out[nOut++] = v;
                        }
                    }
                    if (nIn == 0 || nOut == 0) continue;
                    // ∇φ of the linear interpolant in the tetrahedron: the outward direction.
                    Mat3 m;
                    Vec3 dp;
                    for (int r = 0; r < 3; ++r) {
                        m.row(r) = (x[r + 1] - x[0]).transpose();
                        dp[r] = p[r + 1] - p[0];
                    }
                    const Vec3 grad = m.inverse() * dp;
                    const auto edge = [&](int a, int b) {
                        return vertexOn(n[a], n[b], x[a], x[b], p[a], p[b]);
                    };
                    const auto emit = [&](int a, int b, int c) {
                        const Vec3 nrm = (surfacePoints_[b] - surfacePoints_[a])
                                             .cross(surfacePoints_[c] - surfacePoints_[a]);
                        if (nrm.dot(grad) < 0.0) std::swap(b, c);
                        if (a != b && b != c && a != c) surfaceCells_.push_back({a, b, c});
                    };
                    if (nIn == 1 || nIn == 3) {
                        // One vertex alone on its side: a triangle on its three edges.
                        const int lone = nIn == 1 ? in[0] : out[0];
                        const int* others = nIn == 1 ? out : in;
                        emit(edge(lone, others[0]), edge(lone, others[1]), edge(lone, others[2]));
                    } else {
                        // Two and two: the quad on edges (i0,o0), (i0,o1), (i1,o1), (i1,o0).
                        const int q0 = edge(in[0], out[0]), q1 = edge(in[0], out[1]),
                                  q2 = edge(in[1], out[1]), q3 = edge(in[1], out[0]);
                        emit(q0, q1, q2);
                        emit(q0, q2, q3);
                    }
                }
            }
        }
    }
}

MPM_REGISTER_ONLY(3, ShapeRegistry, LevelSetShape, "levelSet");
MPM_SCHEMA("shapes", "levelSet",
           {"any closed mesh, through a level set",
            {{"file", "string", "-", "required",
              "the .vti written by surfaceToLevelSet (relative to the case)"}},
            "{type: levelSet, file: constant/levelSets/rock.vti}",
            "in 2D use 'disk', 'box' or another 2D shape"});

} // namespace mpm
