// SPDX-License-Identifier: GPL-3.0-or-later
// The sparse grid's node fields: zero-initialised, memory committed only where written.
#include "grid/NodeArray.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <sys/mman.h>
#include <unistd.h>
#include <vector>

namespace mpm {
namespace {

Index resident(const void* p, std::size_t bytes) {
    const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> in((bytes + page - 1) / page);
    EXPECT_EQ(mincore(const_cast<void*>(p), bytes, in.data()), 0);
    Index n = 0;
    for (unsigned char c : in)
        n += c & 1;
    return n;
}

TEST(NodeArray, ZeroInitialisedAndCommittedOnlyWhereWritten) {
    constexpr Index n = Index(1) << 27; // 1 GiB of doubles: reserved, not committed
    NodeArray<double> a(n);
    EXPECT_EQ(a.size(), n);
    EXPECT_EQ(a[0], 0.0);
    EXPECT_EQ(a[n - 1], 0.0);
    for (Index k = 0; k < 4096; ++k)
        a[n / 2 + k] = 1.0;
    const auto page = static_cast<Index>(sysconf(_SC_PAGESIZE));
    EXPECT_LE(resident(a.data(), n * sizeof(double)), 4096 * 8 / page + 2);
}

TEST(NodeArray, ReleaseZeroesAndGivesWholePagesBack) {
    const auto page = static_cast<Index>(sysconf(_SC_PAGESIZE));
    const Index perPage = page / static_cast<Index>(sizeof(double));
    NodeArray<double> a(16 * perPage);
    for (Index k = 0; k < a.size(); ++k)
        a[k] = 1.0 + static_cast<double>(k);
    // An unaligned range: its partial end pages are zeroed in place, its whole pages released.
    const Index first = perPage + 3, count = 10 * perPage;
    a.release(first, count);
    EXPECT_EQ(resident(a.data() + 2 * perPage, 9 * page), 0); // the nine whole pages inside
    for (Index k = 0; k < a.size(); ++k)
        ASSERT_EQ(a[k], k >= first && k < first + count ? 0.0 : 1.0 + static_cast<double>(k)) << k;
}

TEST(NodeArray, MoveHandsTheMappingOver) {
    NodeArray<int> a(1000);
    a[7] = 7;
    NodeArray<int> b(std::move(a));
    EXPECT_EQ(b.size(), 1000);
    EXPECT_EQ(b[7], 7);
    NodeArray<int> c;
    c = std::move(b);
    EXPECT_EQ(c[7], 7);
}

} // namespace
} // namespace mpm
