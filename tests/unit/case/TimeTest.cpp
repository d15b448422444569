// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Time.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace mpm {
namespace {

namespace fs = std::filesystem;
using test::catchInputError;

/// A case folder holding only system/controlDict, and the Time read from it.
class TimeTest : public test::TempDirTest {
protected:
    Time& makeTime(const std::string& controlDict) {
        time_.reset(); // it refers to the case
        writeControlDict(controlDict);
        case_ = std::make_unique<Case>(dir_);
        time_ = std::make_unique<Time>(*case_);
        time_->setStart(0.0, 0, 0.0);
        return *time_;
    }
    void writeControlDict(const std::string& text) {
        fs::create_directories(dir_ / "system");
        std::ofstream(dir_ / "system" / "controlDict") << text;
    }
    /// Rewrite controlDict with a modification time other than the one Time has seen.
    void modifyControlDict(const std::string& text) {
        const fs::path p = dir_ / "system" / "controlDict";
        const auto stamp = fs::last_write_time(p);
        writeControlDict(text);
        fs::last_write_time(p, stamp + std::chrono::seconds(2));
    }

    /// Steps taken until run() stops: (index, value, Δt, write?) per step; every write is
    /// recorded with wrote(), as the solver does.
    struct Step {
        long index;
        double value, deltaT;
        bool write;
    };
    std::vector<Step> runToEnd(Time& t, double stableDeltaT = 1e300) {
        std::vector<Step> steps;
        while (t.run() && steps.size() < 100000) {
            t.advance(stableDeltaT);
            steps.push_back({t.index(), t.value(), t.deltaT(), t.writeTime()});
            if (t.writeTime()) t.wrote();
        }
        return steps;
    }
    static std::vector<long> writeIndices(const std::vector<Step>& steps) {
        std::vector<long> out;
        for (const Step& s : steps)
            if (s.write) out.push_back(s.index);
        return out;
    }

    std::unique_ptr<Case> case_;
    std::unique_ptr<Time> time_;
};

TEST_F(TimeTest, ReadsControlDictWithDefaults) {
    const Time& t = makeTime("endTime: 1\ndeltaT: 0.01\nwriteInterval: 10\n");
    EXPECT_EQ(t.startFrom(), "latestTime");
    EXPECT_EQ(t.startTime(), 0.0);
    EXPECT_EQ(t.endTime(), 1.0);
    EXPECT_EQ(t.fixedDeltaT(), 0.01);
    EXPECT_EQ(t.deltaT(), 0.01);
    EXPECT_FALSE(t.adjustTimeStep());
    EXPECT_EQ(t.maxCo(), 0.5);
    EXPECT_EQ(t.writePrecision(), 6);
    EXPECT_FALSE(t.allowUnstableDeltaT());
    EXPECT_FALSE(t.stopping());
}

TEST_F(TimeTest, StartFromChoices) {
    for (const std::string from : {"firstTime", "startTime", "latestTime"}) {
        const Time& t = makeTime("startFrom: " + from +
                                 "\nstartTime: 0.5\nendTime: 1\ndeltaT: 0.1\n"
                                 "writeInterval: 1\n");
        EXPECT_EQ(t.startFrom(), from);
        EXPECT_EQ(t.startTime(), 0.5);
    }
    const InputError e = catchInputError(
        [&] { makeTime("startFrom: earliest\nendTime: 1\ndeltaT: 0.1\nwriteInterval: 1\n"); });
    EXPECT_EQ(e.key(), "startFrom");
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("firstTime, startTime, latestTime"), std::string::npos)
        << e.what();
    EXPECT_EQ(catchInputError([&] {
                  makeTime("startTime: -1\nendTime: 1\ndeltaT: 0.1\nwriteInterval: 1\n");
              }).key(),
              "startTime");
}

TEST_F(TimeTest, RequiredAndCheckedEntries) {
    EXPECT_EQ(catchInputError([&] { makeTime("deltaT: 0.1\nwriteInterval: 1\n"); }).key(),
              "endTime");
    EXPECT_EQ(catchInputError([&] { makeTime("endTime: 1\nwriteInterval: 1\n"); }).key(), "deltaT");
    EXPECT_EQ(catchInputError([&] { makeTime("endTime: 1\ndeltaT: 0\nwriteInterval: 1\n"); }).key(),
              "deltaT");
    // writeControl timeStep counts steps: a whole number >= 1.
    EXPECT_EQ(
        catchInputError([&] { makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 0.5\n"); }).key(),
        "writeInterval");
    EXPECT_EQ(catchInputError([&] {
                  makeTime("endTime: 1\ndeltaT: 0.1\nwriteControl: clockTime\nwriteInterval: 1\n");
              }).key(),
              "writeControl");
    EXPECT_EQ(catchInputError([&] {
                  makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 1\nwriteIntervall: 2\n");
              }).key(),
              "writeIntervall");
}

TEST_F(TimeTest, TimeStepScheduleWritesEveryNthStepAndTheEnd) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteControl: timeStep\nwriteInterval: 3\n");
    const auto steps = runToEnd(t);
    // 0.1 added ten times is 0.9999999999999999: still exactly ten steps.
    ASSERT_EQ(steps.size(), 10u);
    EXPECT_NEAR(t.value(), 1.0, 1e-12);
    EXPECT_EQ(writeIndices(steps), (std::vector<long>{3, 6, 9, 10}));
    EXPECT_FALSE(t.writeAtEnd()); // the end was written
}

TEST_F(TimeTest, RunTimeScheduleWritesAtTheFirstStepPastEachWriteTime) {
    // Δt = 0.03 does not divide the interval 0.1: writes at 0.12, 0.21, 0.30 (steps 4, 7, 10).
    Time& t = makeTime("endTime: 0.3\ndeltaT: 0.03\nwriteControl: runTime\nwriteInterval: 0.1\n");
    const auto steps = runToEnd(t);
    ASSERT_EQ(steps.size(), 10u);
    EXPECT_EQ(writeIndices(steps), (std::vector<long>{4, 7, 10}));
    for (const Step& s : steps)
        EXPECT_EQ(s.deltaT, 0.03); // runTime never changes Δt
}

TEST_F(TimeTest, FixedDeltaTStopsWithinHalfAStepOfEndTime) {
    Time& t = makeTime("endTime: 0.1\ndeltaT: 0.03\nwriteInterval: 100\n");
    const auto steps = runToEnd(t);
    ASSERT_EQ(steps.size(), 3u); // 0.09: the next step would end 0.02 past endTime
    EXPECT_TRUE(steps.back().write);
}

TEST_F(TimeTest, AdjustableRunTimeLandsOnWriteTimes) {
    Time& t = makeTime("endTime: 0.5\ndeltaT: 0.001\nadjustTimeStep: yes\nmaxDeltaT: 0.03\n"
                       "writeControl: adjustableRunTime\nwriteInterval: 0.1\n");
    const auto steps = runToEnd(t);
    std::vector<double> writes;
    double previous = 0.001;
    for (const Step& s : steps) {
        EXPECT_LE(s.deltaT, 0.03 * (1 + 1e-12)) << "at step " << s.index;
        EXPECT_LE(s.deltaT, 1.2 * previous * (1 + 1e-12)) << "at step " << s.index;
        previous = s.deltaT;
        if (s.write) writes.push_back(s.value);
    }
    ASSERT_EQ(writes.size(), 5u);
    for (std::size_t k = 0; k < writes.size(); ++k)
        EXPECT_NEAR(writes[k], 0.1 * double(k + 1), 1e-14) << "write " << k;
    EXPECT_EQ(t.value(), 0.5); // endTime reached exactly
    // Δt grew from 0.001 by at most 1.2 per step and then stayed at or below maxDeltaT.
    EXPECT_GT(steps.size(), 20u);
    EXPECT_LT(steps.size(), 50u);
}

TEST_F(TimeTest, AdjustableDeltaTFollowsTheStableStep) {
    Time& t = makeTime("endTime: 0.1\ndeltaT: 0.004\nadjustTimeStep: yes\nmaxDeltaT: 0.01\n"
                       "writeControl: adjustableRunTime\nwriteInterval: 0.05\n");
    const auto steps = runToEnd(t, 0.0037);
    for (const Step& s : steps)
        EXPECT_LE(s.deltaT, 0.0037 * (1 + 1e-12)) << "at step " << s.index;
    EXPECT_EQ(t.value(), 0.1);
    EXPECT_EQ(writeIndices(steps).size(), 2u);
}

TEST_F(TimeTest, AdjustableDeltaTEndsExactlyAtEndTimeWithTimeStepWrites) {
    // No write times to land on: the last step is shortened to end at endTime.
    Time& t = makeTime("endTime: 0.1\ndeltaT: 0.007\nadjustTimeStep: yes\nmaxDeltaT: 0.007\n"
                       "writeInterval: 1000\n");
    const auto steps = runToEnd(t);
    ASSERT_EQ(steps.size(), 15u); // 14 × 0.007 = 0.098, then 0.002
    EXPECT_NEAR(steps.back().deltaT, 0.002, 1e-12);
    EXPECT_EQ(t.value(), 0.1);
    EXPECT_EQ(writeIndices(steps), (std::vector<long>{15}));
}

TEST_F(TimeTest, TimeNames) {
    Time& t = makeTime("endTime: 2\ndeltaT: 0.1\nwriteInterval: 1\n");
    EXPECT_EQ(t.name(), "0");
    t.setStart(0.1 + 0.2, 3, 0.0); // 0.30000000000000004 with 6 significant digits
    EXPECT_EQ(t.name(), "0.3");
    t.setStart(1e-5, 0, 0.0);
    EXPECT_EQ(t.name(), "1e-05");
}

TEST_F(TimeTest, TimeNameGrowsUntilItDiffersFromTheLastWrite) {
    // timePrecision 3 names 1.0001 "1", the name of the start: more digits until it differs.
    Time& t = makeTime("endTime: 2\ndeltaT: 0.0001\ntimePrecision: 3\nwriteInterval: 1\n");
    t.setStart(1.0, 0, 0.0);
    EXPECT_EQ(t.name(), "1");
    t.advance(1e300);
    EXPECT_EQ(t.name(), "1.0001");
    t.wrote();
    t.setStart(1.5, 0, 0.0);
    EXPECT_EQ(t.name(), "1.5"); // no clash: the short name
}

TEST_F(TimeTest, PurgeWriteKeepsTheLastN) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 1\npurgeWrite: 2\n");
    std::vector<std::vector<std::string>> purged;
    while (t.run()) {
        t.advance(1e300);
        if (t.writeTime()) purged.push_back(t.wrote());
    }
    ASSERT_EQ(purged.size(), 10u);
    EXPECT_TRUE(purged[0].empty());
    EXPECT_TRUE(purged[1].empty());
    EXPECT_EQ(purged[2], (std::vector<std::string>{"0.1"}));
    EXPECT_EQ(purged[3], (std::vector<std::string>{"0.2"}));
    EXPECT_EQ(purged[9], (std::vector<std::string>{"0.8"}));
}

TEST_F(TimeTest, NoPurgeByDefault) {
    Time& t = makeTime("endTime: 0.5\ndeltaT: 0.1\nwriteInterval: 1\n");
    while (t.run()) {
        t.advance(1e300);
        EXPECT_TRUE(t.wrote().empty());
    }
}

TEST_F(TimeTest, StopAtChoices) {
    Time& now = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 5\nstopAt: writeNow\n");
    EXPECT_FALSE(now.run());
    EXPECT_TRUE(now.stopping());

    Time& noWrite = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 5\nstopAt: noWriteNow\n");
    EXPECT_FALSE(noWrite.run());
    EXPECT_FALSE(noWrite.writeAtEnd());

    Time& next = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 3\nstopAt: nextWrite\n");
    const auto steps = runToEnd(next);
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_TRUE(steps.back().write);
    EXPECT_FALSE(next.writeAtEnd());
}

TEST_F(TimeTest, WriteNowWritesTheCurrentStateAtTheEnd) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 3\n");
    t.advance(1e300);
    modifyControlDict("endTime: 1\ndeltaT: 0.1\nwriteInterval: 3\nstopAt: writeNow\n");
    EXPECT_FALSE(t.run());
    EXPECT_TRUE(t.writeAtEnd()); // step 1 was not a write time
    t.wrote();
    EXPECT_FALSE(t.writeAtEnd());
}

TEST_F(TimeTest, StopFileStopsWithAWriteAndIsRemoved) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 5\n");
    EXPECT_TRUE(t.run());
    t.advance(1e300);
    std::ofstream(dir_ / "stop").flush();
    EXPECT_FALSE(t.run());
    EXPECT_FALSE(fs::exists(dir_ / "stop"));
    EXPECT_TRUE(t.stopping());
    EXPECT_TRUE(t.writeAtEnd());
}

TEST_F(TimeTest, ReReadsAModifiedControlDict) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 1\n");
    EXPECT_TRUE(t.run());
    modifyControlDict("endTime: 2\ndeltaT: 0.05\nwriteInterval: 1\n");
    EXPECT_TRUE(t.run());
    EXPECT_EQ(t.endTime(), 2.0);
    EXPECT_EQ(t.deltaT(), 0.05);
    // A broken file changes nothing.
    modifyControlDict("endTime: [\n");
    EXPECT_TRUE(t.run());
    EXPECT_EQ(t.endTime(), 2.0);
    EXPECT_EQ(t.deltaT(), 0.05);
    // endTime lowered below the current time: the run ends and writes.
    t.advance(1e300);
    modifyControlDict("endTime: 0.01\ndeltaT: 0.05\nwriteInterval: 1\n");
    EXPECT_FALSE(t.run());
    EXPECT_TRUE(t.writeAtEnd());
}

TEST_F(TimeTest, NotReReadWhenRunTimeModifiableIsOff) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 1\nrunTimeModifiable: no\n");
    modifyControlDict("endTime: 2\ndeltaT: 0.05\nwriteInterval: 1\n");
    EXPECT_TRUE(t.run());
    EXPECT_EQ(t.endTime(), 1.0);
    EXPECT_EQ(t.deltaT(), 0.1);
}

TEST_F(TimeTest, TimeDictRoundTrip) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.001\nadjustTimeStep: yes\nwriteInterval: 1\n");
    for (int i = 0; i < 7; ++i)
        t.advance(0.00123 * (1 + 0.1 * i));
    const std::string name = t.name();
    t.writeTimeDict(dir_ / name);
    const double value = t.value(), deltaT = t.deltaT();
    const long index = t.index();

    Time& back = makeTime("endTime: 1\ndeltaT: 0.001\nadjustTimeStep: yes\nwriteInterval: 1\n");
    back.readTimeDict(name);
    EXPECT_EQ(back.value(), value);
    EXPECT_EQ(back.deltaT(), deltaT);
    EXPECT_EQ(back.index(), index);
    EXPECT_EQ(back.startValue(), value);
    EXPECT_EQ(back.name(), name);
}

TEST_F(TimeTest, AFinishedCaseRestartsWithEndReached) {
    const std::string dict = "endTime: 0.1\ndeltaT: 0.03\nwriteInterval: 100\n";
    Time& t = makeTime(dict);
    EXPECT_FALSE(t.restarted());
    EXPECT_FALSE(t.endReached());
    runToEnd(t);
    EXPECT_TRUE(t.endReached()); // 0.09: within half a step of endTime
    const std::string name = t.name();
    t.writeTimeDict(dir_ / name);

    // Run again: the latest time has reached endTime, so there is nothing to do.
    Time& again = makeTime(dict);
    again.readTimeDict(name);
    EXPECT_TRUE(again.restarted());
    EXPECT_TRUE(again.endReached());
    EXPECT_FALSE(again.run());

    // endTime raised: the run goes on from there.
    Time& more = makeTime("endTime: 0.2\ndeltaT: 0.03\nwriteInterval: 100\n");
    more.readTimeDict(name);
    EXPECT_TRUE(more.restarted());
    EXPECT_FALSE(more.endReached());
    EXPECT_TRUE(more.run());
}

TEST_F(TimeTest, AStopSeenByAnyRankStopsEveryRank) {
    Time& t = makeTime("endTime: 1\ndeltaT: 0.1\nwriteInterval: 10\n");
    ASSERT_TRUE(t.run());
    t.advance(1e300); // a step that is not a write time
    ASSERT_TRUE(t.run());
    // This rank sees no request; the agreement (Comm::any) says another rank saw one.
    t.setAgreement([](bool) { return true; });
    EXPECT_FALSE(t.run());
    EXPECT_TRUE(t.stopping());
    EXPECT_TRUE(t.writeAtEnd());
}

} // namespace
} // namespace mpm
