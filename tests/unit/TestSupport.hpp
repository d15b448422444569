// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"
#include "core/SymmetricEigen.hpp"
#include "core/Types.hpp"
#include "grid/Grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

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

/// A new, empty folder under the system temporary directory with a unique name
/// (`mpmFoam_<suite>_<test>_XXXXXX`, made by mkdtemp: no clash between processes or tests run
/// at the same time), removed with its contents when the object is destroyed.
class TempDir {
public:
    TempDir() {
        std::string stem = "mpmFoam";
        if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
            stem += std::string("_") + info->test_suite_name() + "_" + info->name();
        for (char& c : stem)
            if (c == '/') c = '_'; // parameterised tests have '/' in their names
        std::string pattern =
            (std::filesystem::temp_directory_path() / (stem + "_XXXXXX")).string();
        if (::mkdtemp(pattern.data()) == nullptr)
            throw std::runtime_error("cannot create a temporary folder " + pattern);
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::filesystem::path& relative) const {
        return path_ / relative;
    }

private:
    std::filesystem::path path_;
};

/// Fixture for tests that write files: `dir_` is a fresh TempDir of the test, removed when the
/// test ends, also when it fails (the fixture is destroyed after every test).
class TempDirTest : public ::testing::Test {
protected:
    TempDir tmp_;
    std::filesystem::path dir_ = tmp_.path();
};

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

/// Every node of the grid's box, x fastest (the padding of the last blocks excluded).
template <int dim> std::vector<Index> boxNodes(const Grid<dim>& g) {
    std::vector<Index> nodes;
    for (Index f = 0; f < g.numFileNodes(); ++f)
        nodes.push_back(g.nodeOfFileIndex(f));
    return nodes;
}

/// Make every block of the grid active (Grid::activate), as if material reached everywhere.
template <int dim> void activateAll(Grid<dim>& g) {
    std::vector<Index> all(static_cast<std::size_t>(g.numBlocks()));
    for (Index b = 0; b < g.numBlocks(); ++b)
        all[b] = b;
    g.activate(std::move(all));
}

} // namespace mpm::test
