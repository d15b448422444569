// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cassert>
#include <sstream>
#include <stdexcept>
#include <string>

namespace mpm {

/// An error in what the user wrote: a case file, a command-line option, a value out of range.
/// Always checked (release builds too); reported as
/// `--> MPMFOAM FATAL IO ERROR: <file>:<line>: key '<key>': <message>` and exit code 1.
class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, std::string key, const std::string& message)
        : std::runtime_error(format(file, line, key, message)), file_(std::move(file)), line_(line),
          key_(std::move(key)) {}

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& key() const { return key_; }

private:
    static std::string format(const std::string& file, int line, const std::string& key,
                              const std::string& message) {
        std::ostringstream os;
        if (!file.empty()) {
            os << file;
            if (line > 0) os << ':' << line;
            os << ": ";
        }
        if (!key.empty()) os << "key '" << key << "': ";
        os << message;
        return os.str();
    }

    std::string file_;
    int line_;
    std::string key_;
};

/// A run that went wrong numerically (NaN, energy blow-up, particle leaving the grid).
/// Reported as `--> MPMFOAM FATAL ERROR: ...`, exit code 1, after the last good state is written.
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace mpm

/// Internal invariant: checked in debug builds only.
#define MPM_ASSERT(cond) assert(cond)
