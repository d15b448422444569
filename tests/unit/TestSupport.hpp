// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"
#include "core/SymmetricEigen.hpp"
#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "io/ParticleFile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
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

/// The whole content of `file`.
inline std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Points of ids i at (i, 2 i, −i) with the arrays id (Int64), mass 0.5 + i/3 (Float64),
/// velocity (i, i + 1/4, −1e5 i) (Float64 × 3) and an Int64 array `name` whose `components`
/// values are extra(i): every value a function of the id, so a reordered cloud can be checked.
inline io::PointCloud idCloud(const std::vector<std::int64_t>& ids, const std::string& name,
                              int components,
                              const std::function<std::vector<std::int64_t>(std::int64_t)>& extra) {
    io::PointCloud cloud;
    io::PointArray id{"id", 1, {}, {}};
    io::PointArray mass{"mass", 1, {}, {}};
    io::PointArray velocity{"velocity", 3, {}, {}};
    io::PointArray other{name, components, {}, {}};
    id.integer = other.integer = true;
    for (const std::int64_t i : ids) {
        const auto x = static_cast<double>(i);
        cloud.points.insert(cloud.points.end(), {x, 2 * x, -x});
        id.i64.push_back(i);
        mass.f64.push_back(0.5 + x / 3.0);
        velocity.f64.insert(velocity.f64.end(), {x, x + 0.25, -1e5 * x});
        const std::vector<std::int64_t> e = extra(i);
        other.i64.insert(other.i64.end(), e.begin(), e.end());
    }
    cloud.arrays = {id, mass, velocity, other};
    return cloud;
}

} // namespace mpm::test
