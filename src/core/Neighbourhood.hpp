// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

namespace mpm {

/// Call f(i) for every integer index i in [lo, hi] (inclusive), lexicographically, x fastest.
template <int dim, class F> void forEachIndex(const IVec<dim>& lo, const IVec<dim>& hi, F&& f) {
    for (int d = 0; d < dim; ++d) {
        if (hi[d] < lo[d]) return;
    }
    IVec<dim> i = lo;
    while (true) {
        f(static_cast<const IVec<dim>&>(i));
        int d = 0;
        for (; d < dim; ++d) {
            if (i[d] < hi[d]) {
                ++i[d];
                break;
            }
            i[d] = lo[d];
        }
        if (d == dim) return;
    }
}

/// Visit the 3^dim offsets o ∈ {−1, 0, 1}^dim of a cell's neighbourhood (itself included), the
/// first axis fastest: fn(o).
template <int dim, class Fn> void forEachNeighbourOffset(Fn&& fn) {
    forEachIndex<dim>(IVec<dim>::Constant(-1), IVec<dim>::Constant(1), fn);
}

} // namespace mpm
