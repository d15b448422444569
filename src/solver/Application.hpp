// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Time.hpp"

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mpm {

/// Command line, banner and error reporting shared by mpmFoam and the utilities
/// (OpenFOAM's argList): `-case DIR`, `-help`, plus the program's own options: a switch
/// (`-latestTime`) or, written with a placeholder (`-time <t>`), an option taking a value, or
/// (`-list [family]`) one whose value is optional.
class Application {
public:
    using Option = std::pair<std::string, std::string>; ///< option, description

    /// `footer`: text after the option list of the usage (mpmFoam: its signals).
    Application(int argc, char* argv[], std::string name, std::string summary,
                std::vector<Option> switches, std::string footer = {});

    const std::string& caseDir() const { return caseDir_; }
    bool has(const std::string& option) const;
    /// The value given to an option with a placeholder (`-time` of `-time <t>`), "" if absent.
    std::string value(const std::string& option) const;

    /// Print the banner and run `body`; returns the exit code: 0, or 1 after printing
    /// `--> MPMFOAM FATAL (IO) ERROR:` for an InputError, RunError or other exception.
    int run(const std::function<void()>& body) const;

private:
    void usage(std::ostream& os) const;
    std::string name_, summary_, footer_, commandLine_, caseDir_ = ".";
    std::vector<Option> switches_;
    std::vector<std::string> given_;
    std::vector<std::pair<std::string, std::string>> values_; ///< option, value
    bool help_ = false;
    std::string badOption_;
};

/// The run's peak resident memory, `Peak memory: <X> MiB (VmHWM)` (core/Memory.hpp), printed
/// after the phase table and the particle-updates per second.
void reportPeakMemory(std::ostream& os);

/// Progress line per write: simulated time, Δt, steps per second and ETA.
class ProgressMeter {
public:
    explicit ProgressMeter(const Time& time);
    void print();

private:
    const Time& time_;
    double wall0_, lastWall_;
    long lastIndex_;
};

} // namespace mpm
