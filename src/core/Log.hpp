// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <iostream>

namespace mpm {

namespace detail {
/// A stream that discards everything (the log of ranks other than 0).
inline std::ostream& nullStream() {
    static std::ostream sink(nullptr);
    return sink;
}
inline bool& logQuiet() {
    static bool quiet = false;
    return quiet;
}
} // namespace detail

/// Silence log() and warning() on this process (the ranks other than 0 of a parallel run:
/// OpenFOAM's master-only log).
inline void quietLog(bool quiet) {
    detail::logQuiet() = quiet;
}

/// The run log (standard output).
inline std::ostream& log() {
    return detail::logQuiet() ? detail::nullStream() : std::cout;
}

/// A warning on standard error: `--> MPMFOAM Warning: ...`.
inline std::ostream& warning() {
    return detail::logQuiet() ? detail::nullStream() : std::cerr << "--> MPMFOAM Warning: ";
}

} // namespace mpm
