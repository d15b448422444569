// SPDX-License-Identifier: GPL-3.0-or-later
#include "levelset/SignedDistance.hpp"

#include "core/Constants.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace mpm::levelset {

namespace {

constexpr int leafSize = 4;
constexpr double fourPi = 4.0 * pi;

/// Closest point to p on segment [a, b].
Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 <= 0.0) return a;
    const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
    return a + t * ab;
}

/// Closest point to p on triangle abc: Ericson, Real-Time Collision Detection §5.1.5 (Voronoi
/// regions of the corners, then of the edges, else the face by barycentric coordinates).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    }
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) { // degenerate (zero-area) triangle: nearest of its edges
        const Vec3 q0 = closestOnSegment(p, a, b), q1 = closestOnSegment(p, b, c),
                   q2 = closestOnSegment(p, c, a);
        const double s0 = (p - q0).squaredNorm(), s1 = (p - q1).squaredNorm(),
                     s2 = (p - q2).squaredNorm();
        return s0 <= s1 && s0 <= s2 ? q0 : (s1 <= s2 ? q1 : q2);
    }
    const double denom = 1.0 / sum;
    return a + ab * (vb * denom) + ac * (vc * denom);
}

/// Solid angle of triangle abc seen from the origin (Van Oosterom & Strackee 1983), signed
/// positive when the triangle's normal (b − a) × (c − a) points away from the origin.
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double det = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    return 2.0 * std::atan2(det, den);
}

} // namespace

SignedDistance::SignedDistance(const TriangleMesh& mesh, double beta) : betaSq_(beta * beta) {
    const int n = static_cast<int>(mesh.triangles.size());
    if (n == 0) throw std::runtime_error("signed distance to an empty mesh");
    std::vector<Vec3> centres(static_cast<std::size_t>(n));
    for (int t = 0; t < n; ++t) {
        const auto ts = static_cast<std::size_t>(t);
        centres[ts] = (mesh.vertex(ts, 0) + mesh.vertex(ts, 1) + mesh.vertex(ts, 2)) / 3.0;
    }
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    a_.resize(order.size());
    b_.resize(order.size());
    c_.resize(order.size());
    // Corners are copied in BVH order once the tree is built; build() needs them first.
    for (std::size_t t = 0; t < order.size(); ++t) {
        a_[t] = mesh.vertex(t, 0);
        b_[t] = mesh.vertex(t, 1);
        c_[t] = mesh.vertex(t, 2);
    }
    nodes_.reserve(2 * order.size() / leafSize + 2);
    build(0, n, order, centres);
    std::vector<Vec3> a(order.size()), b(order.size()), c(order.size());
    for (std::size_t t = 0; t < order.size(); ++t) {
        const auto o = static_cast<std::size_t>(order[t]);
        a[t] = a_[o];
        b[t] = b_[o];
        c[t] = c_[o];
    }
    a_.swap(a);
    b_.swap(b);
    c_.swap(c);
    numVertices_ = static_cast<int>(mesh.vertices.size());
    corners_.resize(order.size());
    for (std::size_t t = 0; t < order.size(); ++t)
        corners_[t] = mesh.triangles[static_cast<std::size_t>(order[t])];
}

int SignedDistance::build(int first, int count, std::vector<int>& order,
                          const std::vector<Vec3>& centres) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Node node{};
    node.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    node.hi = -node.lo;
    Vec3 clo = node.lo, chi = node.hi;
    Vec3 weighted = Vec3::Zero();
    Vec3 areaVector = Vec3::Zero();
    double area = 0.0;
    for (int i = first; i < first + count; ++i) {
        const auto t = static_cast<std::size_t>(order[static_cast<std::size_t>(i)]);
        for (const Vec3* v : {&a_[t], &b_[t], &c_[t]}) {
            node.lo = node.lo.cwiseMin(*v);
            node.hi = node.hi.cwiseMax(*v);
        }
        clo = clo.cwiseMin(centres[t]);
        chi = chi.cwiseMax(centres[t]);
        const Vec3 av = 0.5 * (b_[t] - a_[t]).cross(c_[t] - a_[t]);
        const double ar = av.norm();
        areaVector += av;
        area += ar;
        weighted += ar * centres[t];
    }
    node.areaVector = areaVector;
    node.dipoleCentre = area > 0.0 ? Vec3(weighted / area) : Vec3(0.5 * (node.lo + node.hi));
    node.radiusSq = 0.0;
    for (int i = first; i < first + count; ++i) {
        const auto t = static_cast<std::size_t>(order[static_cast<std::size_t>(i)]);
        for (const Vec3* v : {&a_[t], &b_[t], &c_[t]}) {
            node.radiusSq = std::max(node.radiusSq, (*v - node.dipoleCentre).squaredNorm());
        }
    }
    node.first = first;
    node.count = count;
    node.left = node.right = -1;
    if (count > leafSize) {
        int axis = 0;
        (chi - clo).maxCoeff(&axis);
        const int half = count / 2;
        auto begin = order.begin() + first;
        // Median split; ties broken by index so that the tree is deterministic.
        std::nth_element(begin, begin + half, begin + count, [&](int p, int q) {
            const double cp = centres[static_cast<std::size_t>(p)][axis];
            const double cq = centres[static_cast<std::size_t>(q)][axis];
            return cp < cq || (cp == cq && p < q);
        });
        node.count = 0;
        node.left = build(first, half, order, centres);
        node.right = build(first + half, count - half, order, centres);
    }
    nodes_[static_cast<std::size_t>(id)] = node;
    return id;
}

double SignedDistance::boxDistanceSq(const Node& n, const Vec3& x) {
    const Vec3 d = (n.lo - x).cwiseMax(x - n.hi).cwiseMax(0.0);
    return d.squaredNorm();
}

double SignedDistance::squaredDistance(const Vec3& x, double boundSq) const {
    double best = boundSq;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
        if (boxDistanceSq(n, x) >= best) continue;
        if (n.count > 0) {
            for (int i = n.first; i < n.first + n.count; ++i) {
                const auto t = static_cast<std::size_t>(i);
                const double d2 = (x - closestOnTriangle(x, a_[t], b_[t], c_[t])).squaredNorm();
                best = std::min(best, d2);
            }
            continue;
        }
        const Node& l = nodes_[static_cast<std::size_t>(n.left)];
        const Node& r = nodes_[static_cast<std::size_t>(n.right)];
        const double dl = boxDistanceSq(l, x), dr = boxDistanceSq(r, x);
        // Push the farther child first so that the nearer one is searched first.
        if (dl <= dr) {
            if (dr < best) stack[top++] = n.right;
            if (dl < best) stack[top++] = n.left;
        } else {
            if (dl < best) stack[top++] = n.left;
            if (dr < best) stack[top++] = n.right;
        }
    }
    return best;
}

double SignedDistance::windingNumber(const Vec3& x) const {
    double omega = 0.0;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
        const Vec3 r = n.dipoleCentre - x;
        const double r2 = r.squaredNorm();
        if (r2 > betaSq_ * n.radiusSq) {
            omega += n.areaVector.dot(r) / (r2 * std::sqrt(r2));
        } else if (n.count > 0) {
            for (int i = n.first; i < n.first + n.count; ++i) {
                const auto t = static_cast<std::size_t>(i);
                omega += solidAngle(a_[t] - x, b_[t] - x, c_[t] - x);
            }
        } else {
            stack[top++] = n.left;
            stack[top++] = n.right;
        }
    }
    return omega / fourPi;
}

double SignedDistance::windingNumberExact(const Vec3& x) const {
    double omega = 0.0;
    for (std::size_t t = 0; t < a_.size(); ++t)
        omega += solidAngle(a_[t] - x, b_[t] - x, c_[t] - x);
    return omega / fourPi;
}

double SignedDistance::signedDistance(const Vec3& x) const {
    const double d = std::sqrt(squaredDistance(x));
    return std::abs(windingNumber(x)) > 0.5 ? -d : d;
}

void SignedDistance::evaluate(RegularGrid& grid) const {
    const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
    if (nx <= 0 || ny <= 0 || nz <= 0) throw std::runtime_error("empty level-set grid");
    const std::size_t np = grid.numPoints();
    const double h = grid.spacing;
    const double band = bandWidth * h, bandSq = band * band;
    const double inf = std::numeric_limits<double>::infinity();
    const std::size_t sx = 1, sy = static_cast<std::size_t>(nx),
                      sz = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
    std::vector<double> d2(np, inf); // squared distance to the best triangle found so far
    std::vector<int> tri(np, -1);    // that triangle (BVH order)
    const int nt = static_cast<int>(a_.size());
    auto dist2 = [&](const Vec3& x, int t) {
        const auto ts = static_cast<std::size_t>(t);
        return (x - closestOnTriangle(x, a_[ts], b_[ts], c_[ts])).squaredNorm();
    };

    // (1) Narrow band: every triangle rasterises its box grown by `band`; a node keeps the
    // nearest triangle (the lowest index on ties). Triangles are bucketed by grid plane k and
    // planes run in parallel, each visiting its triangles in ascending order: deterministic.
    struct Range {
        int lo[3], hi[3];
    };
    std::vector<Range> range(static_cast<std::size_t>(nt));
    std::vector<Vec3> centre(static_cast<std::size_t>(nt));
    std::vector<double> radius(static_cast<std::size_t>(nt));
    std::vector<std::size_t> planeStart(static_cast<std::size_t>(nz) + 1, 0);
    for (int t = 0; t < nt; ++t) {
        const auto ts = static_cast<std::size_t>(t);
        const Vec3 lo = a_[ts].cwiseMin(b_[ts]).cwiseMin(c_[ts]);
        const Vec3 hi = a_[ts].cwiseMax(b_[ts]).cwiseMax(c_[ts]);
        Range& r = range[ts];
        for (int d = 0; d < 3; ++d) {
            const double l = std::floor((lo[d] - band - grid.origin[d]) / h);
            const double u = std::ceil((hi[d] + band - grid.origin[d]) / h);
            const double top = grid.dims[static_cast<std::size_t>(d)] - 1;
            r.lo[d] = static_cast<int>(std::clamp(l, 0.0, top + 1.0));
            r.hi[d] = static_cast<int>(std::clamp(u, -1.0, top));
        }
        centre[ts] = (a_[ts] + b_[ts] + c_[ts]) / 3.0;
        radius[ts] = std::sqrt(
            std::max({(a_[ts] - centre[ts]).squaredNorm(), (b_[ts] - centre[ts]).squaredNorm(),
                      (c_[ts] - centre[ts]).squaredNorm()}));
        if (r.lo[0] <= r.hi[0] && r.lo[1] <= r.hi[1] && r.lo[2] <= r.hi[2]) {
            for (int k = r.lo[2]; k <= r.hi[2]; ++k)
                ++planeStart[static_cast<std::size_t>(k) + 1];
        }
    }
    for (int k = 0; k < nz; ++k)
        planeStart[static_cast<std::size_t>(k) + 1] += planeStart[static_cast<std::size_t>(k)];
    std::vector<int> planeTris(planeStart.back());
    {
        std::vector<std::size_t> fill(planeStart.begin(), planeStart.end() - 1);
        for (int t = 0; t < nt; ++t) {
            const Range& r = range[static_cast<std::size_t>(t)];
            if (r.lo[0] > r.hi[0] || r.lo[1] > r.hi[1] || r.lo[2] > r.hi[2]) continue;
            for (int k = r.lo[2]; k <= r.hi[2]; ++k)
                planeTris[fill[static_cast<std::size_t>(k)]++] = t;
        }
    }
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < nz; ++k) {
        for (std::size_t q = planeStart[static_cast<std::size_t>(k)];
             q < planeStart[static_cast<std::size_t>(k) + 1]; ++q) {
            const int t = planeTris[q];
            const auto ts = static_cast<std::size_t>(t);
            const Range& r = range[ts];
            // Only nodes in the ball of radius band + (triangle radius) around the centroid
            // can lie within the band of the triangle (widened slightly against rounding).
            const Vec3& cen = centre[ts];
            const double R = (band + radius[ts]) * (1.0 + 1e-12), R2 = R * R;
            const double dz = grid.origin.z() + h * k - cen.z();
            for (int j = r.lo[1]; j <= r.hi[1]; ++j) {
                const double dy = grid.origin.y() + h * j - cen.y();
                const double rest = R2 - dy * dy - dz * dz;
                if (rest < 0.0) continue;
                const double w = std::sqrt(rest);
                const int ilo = std::max(
                    r.lo[0], static_cast<int>(std::floor((cen.x() - w - grid.origin.x()) / h)));
                const int ihi = std::min(
                    r.hi[0], static_cast<int>(std::ceil((cen.x() + w - grid.origin.x()) / h)));
                for (int i = ilo; i <= ihi; ++i) {
                    const Vec3 x = grid.point(i, j, k);
                    const std::size_t id = grid.index(i, j, k);
                    // The triangle cannot beat the current best: skip (bounding-ball bound).
                    const double c2 = (x - cen).squaredNorm();
                    if (c2 > radius[ts] * radius[ts]) {
                        const double lb = std::sqrt(c2) - radius[ts];
                        if (lb * lb >= d2[id]) continue;
                    }
                    const double e = dist2(x, t);
                    if (e < d2[id]) {
                        d2[id] = e;
                        tri[id] = t;
                    }
                }
            }
        }
    }
    // A grid far from the surface (no node in the band): the exact distance everywhere.
    if (std::none_of(tri.begin(), tri.end(), [](int t) { return t >= 0; })) {
        evaluateExact(grid);
        return;
    }

    // (2) Outside the band (d > band): propagate the nearest triangle's index from the
    // neighbours, recomputing the exact distance to it (Danielsson-style vector propagation,
    // as in Bridson's SDFGen). Passes along x, y, z (forward and backward), each over
    // independent lines in parallel, twice. Nodes within the band are exact and kept.
    auto relax = [&](std::size_t id, std::size_t from, const Vec3& x) {
        const int t = tri[from];
        if (t < 0 || t == tri[id] || d2[id] <= bandSq) return;
        const double e = dist2(x, t);
        if (e < d2[id] || (e == d2[id] && t < tri[id])) {
            d2[id] = e;
            tri[id] = t;
        }
    };
    const long rows = static_cast<long>(ny) * static_cast<long>(nz);
    for (int cycle = 0; cycle < propagationCycles; ++cycle) {
#pragma omp parallel for schedule(static)
        for (long row = 0; row < rows; ++row) {
            const int j = static_cast<int>(row % ny), k = static_cast<int>(row / ny);
            for (int i = 1; i < nx; ++i)
                relax(grid.index(i, j, k), grid.index(i, j, k) - sx, grid.point(i, j, k));
            for (int i = nx - 2; i >= 0; --i)
                relax(grid.index(i, j, k), grid.index(i, j, k) + sx, grid.point(i, j, k));
        }
#pragma omp parallel for schedule(static)
        for (int k = 0; k < nz; ++k) {
            for (int j = 1; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                    relax(grid.index(i, j, k), grid.index(i, j, k) - sy, grid.point(i, j, k));
            for (int j = ny - 2; j >= 0; --j)
                for (int i = 0; i < nx; ++i)
                    relax(grid.index(i, j, k), grid.index(i, j, k) + sy, grid.point(i, j, k));
        }
#pragma omp parallel for schedule(static)
        for (int j = 0; j < ny; ++j) {
            for (int k = 1; k < nz; ++k)
                for (int i = 0; i < nx; ++i)
                    relax(grid.index(i, j, k), grid.index(i, j, k) - sz, grid.point(i, j, k));
            for (int k = nz - 2; k >= 0; --k)
                for (int i = 0; i < nx; ++i)
                    relax(grid.index(i, j, k), grid.index(i, j, k) + sz, grid.point(i, j, k));
        }
    }

    // Local correction (descent over the mesh): a node outside the band moves to a nearer
    // triangle across an edge of its current one while there is one, then tries all triangles
    // sharing a vertex with it, and repeats until none is nearer. Fans of vertices of valence
    // > maxValence (e.g. the poles of a UV sphere) are left out of the vertex step. Each node
    // is independent: deterministic. The result is still the distance to a triangle, an upper
    // bound of d.
    constexpr int maxValence = 32;
    std::vector<int> vStart(static_cast<std::size_t>(numVertices_) + 1, 0), vTris;
    for (const auto& c : corners_)
        for (int v : c)
            ++vStart[static_cast<std::size_t>(v) + 1];
    for (int v = 0; v < numVertices_; ++v)
        vStart[static_cast<std::size_t>(v) + 1] += vStart[static_cast<std::size_t>(v)];
    vTris.resize(static_cast<std::size_t>(vStart.back()));
    {
        std::vector<int> fill(vStart.begin(), vStart.end() - 1);
        for (int t = 0; t < nt; ++t)
            for (int v : corners_[static_cast<std::size_t>(t)])
                vTris[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = t;
    }
    // ring(t): the triangles sharing a vertex with t; the first edgeCount(t) of them share an
    // edge.
    std::vector<int> ringStart(static_cast<std::size_t>(nt) + 1, 0), ring,
        edgeCount(static_cast<std::size_t>(nt), 0);
    ring.reserve(static_cast<std::size_t>(nt) * 13);
    {
        std::vector<int> tmp;
        for (int t = 0; t < nt; ++t) {
            const auto& ct = corners_[static_cast<std::size_t>(t)];
            tmp.clear();
            for (int v : ct) {
                const auto vs = static_cast<std::size_t>(v);
                if (vStart[vs + 1] - vStart[vs] > maxValence) continue;
                for (int q = vStart[vs]; q < vStart[vs + 1]; ++q)
                    if (vTris[static_cast<std::size_t>(q)] != t)
                        tmp.push_back(vTris[static_cast<std::size_t>(q)]);
            }
            std::sort(tmp.begin(), tmp.end());
            tmp.erase(std::unique(tmp.begin(), tmp.end()), tmp.end());
            auto shared = [&](int u) {
                const auto& cu = corners_[static_cast<std::size_t>(u)];
                int n = 0;
                for (int v : ct)
                    n += (cu[0] == v) + (cu[1] == v) + (cu[2] == v);
                return n;
            };
            const auto mid = std::stable_partition(tmp.begin(), tmp.end(),
                                                   [&](int u) { return shared(u) >= 2; });
            edgeCount[static_cast<std::size_t>(t)] = static_cast<int>(mid - tmp.begin());
            ring.insert(ring.end(), tmp.begin(), tmp.end());
            ringStart[static_cast<std::size_t>(t) + 1] = static_cast<int>(ring.size());
        }
    }
#pragma omp parallel for schedule(dynamic, 16)
    for (long row = 0; row < rows; ++row) {
        const int j = static_cast<int>(row % ny), k = static_cast<int>(row / ny);
        for (int i = 0; i < nx; ++i) {
            const std::size_t id = grid.index(i, j, k);
            if (d2[id] <= bandSq) continue;
            const Vec3 x = grid.point(i, j, k);
            int best = tri[id];
            double bestD2 = d2[id];
            auto search = [&](int t, int count) {
                const auto ts = static_cast<std::size_t>(t);
                for (int q = ringStart[ts]; q < ringStart[ts] + count; ++q) {
                    const int u = ring[static_cast<std::size_t>(q)];
                    const double e = dist2(x, u);
                    if (e < bestD2) {
                        bestD2 = e;
                        best = u;
                    }
                }
            };
            for (int step = 0; step < 100000; ++step) {
                const int t = best;
                const auto ts = static_cast<std::size_t>(t);
                search(t, edgeCount[ts]);
                if (best != t) continue;
                search(t, ringStart[ts + 1] - ringStart[ts]);
                if (best == t) break;
            }
            tri[id] = best;
            d2[id] = bestD2;
        }
    }

    // (3) Sign: carried along each row while the distance balls of consecutive nodes cover the
    // segment between them (d_i + d_{i+1} > h: no surface crossed; the values outside the band
    // are upper bounds, but there the true distance exceeds the band ≥ h), else the winding
    // number. The first node of a row takes its sign along the column i = 0 the same way.
    // The test has a relative margin: a face exactly halfway between two nodes gives
    // d_i + d_{i+1} = h, which rounding must not turn into "covered".
    const double cover = h * (1.0 + 1e-6);
    grid.values.resize(np);
    std::vector<double> d(np);
#pragma omp parallel for schedule(static)
    for (long row = 0; row < rows; ++row) {
        const std::size_t base = static_cast<std::size_t>(row) * sy;
        for (int i = 0; i < nx; ++i)
            d[base + static_cast<std::size_t>(i)] =
                std::sqrt(d2[base + static_cast<std::size_t>(i)]);
    }
    auto insideSign = [&](const Vec3& x) { return std::abs(windingNumber(x)) > 0.5 ? -1.0 : 1.0; };
    std::vector<double> firstSign(static_cast<std::size_t>(rows));
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < nz; ++k) {
        double prevSign = 1.0;
        for (int j = 0; j < ny; ++j) {
            const std::size_t id = grid.index(0, j, k);
            const bool carry = j > 0 && d[id - sy] + d[id] > cover;
            prevSign = carry ? prevSign : insideSign(grid.point(0, j, k));
            firstSign[static_cast<std::size_t>(j) +
                      static_cast<std::size_t>(ny) * static_cast<std::size_t>(k)] = prevSign;
        }
    }
#pragma omp parallel for schedule(dynamic, 16)
    for (long row = 0; row < rows; ++row) {
        const int j = static_cast<int>(row % ny), k = static_cast<int>(row / ny);
        double sign = firstSign[static_cast<std::size_t>(row)];
        for (int i = 0; i < nx; ++i) {
            const std::size_t id = grid.index(i, j, k);
            if (i > 0 && !(d[id - sx] + d[id] > cover)) sign = insideSign(grid.point(i, j, k));
            grid.values[id] = sign * d[id];
        }
    }
}

void SignedDistance::evaluateExact(RegularGrid& grid) const {
    const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
    if (nx <= 0 || ny <= 0 || nz <= 0) throw std::runtime_error("empty level-set grid");
    grid.values.assign(grid.numPoints(), 0.0);
    const double h = grid.spacing;
    const long rows = static_cast<long>(ny) * static_cast<long>(nz);
#pragma omp parallel for schedule(dynamic, 1)
    for (long row = 0; row < rows; ++row) {
        const int j = static_cast<int>(row % ny);
        const int k = static_cast<int>(row / ny);
        double prevD = -1.0;
        double prevSign = 1.0;
        for (int i = 0; i < nx; ++i) {
            const Vec3 x = grid.point(i, j, k);
            // |φ| is 1-Lipschitz: d_i ≤ d_{i−1} + h bounds the search (slightly widened).
            const double bound = prevD >= 0.0 ? (prevD + h) * (1.0 + 1e-9) + 1e-300
                                              : std::numeric_limits<double>::infinity();
            const double d = std::sqrt(squaredDistance(x, bound * bound));
            double sign;
            if (prevD >= 0.0 && prevD + d > h * (1.0 + 1e-6)) { // margin: see evaluate()
                sign = prevSign; // the balls of radius d cover the segment: no surface crossed
            } else {
                sign = std::abs(windingNumber(x)) > 0.5 ? -1.0 : 1.0;
            }
            grid.values[grid.index(i, j, k)] = sign * d;
            prevD = d;
            prevSign = sign;
        }
    }
}

} // namespace mpm::levelset
