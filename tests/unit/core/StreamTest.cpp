// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/Stream.hpp"
#include "core/Types.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace mpm {
namespace {

struct alignas(32) Chunks {
    int tag[3];
    double w[9];
};

// Streamed stores are copies: every bit arrives, also in an array (where consecutive objects
// share lines) and after sfence, whatever the object's neighbours hold.
TEST(Stream, StoreCopiesWholeObjectsBitForBit) {
    std::vector<Chunks> out(5), expected(5);
    for (auto& c : out)
        std::memset(&c, 0xab, sizeof c);
    for (int k = 0; k < 5; ++k) {
        Chunks& c = expected[k];
        std::memset(&c, 0, sizeof c); // padding included
        c.tag[0] = k, c.tag[1] = -k, c.tag[2] = 7;
        for (int j = 0; j < 8; ++j)
            c.w[j] = k + 0.1 * j;
        c.w[8] = -0.0;
        streamStore(out[k], c);
    }
    sfence();
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(std::memcmp(&out[k], &expected[k], sizeof(Chunks)), 0) << "object " << k;
        EXPECT_TRUE(std::signbit(out[k].w[8]));
    }
}

TEST(Stream, ValueCopiesMatricesOfEitherAlignment) {
    std::vector<Mat<2>> m2(3, Mat<2>::Constant(9.0));
    std::vector<Mat3> m3(3, Mat3::Constant(9.0));
    for (int k = 0; k < 3; ++k) {
        streamValue(m2[k], Mat<2>(Mat<2>::Identity() * (k + 0.5)));
        streamValue(m3[k], Mat3(Mat3::Identity() * (k - 0.25)));
    }
    sfence();
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(m2[k], Mat<2>::Identity() * (k + 0.5));
        EXPECT_EQ(m3[k], Mat3::Identity() * (k - 0.25));
    }
}

} // namespace
} // namespace mpm
