// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/Memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>

namespace {

/// VmRSS of /proc/self/status [bytes], the current resident set (the high-water mark can
/// never be below it).
std::int64_t residentNow() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stoll(line.substr(6)) * 1024;
    return -1;
}

} // namespace

TEST(Memory, PeakIsAtLeastTheResidentSetAndReadFromVmHWM) {
    // The resident set first, the mark after: reading the file allocates, so the set may grow
    // between the two readings, and the mark only ever rises.
    const std::int64_t resident = residentNow();
    const mpm::PeakMemory peak = mpm::peakResident();
    EXPECT_EQ(peak.source, "VmHWM"); // Linux: /proc/self/status is readable
    EXPECT_GE(peak.bytes, resident);
    EXPECT_EQ(mpm::peakResidentBytes() > 0, true);
}

TEST(Memory, PeakGrowsByWhatIsTouched) {
    // Touch a fresh block of (peak so far + 256 MiB), every page: the resident set then holds
    // at least the block, so the new peak is at least its size, and at most the old peak plus
    // the block (the rest of the process was resident within the old peak) plus 8 MiB of slack.
    const std::int64_t before = mpm::peakResidentBytes();
    ASSERT_GT(before, 0);
    const std::int64_t extra = before + (std::int64_t(256) << 20);
    const std::size_t n = static_cast<std::size_t>(extra);
    std::unique_ptr<char[]> block(new char[n]);
    for (std::size_t i = 0; i < n; i += 4096)
        block[i] = static_cast<char>(i);
    const std::int64_t after = mpm::peakResidentBytes();
    EXPECT_GE(after, extra);
    EXPECT_LE(after, before + extra + (std::int64_t(8) << 20));
    volatile char sink = block[n / 2]; // keep the pages in use until the reading
    (void)sink;
}
