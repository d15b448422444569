// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/FastMath.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using mpm::fastLog;

TEST(FastMath, LogMatchesStdLogToAFewUlp) {
    std::mt19937_64 rng(7);
    for (int k = 0; k < 100000; ++k) {
        // Log-uniform over 1e-300 … 1e300, and a dense sample near 1 where ln x → 0.
        const double e = (static_cast<double>(rng() >> 11) * 0x1.0p-53 - 0.5) * 600.0;
        for (double x : {std::pow(10.0, e),
                         1.0 + 1e-3 * (static_cast<double>(rng() >> 11) * 0x1.0p-53 - 0.5)}) {
            const double ref = std::log(x);
            EXPECT_NEAR(fastLog(x), ref,
                        4e-16 * std::fabs(ref) + 2e-16 * std::fabs(x - 1.0) + 1e-300)
                << "x = " << x;
        }
    }
}

TEST(FastMath, LogOfExactValues) {
    EXPECT_EQ(fastLog(1.0), 0.0);
    EXPECT_NEAR(fastLog(2.0), std::log(2.0), 1e-16);
    EXPECT_NEAR(fastLog(std::exp(1.0)), 1.0, 2e-16);
    EXPECT_NEAR(fastLog(0.5), -std::log(2.0), 1e-16);
}
