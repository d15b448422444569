// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/Splitting.hpp"

#include "core/Parallel.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace mpm {

namespace {

/// The domain D = F S of point i; `s` stores S − 1 (zero for a point as seeded).
template <int dim> Mat<dim> domainOf(const Particles<dim>& p, const std::vector<Mat3>& s, Index i) {
    return p.F[i] * (Mat<dim>::Identity() + s[i].template topLeftCorner<dim, dim>());
}

/// (σ², m): the largest eigenvalue of Dᵀ D and its unit eigenvector.
template <int dim> std::pair<double, Vec<dim>> largestStretch(const Mat<dim>& d) {
    Eigen::SelfAdjointEigenSolver<Mat<dim>> es;
    es.computeDirect(d.transpose() * d);
    return {es.eigenvalues()(dim - 1), es.eigenvectors().col(dim - 1).normalized()};
}

} // namespace

template <int dim>
std::unique_ptr<ParticleSplitting<dim>>
ParticleSplitting<dim>::create(const Dictionary& schemes, bool granular, Particles<dim>& p) {
    if (!schemes.has("splitting")) {
        if (!granular) return nullptr;
        auto s = std::make_unique<ParticleSplitting>(GranularMaxStretch, p);
        s->byDefault_ = true;
        return s;
    }
    if (!schemes.isDict("splitting")) {
        const std::string w = schemes.getString("splitting");
        if (w == "off" || w == "false" || w == "no") return nullptr;
        schemes.error("splitting",
                      "expected off or a map, e.g. splitting: {maxStretch: 4}; got '" + w + "'");
    }
    const Dictionary sd = schemes.subDict("splitting");
    auto s = std::make_unique<ParticleSplitting>(
        sd.getScalar("maxStretch",
                     Bounds{1.0, std::numeric_limits<double>::infinity(), false, true}),
        p);
    sd.checkUnknownKeys();
    return s;
}

template <int dim>
ParticleSplitting<dim>::ParticleSplitting(double maxStretch, Particles<dim>& p)
    : maxStretch_(maxStretch), domain_(p.addTensor(FieldInfo{"splitDomain"})),
      level_(p.addFlag(FieldInfo{"splitLevel"})) {
    assert(maxStretch > 1.0 && "ParticleSplitting: maxStretch must exceed 1");
}

template <int dim>
Index ParticleSplitting<dim>::apply(Particles<dim>& p, const Comm& comm, double cellSize,
                                    const int* nearBody) {
    const Index n = static_cast<Index>(p.size());
    const std::vector<Mat3>& s = p.tensor(domain_);
    const std::vector<int>& level = p.flag(level_);
    const double limit2 = maxStretch_ * maxStretch_;
    split_.assign(p.size(), 0);
    Index count = 0;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(+ : count)
    for (Index i = 0; i < n; ++i) {
        // σ² ≤ |D|², so most points are passed over without an eigen-solve; a point never
        // split has S = 1, D = F, and is passed over without reading S.
        const double norm2 = level[i] == 0 ? p.F[i].squaredNorm() : domainOf(p, s, i).squaredNorm();
        if (norm2 <= limit2 || level[i] >= MaxLevel || (nearBody != nullptr && nearBody[i] != 0))
            continue;
        const double sigma2 = largestStretch<dim>(domainOf(p, s, i)).first;
        // The children land σ a/4 away: at most a cell (σ² a² ≤ 16 h²).
        const double side2 = std::pow(std::ldexp(p.volume0[i], level[i]), 2.0 / dim);
        if (sigma2 > limit2 && sigma2 * side2 <= 16.0 * cellSize * cellSize) {
            split_[i] = 1;
            ++count;
        }
    }
    // The children's ids: the largest id + 1 on, in rank order, then index order.
    Index before = 0, total = count;
    if (comm.parallel()) {
        const std::vector<Index> counts = comm.gather(count);
        total = 0;
        for (int r = 0; r < comm.size(); ++r) {
            if (r < comm.rank()) before += counts[static_cast<std::size_t>(r)];
            total += counts[static_cast<std::size_t>(r)];
        }
    }
    if (total == 0) return 0; // the same on every rank: no rank waits below
    Index maxId = n > 0 ? *std::max_element(p.id.begin(), p.id.end()) : -1;
    if (comm.parallel())
        for (const Index m : comm.gather(maxId))
            maxId = std::max(maxId, m);
    std::vector<Index> parents;
    parents.reserve(static_cast<std::size_t>(count));
    for (Index i = 0; i < n; ++i)
        if (split_[i]) parents.push_back(i);
    // Every field of a child starts as its parent's.
    p.forEachArray([&](auto& a) {
        a.resize(static_cast<std::size_t>(n + count));
        for (std::size_t k = 0; k < parents.size(); ++k)
            a[static_cast<std::size_t>(n) + k] = a[static_cast<std::size_t>(parents[k])];
    });
    std::vector<Mat3>& sw = p.tensor(domain_);
    std::vector<int>& lw = p.flag(level_);
    for (std::size_t k = 0; k < parents.size(); ++k) {
        const Index i = parents[k], j = n + static_cast<Index>(k);
        const Mat<dim> d = domainOf(p, sw, i);
        const auto [sigma2, m] = largestStretch<dim>(d);
        const double sigma = std::sqrt(sigma2);
        const Vec<dim> u = d * m / sigma;
        const double side = std::pow(std::ldexp(p.volume0[i], lw[i]), 1.0 / dim);
        const Vec<dim> offset = 0.25 * sigma * side * u;
        // S ← S (1 − ½ m mᵀ), stored as S − 1.
        Mat3 halve = Mat3::Zero();
        halve.template topLeftCorner<dim, dim>() = 0.5 * m * m.transpose();
        const Mat3 sNew = sw[i] - (Mat3::Identity() + sw[i]) * halve;
        for (const Index c : {i, j}) {
            p.mass[c] *= 0.5;
            p.volume[c] *= 0.5;
            p.volume0[c] *= 0.5;
            sw[c] = sNew;
            lw[c] += 1;
        }
        p.x[i] -= offset;
        p.x[j] += offset;
        p.id[j] = maxId + 1 + before + static_cast<Index>(k);
    }
    return total;
}

template class ParticleSplitting<2>;
template class ParticleSplitting<3>;

} // namespace mpm
