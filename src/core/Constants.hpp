// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace mpm {

/// π, the double nearest to it (the value of POSIX M_PI, without needing the macro).
inline constexpr double pi = 3.14159265358979323846;

} // namespace mpm
