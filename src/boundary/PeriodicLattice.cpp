// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/PeriodicLattice.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

template <int dim>
PeriodicLattice<dim>::PeriodicLattice(const Grid<dim>& grid, const std::array<bool, dim>& periodic)
    : grid_(grid), n_(grid.nodes()), periodic_(periodic), lo_(grid.lo()), hi_(grid.hi()),
      period_(Vec<dim>::Zero()), nb_(grid.blocks()) {
    constexpr int pad = Grid<dim>::Pad;
    constexpr int bs = Grid<dim>::BlockSize;
    for (int d = 0; d < dim; ++d) {
        cells_[d] = n_[d] - 1 - 2 * pad;
        if (periodic_[d]) period_[d] = hi_[d] - lo_[d];
        any_ |= periodic_[d];
    }
    if (!any_) return;

    // Blocks along each axis whose nodes share a class.
    for (int d = 0; d < dim; ++d) {
        related_[d].resize(nb_[d]);
        for (int c = 0; c < nb_[d]; ++c) {
            std::vector<int>& r = related_[d][c];
            r.push_back(c);
            if (!periodic_[d]) continue;
            for (int i = c * bs; i < std::min((c + 1) * bs, n_[d]); ++i) {
                const int o = ownerCoord(d, i);
                for (int j = o; j >= 0; j -= cells_[d])
                    r.push_back(j / bs);
                for (int j = o + cells_[d]; j < n_[d]; j += cells_[d])
                    r.push_back(j / bs);
            }
            std::sort(r.begin(), r.end());
            r.erase(std::unique(r.begin(), r.end()), r.end());
        }
    }

    // Image nodes grouped by block (counting sort), ascending within a block.
    const Index numBlocks = grid.numBlocks();
    auto blockOfNode = [&](const IVec<dim>& c) {
        Index b = 0;
        for (int d = dim - 1; d >= 0; --d)
            b = b * nb_[d] + c[d] / bs;
        return b;
    };
    imageStart_.assign(numBlocks + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<Index> next;
        if (pass == 1) {
            for (Index b = 0; b < numBlocks; ++b)
                imageStart_[b + 1] += imageStart_[b];
            images_.resize(imageStart_[numBlocks]);
            owners_.resize(imageStart_[numBlocks]);
            next.assign(imageStart_.begin(), imageStart_.end() - 1);
        }
        IVec<dim> c = IVec<dim>::Zero();
        for (Index f = 0; f < grid.numFileNodes(); ++f) { // x fastest
            bool image = false;
            IVec<dim> oc;
            for (int d = 0; d < dim; ++d) {
                oc[d] = ownerCoord(d, c[d]);
                image |= oc[d] != c[d];
            }
            if (image) {
                const Index k = grid.nodeIndex(c), o = grid.nodeIndex(oc);
                const Index b = blockOfNode(c);
                if (pass == 0) {
                    ++imageStart_[b + 1];
                } else {
                    images_[next[b]] = k;
                    owners_[next[b]++] = o;
                }
            }
            for (int d = 0; d < dim && ++c[d] == n_[d]; ++d)
                c[d] = 0;
        }
    }
    mark_.assign(numBlocks, 0);
}

template <int dim> int PeriodicLattice<dim>::ownerCoord(int axis, int i) const {
    if (!periodic_[axis]) return i;
    constexpr int pad = Grid<dim>::Pad;
    const int cells = cells_[axis];
    return pad + ((i - pad) % cells + cells) % cells;
}

template <int dim> Index PeriodicLattice<dim>::owner(Index k) const {
    IVec<dim> c = grid_.nodeCoord(k);
    for (int d = 0; d < dim; ++d)
        c[d] = ownerCoord(d, c[d]);
    return grid_.nodeIndex(c);
}

template <int dim> bool PeriodicLattice<dim>::isOwner(Index k) const {
    return owner(k) == k;
}

template <int dim>
void PeriodicLattice<dim>::fold(Grid<dim>& g, const std::vector<Index>& activeBlocks,
                                unsigned fields) const {
    if (!any_) return;
    if (fields & FoldMass) foldField(g.mass, activeBlocks);
    if (fields & FoldMomentum) foldField(g.momentum, activeBlocks);
    if (fields & FoldForce) foldField(g.force, activeBlocks);
}

template <int dim> void PeriodicLattice<dim>::closeActiveBlocks(std::vector<Index>& blocks) {
    if (!any_) return;
    std::vector<Index>& closed = closed_; // keeps its memory between steps
    closed.clear();
    for (Index b : blocks) {
        IVec<dim> c;
        Index r = b;
        for (int d = 0; d < dim; ++d) {
            c[d] = static_cast<int>(r % nb_[d]);
            r /= nb_[d];
        }
        // Every combination of related block coordinates along the axes.
        std::array<std::size_t, dim> at{};
        while (true) {
            Index k = 0;
            for (int d = dim - 1; d >= 0; --d)
                k = k * nb_[d] + related_[d][c[d]][at[d]];
            if (!mark_[k]) {
                mark_[k] = 1;
                closed.push_back(k);
            }
            int d = 0;
            while (d < dim && ++at[d] == related_[d][c[d]].size())
                at[d++] = 0;
            if (d == dim) break;
        }
    }
    for (Index k : closed)
        mark_[k] = 0;
    std::sort(closed.begin(), closed.end());
    blocks.swap(closed);
}

template <int dim> Vec<dim> PeriodicLattice<dim>::wrapPosition(Vec<dim> x) const {
    for (int d = 0; d < dim; ++d) {
        if (!periodic_[d] || (x[d] >= lo_[d] && x[d] < hi_[d])) continue;
        const double length = period_[d];
        x[d] -= length * std::floor((x[d] - lo_[d]) / length);
        // Rounding can land a point just below lo on hi itself, the same node as lo.
        if (!(x[d] >= lo_[d] && x[d] < hi_[d])) x[d] = lo_[d];
    }
    return x;
}

template <int dim> void PeriodicLattice<dim>::wrap(Particles<dim>& p) const {
    if (!any_) return;
    const Index n = static_cast<Index>(p.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
    for (Index i = 0; i < n; ++i)
        p.x[i] = wrapPosition(p.x[i]);
}

template <int dim>
Vec<dim> PeriodicLattice<dim>::separation(const Vec<dim>& a, const Vec<dim>& b) const {
    Vec<dim> s = a - b;
    for (int d = 0; d < dim; ++d)
        if (periodic_[d]) s[d] -= period_[d] * std::round(s[d] / period_[d]);
    return s;
}

template <int dim>
IVec<dim> PeriodicLattice<dim>::imageIndex(const Vec<dim>& x, const Vec<dim>& c) const {
    IVec<dim> n = IVec<dim>::Zero();
    for (int d = 0; d < dim; ++d)
        if (periodic_[d]) n[d] = static_cast<int>(std::round((x[d] - c[d]) / period_[d]));
    return n;
}

template class PeriodicLattice<2>;
template class PeriodicLattice<3>;

} // namespace mpm
