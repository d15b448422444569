// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/FailureReport.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace mpm;

TEST(FailureReport, NamesThePointOnlyWhereItIsOneOfTheRanks) {
    Particles<2> p;
    p.resize(2);
    p.id = {7, 9};
    p.x[1] = Vec<2>(0.5, 0.25);
    const std::string serial = describePoint(p, 1, -1);
    EXPECT_EQ(serial.rfind("particle 9 at (", 0), 0u) << serial;
    EXPECT_NE(serial.find("0.5 0.25) "), std::string::npos) << serial;
    EXPECT_EQ(describePoint(p, 1, 3), "rank 3: " + serial);
    EXPECT_EQ(describePoint(p, -1, 3), "");
    // The fastest point of a rank that holds none (or an index past its points): nothing of the
    // point is read, and none is named.
    EXPECT_EQ(describePoint(p, 2, 3), "");
    const Particles<2> none;
    EXPECT_EQ(describePoint(none, 0, 1), "");
}

} // namespace
