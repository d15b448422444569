// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace mpm {

/// The ranks of a run and what they say to each other (Open MPI, docs/parallel.md). A serial run
/// has the default Comm: rank 0 of 1, every reduction the identity, no MPI call at all.
///
/// Every member is collective: all ranks call it, in the same order. Reductions of doubles are
/// made in rank order by every rank alike (a gather then a fixed-order sum, not MPI_Allreduce,
/// whose order is the library's): the same numbers give the same result on every rank and in
/// every run.
class Comm {
public:
    /// One rank (a serial run).
    Comm() = default;
    /// MPI_COMM_WORLD after MPI_Init (mpmFoam -parallel); MPI_Finalize in the destructor.
    static Comm initWorld(int& argc, char**& argv);
    ~Comm();
    Comm(Comm&& other) noexcept;
    Comm& operator=(Comm&&) = delete;
    Comm(const Comm&) = delete;
    Comm& operator=(const Comm&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool master() const { return rank_ == 0; }
    /// True when launched with -parallel (MPI initialised), even on one rank.
    bool parallel() const { return mpi_; }

    /// Σ over ranks of `n` doubles in place, in rank order (bit-identical on every rank).
    void sum(double* data, int n) const;
    double sum(double x) const {
        sum(&x, 1);
        return x;
    }
    Index sum(Index x) const;
    /// Σ over ranks of `n` integers in place (exact, so in any order).
    void sum(Index* data, std::size_t n) const;
    double max(double x) const;
    double min(double x) const;
    Index min(Index x) const;
    /// True if `x` is true on any rank.
    bool any(bool x) const;
    /// Trivially copyable values `x` of every rank, in rank order.
    template <class T> std::vector<T> gather(const T& x) const {
        static_assert(std::is_trivially_copyable_v<T>);
        std::vector<char> bytes(sizeof(T));
        std::memcpy(bytes.data(), &x, sizeof(T));
        const std::vector<char> all = gatherBytes(bytes);
        std::vector<T> r(static_cast<std::size_t>(size_));
        std::memcpy(static_cast<void*>(r.data()), all.data(), all.size());
        return r;
    }

    /// Personalised exchange: `send[r]` goes to rank r; returns what each rank sent to this one
    /// (`recv[r]` from rank r). send.size() == size(). With `neighbours` (ascending, this rank
    /// excluded, a symmetric relation: r lists me when I list r) only those ranks exchange,
    /// their sizes first, point to point, and every other send[r] must be empty; without, the
    /// sizes go through one MPI_Alltoall (every rank: at start-up and after a rebalance).
    std::vector<std::vector<char>> exchange(const std::vector<std::vector<char>>& send,
                                            const std::vector<int>* neighbours = nullptr) const;
    /// Rank 0's `text` on every rank.
    std::string broadcast(const std::string& text) const;
    void barrier() const;
    /// Stop every rank now (a failure seen by one rank only): MPI_Abort with `code`.
    [[noreturn]] void abort(int code) const;
    /// The end of a run with exit code `code` on this rank: when every rank gets here within
    /// `seconds` (a normal end, or a failure all ranks saw, as a bad input or a collective
    /// check), the largest code of all; otherwise some rank failed alone while the others wait in
    /// a collective, and every rank is stopped (abort) — never a hang.
    int finish(int code, double seconds = 10.0) const;

private:
    /// Equal-sized blocks of bytes of every rank, concatenated in rank order.
    std::vector<char> gatherBytes(const std::vector<char>& mine) const;

    int rank_ = 0;
    int size_ = 1;
    bool mpi_ = false;
};

/// The one-rank Comm of serial runs and tests.
inline const Comm& serialComm() {
    static const Comm serial;
    return serial;
}

/// Bytes of trivially copyable values, appended and read back in order (the messages of Comm).
class ByteWriter {
public:
    explicit ByteWriter(std::vector<char>& out) : out_(out) {}
    template <class T> void put(const T& x) {
        static_assert(std::is_trivially_copyable_v<T>);
        const std::size_t at = out_.size();
        out_.resize(at + sizeof(T));
        std::memcpy(out_.data() + at, &x, sizeof(T));
    }
    /// n values of plain data (trivially copyable, or fixed-size Eigen types).
    template <class T> void put(const T* x, std::size_t n) {
        const std::size_t at = out_.size();
        out_.resize(at + n * sizeof(T));
        if (n > 0) std::memcpy(out_.data() + at, static_cast<const void*>(x), n * sizeof(T));
    }

private:
    std::vector<char>& out_;
};

class ByteReader {
public:
    explicit ByteReader(const std::vector<char>& in) : in_(in) {}
    template <class T> T get() {
        T x;
        get(&x, 1);
        return x;
    }
    template <class T> void get(T* x, std::size_t n) {
        if (n > 0) std::memcpy(static_cast<void*>(x), in_.data() + at_, n * sizeof(T));
        at_ += n * sizeof(T);
    }
    bool done() const { return at_ >= in_.size(); }

private:
    const std::vector<char>& in_;
    std::size_t at_ = 0;
};

} // namespace mpm
