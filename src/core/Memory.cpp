// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/Memory.hpp"

#include <sys/resource.h>

#include <fstream>
#include <sstream>

namespace mpm {

PeakMemory peakResident() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) != 0) continue;
        std::istringstream is(line.substr(6));
        std::int64_t kib = -1;
        std::string unit;
        if (is >> kib >> unit && unit == "kB" && kib >= 0) return {kib * 1024, "VmHWM"};
    }
    rusage ru{};
    if (getrusage(RUSAGE_SELF, &ru) == 0 && ru.ru_maxrss > 0)
        return {static_cast<std::int64_t>(ru.ru_maxrss) * 1024, "ru_maxrss"};
    return {};
}

std::int64_t peakResidentBytes() {
    return peakResident().bytes;
}

} // namespace mpm
