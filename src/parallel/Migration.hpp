// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "grid/Grid.hpp"
#include "parallel/Comm.hpp"
#include "parallel/Decomposition.hpp"
#include "particles/Particles.hpp"

#include <vector>

namespace mpm {

/// The rank that owns point x: the owner of its block, or -1 outside the grid's arrays (the
/// sort reports such a point).
template <int dim> int ownerOf(const Vec<dim>& x, const Grid<dim>& g, const Decomposition<dim>& d) {
    const Vec<dim> xh = (x - g.origin()) * g.invH();
    return g.insideArrays(xh) ? d.owner(g.blockOf(xh)) : -1;
}

/// Keep only the points this rank owns (a fresh start: every rank seeded all of them, in the
/// same order) and those outside the arrays (the sort reports them).
template <int dim>
void keepOwned(Particles<dim>& p, const Grid<dim>& g, const Decomposition<dim>& d, int rank) {
    std::vector<Index> keep;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int r = ownerOf(p.x[i], g, d);
        if (r == rank || r < 0) keep.push_back(static_cast<Index>(i));
    }
    if (keep.size() != p.size()) p.permute(keep);
}

/// Migration after G2P: every point whose block another rank owns goes to that rank with all
/// its fields (Particles::forEachArray, the field table's order); the points received are
/// appended in rank order, so the result does not depend on timing. Returns true when this
/// rank's points changed. `scratch`: the reorder buffers; `neighbours`: the ranks points can go
/// to (Comm::exchange), or nullptr: any.
template <int dim>
bool migrate(Particles<dim>& p, const Grid<dim>& g, const Decomposition<dim>& d, const Comm& comm,
             PermuteBuffers<dim>& scratch, const std::vector<int>* neighbours = nullptr) {
    const int me = comm.rank();
    const std::size_t nr = static_cast<std::size_t>(comm.size());
    std::vector<std::vector<Index>> leaving(nr);
    std::vector<Index> keep;
    keep.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int r = ownerOf(p.x[i], g, d);
        if (r == me || r < 0)
            keep.push_back(static_cast<Index>(i));
        else
            leaving[static_cast<std::size_t>(r)].push_back(static_cast<Index>(i));
    }
    std::vector<std::vector<char>> send(nr);
    for (std::size_t r = 0; r < nr; ++r) {
        if (leaving[r].empty()) continue;
        ByteWriter w(send[r]);
        w.put(static_cast<Index>(leaving[r].size()));
        p.forEachArray([&](auto& a) {
            for (Index i : leaving[r])
                w.put(&a[static_cast<std::size_t>(i)], 1);
        });
    }
    const std::vector<std::vector<char>> recv = comm.exchange(send, neighbours);
    const bool left = keep.size() != p.size();
    if (left) p.permute(keep, scratch);
    bool arrived = false;
    for (std::size_t r = 0; r < nr; ++r) {
        if (recv[r].empty() || static_cast<int>(r) == me) continue;
        ByteReader in(recv[r]);
        const auto m = static_cast<std::size_t>(in.get<Index>());
        const std::size_t n0 = p.size();
        p.forEachArray([&](auto& a) {
            a.resize(n0 + m);
            in.get(a.data() + n0, m);
        });
        arrived = true;
    }
    return left || arrived;
}

} // namespace mpm
