// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <charconv>
#include <string>

namespace mpm {

/// `value` as `%.17g` writes it (17 significant digits: read back bit-identically, by
/// Dictionary too), independent of the global locale.
inline std::string fullPrecision(double value) {
    char buffer[64];
    const auto result =
        std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 17);
    return std::string(buffer, result.ptr);
}

} // namespace mpm
