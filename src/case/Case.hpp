// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mpm {

/// The case folder (docs/caseFormat.md §1): paths and the dictionaries in system/ and constant/.
class Case {
public:
    explicit Case(std::filesystem::path root);
    /// The case of rank `rank` of a parallel run (OpenFOAM's processor case): its time
    /// directories live in `<root>/processor<rank>/`, which must exist (decomposePar made it);
    /// read() and exists() look there first and, for system/ and constant/ (shared), then in the
    /// root case; a time directory's files are the processor's own. An InputError when the
    /// directory is missing.
    Case processor(int rank) const;

    const std::filesystem::path& root() const { return root_; }
    /// The root of the whole case (root() itself except for a processor case).
    const std::filesystem::path& globalRoot() const { return global_.empty() ? root_ : global_; }
    std::filesystem::path path(const std::string& relative) const { return root_ / relative; }

    /// Read `relative` (e.g. "system/controlDict"); messages name it by displayName(). A missing
    /// required file is an InputError.
    Dictionary read(const std::string& relative) const;
    bool exists(const std::string& relative) const;
    /// `relative` as messages name it: its path from the whole case's root, i.e. with the
    /// processor folder of a processor case ("processor1/0.004/uniform/time") unless it is a
    /// shared file of the root case ("system/controlDict", or one missing from both).
    std::string displayName(const std::string& relative) const;

    /// Time directories holding particles.vtu, sorted by time value.
    std::vector<std::pair<double, std::string>> timeDirectories() const;

private:
    Case() = default;
    /// The file `relative` names: in root(), else (processor case, system/ and constant/ only)
    /// in the global root.
    std::filesystem::path locate(const std::string& relative) const;

    std::filesystem::path root_;
    std::filesystem::path global_; ///< the root case of a processor case; empty otherwise
};

/// OpenFOAM's time-directory name: %g with `precision` significant digits ("0.05", "1e-05").
std::string timeName(double t, int precision);

/// A time directory's name: a decimal number, optionally signed and with an exponent ("0",
/// "0.004", "1e-05"), as bin/tools/CleanFunctions' _cfIsNumber; "inf", "nan" and hex are not.
bool isTimeName(const std::string& name);

/// The directories of `dir` whose name is a time (isTimeName), sorted by value, then name;
/// with `withParticles`, only those holding particles.vtu (a complete write).
std::vector<std::pair<double, std::string>> timeDirectories(const std::filesystem::path& dir,
                                                            bool withParticles);

} // namespace mpm
