// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace mpm::test {

/// Run `f`, which must throw an InputError, and return that error for inspection (records a
/// test failure if it does not throw).
inline InputError catchInputError(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "expected an InputError";
    return InputError("", -1, "", "no error");
}

} // namespace mpm::test
