// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "grid/Grid.hpp"
#include "parallel/Comm.hpp"
#include "parallel/Decomposition.hpp"

#include <vector>

namespace mpm {

/// The grid of one rank of a parallel run and its halo (docs/parallel.md).
///
/// A rank owns the blocks the decomposition gives it and the points in them. Its points'
/// stencils also reach blocks of other ranks (one block deep: a stencil spans at most the
/// neighbouring blocks): these are its ghost blocks. Each step
///  - exchangeBlocks: every rank tells the owners which of their blocks it reaches; an owner
///    activates its own reached blocks and every block reached by another rank;
///  - sum (after each P2G): the ghosts' partial sums go to the owners, which add them in rank
///    order after their own (a fixed order: the result is bit-identical run to run);
///  - copy (after each grid velocity): the owners' values overwrite the ghosts'.
/// The grid update runs on owned() only, so every node is updated once, by its owner.
template <int dim> class GridHalo {
public:
    GridHalo(const Comm& comm, const Decomposition<dim>& decomposition)
        : comm_(comm), decomposition_(decomposition),
          ghostOut_(static_cast<std::size_t>(comm.size())),
          ghostIn_(static_cast<std::size_t>(comm.size())) {}

    /// From the blocks this rank's points reach (ascending), the blocks to activate: those and
    /// the blocks of this rank other ranks reach (ascending).
    std::vector<Index> exchangeBlocks(const std::vector<Index>& reached);
    /// The active blocks this rank owns (ascending): where the grid is updated.
    const std::vector<Index>& owned() const { return owned_; }

    /// Add the ghosts' values of `fields` (NodeArray<double> or NodeArray<Vec<dim>>) onto the
    /// owners'.
    template <class... Fields> void sum(Fields&... fields) {
        transfer(ghostOut_, ghostIn_, true, fields...);
    }
    /// Overwrite the ghosts' values of `fields` with the owners'.
    template <class... Fields> void copy(Fields&... fields) {
        transfer(ghostIn_, ghostOut_, false, fields...);
    }

    /// The ranks this one exchanges with (Comm::exchange), or nullptr: all.
    void setNeighbours(const std::vector<int>* neighbours) { neighbours_ = neighbours; }

    /// Bytes sent in the last step's halo exchanges (the communication volume, report()).
    double bytesSent() const { return bytes_; }
    void resetBytes() { bytes_ = 0; }

private:
    static constexpr Index Nb = Grid<dim>::NodesPerBlock;

    /// Send the values of `from[r]`'s blocks to rank r; receive those of `to[r]`'s blocks from
    /// rank r and add them (add) or assign them, rank by rank in ascending order.
    template <class... Fields>
    void transfer(const std::vector<std::vector<Index>>& from,
                  const std::vector<std::vector<Index>>& to, bool add, Fields&... fields) {
        const std::size_t n = from.size();
        std::vector<std::vector<char>> send(n);
        for (std::size_t r = 0; r < n; ++r) {
            if (from[r].empty()) continue;
            ByteWriter w(send[r]);
            for (Index b : from[r])
                (pack(w, fields, b), ...);
        }
        for (const auto& s : send)
            bytes_ += static_cast<double>(s.size());
        const std::vector<std::vector<char>> recv = comm_.exchange(send, neighbours_);
        for (std::size_t r = 0; r < n; ++r) {
            if (to[r].empty() || static_cast<int>(r) == comm_.rank()) continue;
            ByteReader in(recv[r]);
            for (Index b : to[r])
                (unpack(in, fields, b, add), ...);
        }
    }
    template <class T> static void pack(ByteWriter& w, const NodeArray<T>& f, Index b) {
        w.put(&f[b * Nb], Nb);
    }
    template <class T> static void unpack(ByteReader& in, NodeArray<T>& f, Index b, bool add) {
        T values[Nb];
        in.get(values, Nb);
        for (Index l = 0; l < Nb; ++l)
            f[b * Nb + l] = add ? T(f[b * Nb + l] + values[l]) : values[l];
    }

    const Comm& comm_;
    const Decomposition<dim>& decomposition_;
    std::vector<std::vector<Index>> ghostOut_; ///< [r]: my reached blocks that rank r owns
    std::vector<std::vector<Index>> ghostIn_;  ///< [r]: my blocks that rank r reaches
    std::vector<Index> owned_;
    const std::vector<int>* neighbours_ = nullptr;
    double bytes_ = 0;
};

} // namespace mpm
