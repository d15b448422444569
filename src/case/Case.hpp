// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mpm {

/// The case folder (DESIGN §3): paths and the dictionaries in system/ and constant/.
class Case {
public:
    explicit Case(std::filesystem::path root);

    const std::filesystem::path& root() const { return root_; }
    std::filesystem::path path(const std::string& relative) const { return root_ / relative; }

    /// Read `relative` (e.g. "system/controlDict"); messages name it by that relative path.
    /// A missing required file is an InputError.
    Dictionary read(const std::string& relative) const;
    bool exists(const std::string& relative) const;

    /// Time directories holding particles.vtu, sorted by time value.
    std::vector<std::pair<double, std::string>> timeDirectories() const;

private:
    std::filesystem::path root_;
};

/// OpenFOAM's time-directory name: %g with `precision` significant digits ("0.05", "1e-05").
std::string timeName(double t, int precision);

} // namespace mpm
