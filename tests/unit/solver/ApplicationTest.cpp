// SPDX-License-Identifier: GPL-3.0-or-later
// The command line of mpmFoam and the utilities: -case, switches, options with a value, and
// bad options (an error exit, never a run).
#include "solver/Application.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mpm {
namespace {

/// An Application over the words of `line` (argv[0] = "prog").
Application parse(std::vector<std::string> words) {
    words.insert(words.begin(), "prog");
    static std::vector<std::string> keep; // argv must outlive the call
    keep = words;
    std::vector<char*> argv;
    for (std::string& w : keep)
        argv.push_back(w.data());
    return Application(static_cast<int>(argv.size()), argv.data(), "prog", "a test",
                       {{"-latestTime", "switch"}, {"-time <t>", "option with a value"}});
}

TEST(Application, SwitchesAndValues) {
    const Application app = parse({"-case", "c", "-time", "0.25", "-latestTime"});
    EXPECT_EQ(app.caseDir(), "c");
    EXPECT_TRUE(app.has("-latestTime"));
    EXPECT_TRUE(app.has("-time"));
    EXPECT_EQ(app.value("-time"), "0.25");
    EXPECT_EQ(parse({}).value("-time"), "");
    EXPECT_FALSE(parse({}).has("-latestTime"));
}

TEST(Application, AMissingValueOrAnUnknownOptionExitsWithoutRunning) {
    for (const auto& words : {std::vector<std::string>{"-time"}, {"-times", "1"}, {"-case"}}) {
        const Application app = parse(words);
        bool ran = false;
        testing::internal::CaptureStderr();
        EXPECT_EQ(app.run([&] { ran = true; }), 1);
        const std::string err = testing::internal::GetCapturedStderr();
        EXPECT_FALSE(ran);
        EXPECT_NE(err.find("FATAL ERROR"), std::string::npos) << err;
    }
}

} // namespace
} // namespace mpm
