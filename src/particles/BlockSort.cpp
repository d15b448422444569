// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/BlockSort.hpp"
#include "core/Parallel.hpp"

#include <atomic>

namespace mpm {

template <int dim> Index BlockSort<dim>::update(const Particles<dim>& p, const Grid<dim>& grid) {
    const Index n = static_cast<Index>(p.size());
    const Index nb = grid.numBlocks();
    block_.resize(n);
    Index firstOutside = n;
    const Vec<dim> origin = grid.origin();
    const double invH = grid.invH();
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : firstOutside)
    for (Index i = 0; i < n; ++i) {
        const Vec<dim> xh = (p.x[i] - origin) * invH;
        if (!grid.insideArrays(xh)) {
            firstOutside = std::min(firstOutside, i);
            block_[i] = 0;
        } else {
            block_[i] = grid.blockOf(xh);
        }
    }
    if (firstOutside < n) return firstOutside;

    start_.assign(nb + 1, 0);
    for (Index i = 0; i < n; ++i)
        ++start_[block_[i] + 1];
    for (Index b = 0; b < nb; ++b)
        start_[b + 1] += start_[b];
    order_.resize(n);
    {
        std::vector<Index> next(start_.begin(), start_.end() - 1);
        for (Index i = 0; i < n; ++i)
            order_[next[block_[i]]++] = i;
    }

    for (auto& c : colourBlocks_)
        c.clear();
    active_.assign(nb, 0);
    const IVec<dim> nbDims = grid.blocks();
    for (Index b = 0; b < nb; ++b) {
        if (start_[b + 1] == start_[b]) continue;
        const IVec<dim> c = grid.blockCoord(b);
        int colour = 0;
        for (int d = 0; d < dim; ++d)
            colour |= (c[d] & 1) << d;
        colourBlocks_[colour].push_back(b);
        // Mark the 3^dim neighbourhood.
        IVec<dim> o = IVec<dim>::Constant(-1);
        while (true) {
            bool inside = true;
            Index k = 0;
            for (int d = dim - 1; d >= 0; --d) {
                const int cd = c[d] + o[d];
                if (cd < 0 || cd >= nbDims[d]) inside = false;
                k = k * nbDims[d] + cd;
            }
            if (inside) active_[k] = 1;
            int d = 0;
            while (d < dim && ++o[d] > 1)
                o[d++] = -1;
            if (d == dim) break;
        }
    }
    activeNodeBlocks_.clear();
    for (Index b = 0; b < nb; ++b)
        if (active_[b]) activeNodeBlocks_.push_back(b);
    return -1;
}

template class BlockSort<2>;
template class BlockSort<3>;

} // namespace mpm
