// SPDX-License-Identifier: GPL-3.0-or-later
#include "parallel/Comm.hpp"

#include <mpi.h>

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <stdexcept>

namespace mpm {

namespace {

void check(int code, const char* what) {
    if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI error in ") + what);
}

} // namespace

Comm Comm::initWorld(int& argc, char**& argv) {
    int ready = 0;
    MPI_Initialized(&ready);
    if (!ready) check(MPI_Init(&argc, &argv), "MPI_Init");
    Comm c;
    c.mpi_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &c.rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &c.size_);
    return c;
}

Comm::Comm(Comm&& other) noexcept : rank_(other.rank_), size_(other.size_), mpi_(other.mpi_) {
    other.mpi_ = false;
}

Comm::~Comm() {
    if (!mpi_) return;
    int done = 0;
    MPI_Finalized(&done);
    if (!done) MPI_Finalize();
}

std::vector<char> Comm::gatherBytes(const std::vector<char>& mine) const {
    if (!mpi_) return mine;
    std::vector<char> all(mine.size() * static_cast<std::size_t>(size_));
    check(MPI_Allgather(mine.data(), static_cast<int>(mine.size()), MPI_BYTE, all.data(),
                        static_cast<int>(mine.size()), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Allgather");
    return all;
}

void Comm::sum(double* data, int n) const {
    if (!mpi_ || size_ == 1) return;
    std::vector<double> all(static_cast<std::size_t>(n) * static_cast<std::size_t>(size_));
    check(MPI_Allgather(data, n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, MPI_COMM_WORLD),
          "MPI_Allgather");
    for (int k = 0; k < n; ++k) {
        double s = 0.0;
        for (int r = 0; r < size_; ++r)
            s += all[static_cast<std::size_t>(r) * n + k];
        data[k] = s;
    }
}

Index Comm::sum(Index x) const {
    if (!mpi_) return x;
    std::int64_t in = x, out = 0;
    check(MPI_Allreduce(&in, &out, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
    return static_cast<Index>(out);
}

void Comm::sum(Index* data, std::size_t n) const {
    if (!mpi_ || size_ == 1) return;
    static_assert(sizeof(Index) == sizeof(std::int64_t));
    constexpr std::size_t Chunk = std::size_t(1) << 26; // MPI counts are int
    for (std::size_t at = 0; at < n; at += Chunk)
        check(MPI_Allreduce(MPI_IN_PLACE, data + at, static_cast<int>(std::min(Chunk, n - at)),
                            MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD),
              "MPI_Allreduce");
}

double Comm::max(double x) const {
    if (!mpi_) return x;
    double out = 0;
    check(MPI_Allreduce(&x, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return out;
}

double Comm::min(double x) const {
    if (!mpi_) return x;
    double out = 0;
    check(MPI_Allreduce(&x, &out, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    return out;
}

Index Comm::min(Index x) const {
    if (!mpi_) return x;
    std::int64_t in = x, out = 0;
    check(MPI_Allreduce(&in, &out, 1, MPI_INT64_T, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    return static_cast<Index>(out);
}

bool Comm::any(bool x) const {
    if (!mpi_) return x;
    int in = x ? 1 : 0, out = 0;
    check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return out != 0;
}

std::vector<std::vector<char>> Comm::exchange(const std::vector<std::vector<char>>& send,
                                              const std::vector<int>* neighbours) const {
    if (!mpi_) return send;
    const std::size_t n = static_cast<std::size_t>(size_);
    std::vector<std::int64_t> sendCount(n), recvCount(n, 0);
    for (std::size_t r = 0; r < n; ++r)
        sendCount[r] = static_cast<std::int64_t>(send[r].size());
    std::vector<MPI_Request> requests;
    requests.reserve(2 * n);
    if (neighbours) { // sizes from and to the neighbours only
        for (std::size_t r = 0; r < n; ++r)
            assert((send[r].empty() || std::binary_search(neighbours->begin(), neighbours->end(),
                                                          static_cast<int>(r))) &&
                   "a message to a rank that is not a neighbour");
        for (const int r : *neighbours) {
            requests.emplace_back();
            check(MPI_Irecv(&recvCount[static_cast<std::size_t>(r)], 1, MPI_INT64_T, r, 6,
                            MPI_COMM_WORLD, &requests.back()),
                  "MPI_Irecv");
            requests.emplace_back();
            check(MPI_Isend(&sendCount[static_cast<std::size_t>(r)], 1, MPI_INT64_T, r, 6,
                            MPI_COMM_WORLD, &requests.back()),
                  "MPI_Isend");
        }
        check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
              "MPI_Waitall");
        requests.clear();
    } else {
        check(MPI_Alltoall(sendCount.data(), 1, MPI_INT64_T, recvCount.data(), 1, MPI_INT64_T,
                           MPI_COMM_WORLD),
              "MPI_Alltoall");
    }
    std::vector<std::vector<char>> recv(n);
    constexpr int Tag = 7;
    for (std::size_t r = 0; r < n; ++r) {
        recv[r].resize(static_cast<std::size_t>(recvCount[r]));
        if (recvCount[r] == 0 || static_cast<int>(r) == rank_) continue;
        requests.emplace_back();
        check(MPI_Irecv(recv[r].data(), static_cast<int>(recvCount[r]), MPI_BYTE,
                        static_cast<int>(r), Tag, MPI_COMM_WORLD, &requests.back()),
              "MPI_Irecv");
    }
    for (std::size_t r = 0; r < n; ++r) {
        if (send[r].empty() || static_cast<int>(r) == rank_) continue;
        requests.emplace_back();
        check(MPI_Isend(send[r].data(), static_cast<int>(send[r].size()), MPI_BYTE,
                        static_cast<int>(r), Tag, MPI_COMM_WORLD, &requests.back()),
              "MPI_Isend");
    }
    recv[static_cast<std::size_t>(rank_)] = send[static_cast<std::size_t>(rank_)];
    check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
          "MPI_Waitall");
    return recv;
}

std::string Comm::broadcast(const std::string& text) const {
    if (!mpi_) return text;
    std::int64_t n = static_cast<std::int64_t>(text.size());
    check(MPI_Bcast(&n, 1, MPI_INT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
    std::string r = rank_ == 0 ? text : std::string(static_cast<std::size_t>(n), '\0');
    check(MPI_Bcast(r.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast");
    return r;
}

void Comm::barrier() const {
    if (mpi_) MPI_Barrier(MPI_COMM_WORLD);
}

int Comm::finish(int code, double seconds) const {
    if (!mpi_ || size_ == 1) return code;
    MPI_Request request;
    check(MPI_Ibarrier(MPI_COMM_WORLD, &request), "MPI_Ibarrier");
    const double start = MPI_Wtime();
    int done = 0;
    while (!done) {
        check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
        if (!done && MPI_Wtime() - start > seconds) abort(code != 0 ? code : 1);
    }
    int worst = 0;
    check(MPI_Allreduce(&code, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return worst;
}

void Comm::abort(int code) const {
    if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);
}

} // namespace mpm
