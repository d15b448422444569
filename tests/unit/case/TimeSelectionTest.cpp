// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/TimeSelection.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mpm {
namespace {

using test::catchInputError;

const TimeSelection::TimeList times{{0.0, "0"},   {1e-05, "1e-05"}, {0.1, "0.1"},
                                    {0.2, "0.2"}, {0.3, "0.3"},     {0.30000001, "0.30000001"},
                                    {1.0, "1"}};

std::vector<std::string> selected(const std::string& list) {
    std::vector<std::string> out;
    for (const auto& t : TimeSelection(list).select(times))
        out.push_back(t.second);
    return out;
}

using V = std::vector<std::string>;

TEST(TimeSelectionTest, SingleTimes) {
    EXPECT_EQ(selected("0.1"), V{"0.1"});
    EXPECT_EQ(selected("0"), V{"0"});
    EXPECT_EQ(selected("1e-5"), V{"1e-05"}); // by value
    EXPECT_EQ(selected("1e-05"), V{"1e-05"});
    EXPECT_EQ(selected("0.2,0.1"), (V{"0.1", "0.2"})); // in time order
    EXPECT_EQ(selected("0.1, 0.1"), V{"0.1"});         // once
    EXPECT_EQ(selected("1.0"), V{"1"});
    // A directory's name rounds its time: 0.1 + 1e-12 is the time named 0.1.
    EXPECT_EQ(TimeSelection("0.1").select({{0.1 + 1e-12, "0.1"}}).size(), 1U);
}

TEST(TimeSelectionTest, Ranges) {
    EXPECT_EQ(selected("0.1:0.3"), (V{"0.1", "0.2", "0.3"}));
    EXPECT_EQ(selected(":0.1"), (V{"0", "1e-05", "0.1"}));
    EXPECT_EQ(selected("0.3:"), (V{"0.3", "0.30000001", "1"}));
    EXPECT_EQ(selected(":"), (V{"0", "1e-05", "0.1", "0.2", "0.3", "0.30000001", "1"}));
    EXPECT_EQ(selected("0.15:0.25"), V{"0.2"});
    EXPECT_EQ(selected(":1e-5,1:"), (V{"0", "1e-05", "1"}));
    EXPECT_EQ(selected("0.2:0.2"), V{"0.2"});
}

TEST(TimeSelectionTest, Errors) {
    for (const std::string bad : {"", " ", "0.1,", ",0.1", "0.1,,0.2", "abc", "0.1:x", "1:2:3",
                                  "0.3:0.1", "nan", "inf", "0.1s"}) {
        const InputError e = catchInputError([&] { TimeSelection s(bad); });
        EXPECT_EQ(std::string(e.what()).rfind("-time '" + bad + "': ", 0), 0U) << e.what();
    }
    // A time that is not written names the times; a range may be empty if another item is not.
    const InputError missing = catchInputError([] { (void)selected("0.15"); });
    EXPECT_NE(std::string(missing.what()).find("-time: no written time 0.15"), std::string::npos)
        << missing.what();
    EXPECT_NE(std::string(missing.what()).find("0 1e-05 0.1 0.2"), std::string::npos);
    EXPECT_EQ(selected("2:3,0.1"), V{"0.1"});
    const InputError none = catchInputError([] { (void)selected("2:3"); });
    EXPECT_NE(std::string(none.what()).find("selects no written time"), std::string::npos)
        << none.what();
    const InputError empty =
        catchInputError([] { (void)TimeSelection(":").select(TimeSelection::TimeList{}); });
    EXPECT_NE(std::string(empty.what()).find("times: none"), std::string::npos) << empty.what();
}

} // namespace
} // namespace mpm
