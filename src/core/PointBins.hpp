// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Neighbourhood.hpp"
#include "core/Types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace mpm {

/// Point indices binned in cubic cells over a box, stored compressed (CSR: each cell's first slot
/// in `start`, then the point indices cell by cell, ascending within a cell). A query x walks the
/// (2 ring + 1)^dim block of cells around x's cell, which holds every point within
/// ring · cellSize() of x. Points and queries outside the box fall in its border cells; the
/// block stays complete because clamping a cell index to the box never moves it away from a
/// cell inside.
///
/// The cell side is the requested minCell, or larger where the box would otherwise need more
/// than about 8 cells a point: larger cells keep every block complete and only cost time, and
/// they bound the memory when a tiny radius meets a wide spread of points.
template <int dim> class PointBins {
public:
    using Box = Eigen::AlignedBox<double, dim>;

    /// Bin `points` over their own bounds.
    PointBins(const std::vector<Vec<dim>>& points, double minCell)
        : PointBins(points, minCell, boundsOf(points)) {}

    /// Bin `points` over `box` (the cells of an empty box are one).
    PointBins(const std::vector<Vec<dim>>& points, double minCell, const Box& box) {
        if (!(minCell > 0.0) || !std::isfinite(minCell))
            throw std::invalid_argument("PointBins: the cell size must be positive and finite");
        origin_ = box.isEmpty() ? Vec<dim>::Zero() : box.min();
        const Vec<dim> extent = box.isEmpty() ? Vec<dim>::Zero() : Vec<dim>(box.sizes());
        const double budget = 8.0 * static_cast<double>(std::max<std::size_t>(points.size(), 1));
        cell_ = minCell;
        while (cellCountFor(extent, cell_) > budget)
            cell_ *= 2.0;
        std::size_t cellCount = 1;
        for (int d = 0; d < dim; ++d) {
            cells_[d] = std::max(1, static_cast<int>(std::ceil(extent[d] / cell_)));
            cellCount *= static_cast<std::size_t>(cells_[d]);
        }
        const std::size_t n = points.size();
        start_.assign(cellCount + 1, 0);
        std::vector<std::size_t> cellIndex(n);
        for (std::size_t i = 0; i < n; ++i)
            ++start_[(cellIndex[i] = linear(cellOf(points[i]))) + 1];
        for (std::size_t k = 0; k < cellCount; ++k)
            start_[k + 1] += start_[k];
        members_.resize(n);
        std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            members_[fill[cellIndex[i]]++] = i;
    }

    /// The cell side actually used, ≥ the requested one [m].
    [[nodiscard]] double cellSize() const { return cell_; }

    /// The cell of x, clamped to the box.
    [[nodiscard]] IVec<dim> cellOf(const Vec<dim>& x) const {
        IVec<dim> c;
        for (int d = 0; d < dim; ++d) {
            const double s = std::floor((x[d] - origin_[d]) / cell_);
            c[d] = !(s >= 0.0) ? 0 : (s >= cells_[d] ? cells_[d] - 1 : static_cast<int>(s));
        }
        return c;
    }

    /// f(j) for every point j in the block of `ring` cells around x's cell, cell by cell (first
    /// axis fastest), ascending j within a cell.
    template <class F> void forEachNear(const Vec<dim>& x, int ring, F&& f) const {
        visit(x, ring, [&](std::size_t j) {
            f(j);
            return false;
        });
    }

    /// Whether pred(j) holds for some point j of x's block; stops at the first that does.
    template <class P> [[nodiscard]] bool anyNear(const Vec<dim>& x, int ring, P&& pred) const {
        return visit(x, ring, pred);
    }

private:
    static Box boundsOf(const std::vector<Vec<dim>>& points) {
        Box box;
        for (const auto& x : points)
            box.extend(x);
        return box;
    }

    static double cellCountFor(const Vec<dim>& extent, double cell) {
        double count = 1.0;
        for (int d = 0; d < dim; ++d)
            count *= std::max(1.0, std::ceil(extent[d] / cell));
        return count;
    }

    [[nodiscard]] std::size_t linear(const IVec<dim>& c) const {
        std::size_t k = 0;
        for (int d = dim - 1; d >= 0; --d)
            k = k * static_cast<std::size_t>(cells_[d]) + static_cast<std::size_t>(c[d]);
        return k;
    }

    /// stop(j) for the block's points in order until one returns true; whether one did.
    template <class S> bool visit(const Vec<dim>& x, int ring, S&& stop) const {
        const IVec<dim> c = cellOf(x);
        IVec<dim> lo;
        IVec<dim> hi;
        for (int d = 0; d < dim; ++d) {
            lo[d] = std::max(0, c[d] - ring);
            hi[d] = std::min(cells_[d] - 1, c[d] + ring);
        }
        bool stopped = false;
        forEachIndex<dim>(lo, hi, [&](const IVec<dim>& b) {
            if (stopped) return;
            const std::size_t k = linear(b);
            for (std::size_t m = start_[k]; m < start_[k + 1] && !stopped; ++m)
                stopped = stop(members_[m]);
        });
        return stopped;
    }

    Vec<dim> origin_;
    IVec<dim> cells_;
    double cell_ = 0.0;
    std::vector<std::size_t> start_;
    std::vector<std::size_t> members_;
};

} // namespace mpm
