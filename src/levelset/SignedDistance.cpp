// SPDX-License-Identifier: GPL-3.0-or-later
#include "levelset/SignedDistance.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mpm::levelset {

namespace {

constexpr int leafSize = 4;
constexpr double fourPi = 12.566370614359172954;

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
            if (prevD >= 0.0 && prevD + d > h) {
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
