// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"

#include <filesystem>
#include <string>

namespace mpm {

/// Throw an InputError naming `dir` unless it is a case directory: an existing folder
/// (`missing` is the message when it is not) with a system/controlDict.
inline void requireCaseDirectory(const std::filesystem::path& dir, const std::string& missing) {
    namespace fs = std::filesystem;
    if (!fs::is_directory(dir)) throw InputError(dir.string(), 0, "", missing);
    if (!fs::is_regular_file(dir / "system/controlDict") &&
        !fs::is_regular_file(dir / "system/controlDict.yaml"))
        throw InputError(dir.string(), 0, "", "not a case directory: it has no system/controlDict");
}

} // namespace mpm
