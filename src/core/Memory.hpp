// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <string>

namespace mpm {

/// Peak resident memory of this process so far [bytes] and where it was read.
struct PeakMemory {
    std::int64_t bytes = -1; ///< -1: not available
    std::string source;      ///< "VmHWM" (/proc/self/status) or "ru_maxrss" (getrusage)
};

/// The high-water mark of the resident set: VmHWM of /proc/self/status (Linux, kB = KiB), or
/// getrusage's ru_maxrss (KiB on Linux) where /proc is not readable.
PeakMemory peakResident();

/// peakResident().bytes.
std::int64_t peakResidentBytes();

} // namespace mpm
