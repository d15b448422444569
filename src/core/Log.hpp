// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <iostream>

namespace mpm {

/// The run log (standard output).
inline std::ostream& log() {
    return std::cout;
}

/// A warning on standard error: `--> MPMFOAM Warning: ...`.
inline std::ostream& warning() {
    return std::cerr << "--> MPMFOAM Warning: ";
}

} // namespace mpm
