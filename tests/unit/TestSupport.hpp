// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"
#include "core/SymmetricEigen.hpp"
#include "core/Types.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

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

/// Mean pressure p = −tr σ/3 and q = √½ |σ − (tr σ/3) 1| [000 Eq. 6].
inline void invariants(const Mat3& s, double& p, double& q) {
    p = -s.trace() / 3.0;
    q = std::sqrt(0.5) * (s + p * Mat3::Identity()).norm();
}

/// A random rotation (eigenvectors of a random symmetric matrix).
inline Mat3 randomRotation(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 a;
    for (int i = 0; i < 9; ++i)
        a(i) = u(rng);
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(a + a.transpose(), lam, Q);
    return Q;
}

} // namespace mpm::test
