// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"

#include <filesystem>
#include <string>

namespace mpm {

/// Throw an InputError naming `dir` unless it is a case directory: an existing folder
/// (`missing` is the message when it is not) with a system/controlDict, or, for a utility that
/// reads another file and not the run control (surfaceToLevelSet: its dictionary, written
/// before the case has a controlDict), with `file` (`.yaml` appended accepted, as Case reads);
/// `noFile` is then the message, which names the file.
inline void requireCaseDirectory(const std::filesystem::path& dir, const std::string& missing,
                                 const std::string& file = "system/controlDict",
                                 const std::string& noFile = "") {
    namespace fs = std::filesystem;
    if (!fs::is_directory(dir)) throw InputError(dir.string(), 0, "", missing);
    if (!fs::is_regular_file(dir / file) && !fs::is_regular_file(dir / (file + ".yaml")))
        throw InputError(dir.string(), 0, "",
                         noFile.empty() ? "not a case directory: it has no " + file : noFile);
}

} // namespace mpm
