// SPDX-License-Identifier: GPL-3.0-or-later
// The probes function object on hand-built States: linear fields sampled exactly on symmetric
// point lattices (2D and 3D), the weight and radius against a hand-computed average, empty
// probes, the header and columns, thread-count independence and the input errors.
#include "TestSupport.hpp"
#include "monitors/FunctionObject.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace mpm {
namespace {

namespace fs = std::filesystem;

/// What a probes function object wrote: the `#` lines and the rows (time first).
struct Output {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
};

template <int dim> class Scene {
public:
    Scene(const fs::path& dir, const std::string& gridYaml)
        : dir_(dir), grid_(Dictionary::fromString(gridYaml, "constant/grid")),
          g_(BodyAcceleration<dim>::constant(Vec<dim>::Zero())) {
        fs::create_directories(dir_ / "system");
        std::ofstream(dir_ / "system/controlDict")
            << "endTime: 1\ndeltaT: 0.001\nwriteInterval: 10\n";
        for (auto& r : reactions_)
            r.setZero();
    }

    /// Build `type: probes` from `yaml` and check it against the scene (throws InputErrors).
    std::unique_ptr<FunctionObject<dim>> make(const std::string& yaml) {
        const Case cs(dir_);
        const Time time(cs);
        auto f = FunctionObjectRegistry<dim>::create(
            Dictionary::fromString("type: probes\n" + yaml, "system/controlDict"), "probes");
        f->prepare(state(time.value()), time);
        return f;
    }

    /// Run it `times` times on the current points and read its file back.
    Output run(const std::string& yaml, int times = 1) {
        const Case cs(dir_);
        const Time time(cs);
        {
            auto f = make(yaml);
            f->open(cs, time);
            for (int k = 0; k < times; ++k)
                f->executeNow(state(time.value()), time);
        }
        Output out;
        std::ifstream in(dir_ / "postProcessing/probes/0/probes.dat");
        std::string line;
        while (std::getline(in, line)) {
            if (line.rfind('#', 0) == 0) {
                out.header.push_back(line);
                continue;
            }
            std::istringstream is(line);
            std::vector<double> row;
            double v = 0;
            while (is >> v)
                row.push_back(v);
            out.rows.push_back(row);
        }
        return out;
    }

    Particles<dim> p;

private:
    State<dim> state(double t) const {
        State<dim> s(p, grid_, materials_, gravity_, reactions_, bodies_, *g_);
        s.time = t;
        return s;
    }

    fs::path dir_;
    Grid<dim> grid_;
    std::unique_ptr<BodyAcceleration<dim>> g_;
    std::vector<std::unique_ptr<Material<dim>>> materials_;
    std::vector<std::unique_ptr<RigidBody<dim>>> bodies_;
    std::array<Vec<dim>, 2 * dim> reactions_;
    Vec<dim> gravity_ = Vec<dim>::Zero();
};

/// Points on the lattice x = lo + (i + ½) a, i = 0 … n−1 per axis, of mass 1e-3 kg.
template <int dim> void lattice(Particles<dim>& p, double lo, double a, int n) {
    Index total = 1;
    for (int d = 0; d < dim; ++d)
        total *= n;
    p.resize(static_cast<std::size_t>(total));
    for (Index k = 0; k < total; ++k) {
        Index r = k;
        for (int d = 0; d < dim; ++d) {
            p.x[k][d] = lo + (static_cast<double>(r % n) + 0.5) * a;
            r /= n;
        }
        p.mass[k] = 1e-3;
        p.volume[k] = 1e-6;
        p.stress[k].setZero();
        p.v[k].setZero();
    }
}

/// The linear fields of the 2D tests at x.
double pressureAt(const Vec<2>& x) {
    return 1000 + 200 * x[0] - 300 * x[1];
}
double shearAt(const Vec<2>& x) {
    return 50 + 10 * x[0] - 20 * x[1];
}
Vec<2> velocityAt(const Vec<2>& x) {
    return {1 + 2 * x[0] - x[1], -0.5 + 0.3 * x[0] + 0.7 * x[1]};
}
double densityAt(const Vec<2>& x) {
    return 1500 + 100 * x[0] - 50 * x[1];
}
double plasticAt(const Vec<2>& x) {
    return 0.01 + 0.002 * x[0] + 0.003 * x[1];
}
double slipAt(const Vec<2>& x) {
    return 3 - x[0] + 2 * x[1];
}

class ProbesTest : public test::TempDirTest {
protected:
    /// A 2 m × 2 m grid (h = 0.1 m) and a 40 × 40 lattice of points (spacing 0.05 m) over it
    /// carrying the linear fields above, and a model scalar `slip`.
    void SetUp() override {
        auto& p = scene_.p;
        lattice(p, 0.0, 0.05, 40);
        const std::size_t slip = p.addScalar(FieldInfo{"slip"});
        for (std::size_t i = 0; i < p.size(); ++i) {
            const Vec<2> x = p.x[i];
            p.stress[i] = -pressureAt(x) * Mat3::Identity();
            p.stress[i](0, 1) = p.stress[i](1, 0) = shearAt(x);
            p.v[i] = velocityAt(x);
            p.volume[i] = p.mass[i] / densityAt(x);
            p.plasticStrain[i] = plasticAt(x);
            p.scalar(slip)[i] = slipAt(x);
        }
    }

    Scene<2> scene_{dir_, "bounds: {min: [0, 0], max: [2, 2]}\ncellSize: 0.1\n"};
};

TEST_F(ProbesTest, LinearFieldsAreExactOnASymmetricLattice) {
    // Probes midway between points, on a point, and with the default R = 1.5 h = 0.15 m or a
    // small R = 0.04 m (the four nearest points): the Shepard average of a linear field on a
    // stencil symmetric about the probe is its value there.
    const std::vector<Vec<2>> probes{{1.0, 0.5}, {1.5, 1.0}, {1.025, 0.525}};
    for (const char* radius : {"", "radius: 0.04\n"}) {
        const Output out = scene_.run(
            std::string("fields: [pressure, velocity, density, stress, plasticStrain, slip]\n"
                        "probeLocations: [[1.0, 0.5], [1.5, 1.0], [1.025, 0.525]]\n") +
            radius);
        ASSERT_EQ(out.rows.size(), 1u);
        const std::vector<double>& r = out.rows[0];
        // pressure 3, velocity 3 × 2, density 3, stress 3 × 4, plasticStrain 3, slip 3
        ASSERT_EQ(r.size(), 1u + 3 + 6 + 3 + 12 + 3 + 3);
        std::size_t c = 1;
        const auto expect = [&](double value, const char* what) {
            EXPECT_NEAR(r[c], value, 1e-10 * std::max(1.0, std::fabs(value)))
                << what << " column " << c << " radius '" << radius << "'";
            ++c;
        };
        for (const auto& x : probes)
            expect(pressureAt(x), "pressure");
        for (const auto& x : probes)
            expect(velocityAt(x)[0], "vx"), expect(velocityAt(x)[1], "vy");
        for (const auto& x : probes)
            expect(densityAt(x), "density");
        for (const auto& x : probes) {
            expect(-pressureAt(x), "xx"), expect(-pressureAt(x), "yy");
            expect(-pressureAt(x), "zz"), expect(shearAt(x), "xy");
        }
        for (const auto& x : probes)
            expect(plasticAt(x), "plasticStrain");
        for (const auto& x : probes)
            expect(slipAt(x), "slip");
    }
}

TEST_F(ProbesTest, WeightAndRadiusGiveTheHandComputedAverage) {
    // A quadratic field is not reproduced: the value is Σ w m f / Σ w m with
    // w = (1 − (r/R)²)², computed here point by point, for R = 1.5 h and an explicit R.
    auto& p = scene_.p;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double f = p.x[i].squaredNorm() + 7 * p.x[i][0] * p.x[i][1];
        p.stress[i] = -f * Mat3::Identity();
        p.mass[i] = 1e-3 * (1 + 0.5 * std::sin(13.0 * static_cast<double>(i)));
    }
    const Vec<2> x0(0.93, 1.21);
    for (double R : {0.15, 0.11, 0.04}) {
        double sw = 0, swf = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const double r = (p.x[i] - x0).norm();
            if (r >= R) continue;
            const double w = std::pow(1 - (r / R) * (r / R), 2) * p.mass[i];
            sw += w;
            swf += w * (-p.stress[i].trace() / 3);
        }
        const std::string radius = R == 0.15 ? "" : "radius: " + std::to_string(R) + "\n";
        const Output out = scene_.run("probeLocations: [[0.93, 1.21]]\n" + radius);
        ASSERT_EQ(out.rows.size(), 1u);
        ASSERT_EQ(out.rows[0].size(), 2u);
        EXPECT_NEAR(out.rows[0][1], swf / sw, 1e-10 * swf / sw) << "R = " << R;
        // The quadratic field is not exact: the stencil matters.
        EXPECT_GT(std::fabs(out.rows[0][1] - (x0.squaredNorm() + 7 * x0[0] * x0[1])), 1e-4);
    }
}

TEST_F(ProbesTest, HeaderNamesTheProbesAndColumns) {
    const Output out = scene_.run("fields: [velocity, pressure]\n"
                                  "probeLocations: [[1.0, 0.5], [1.5, 1.0]]\n");
    const std::vector<std::string> header{"# probes", "# probe 0: (1, 0.5)", "# probe 1: (1.5, 1)",
                                          "# radius: 0.15",
                                          "# time vx_0 vy_0 vx_1 vy_1 pressure_0 pressure_1"};
    EXPECT_EQ(out.header, header);
    // Default fields: pressure; an explicit radius is echoed.
    const Output def = scene_.run("probeLocations: [[1.0, 0.5]]\nradius: 0.04\n");
    EXPECT_EQ(def.header.back(), "# time pressure_0");
    EXPECT_EQ(def.header[2], "# radius: 0.04");
    EXPECT_NEAR(def.rows.at(0).at(1), pressureAt({1.0, 0.5}), 1e-9);
}

TEST_F(ProbesTest, EmptyProbeWritesZeroAndWarnsOnce) {
    // Only the points of x < 1 m, y < 1 m are kept: the probe at (1.5, 1.5) is empty.
    auto& p = scene_.p;
    std::vector<Index> keep;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.x[i][0] < 1 && p.x[i][1] < 1) keep.push_back(static_cast<Index>(i));
    p.permute(keep);
    ::testing::internal::CaptureStderr();
    const Output out = scene_.run("fields: [pressure, velocity]\n"
                                  "probeLocations: [[0.5, 0.5], [1.5, 1.5]]\n",
                                  3);
    const std::string err = ::testing::internal::GetCapturedStderr();
    ASSERT_EQ(out.rows.size(), 3u);
    for (const auto& r : out.rows) {
        ASSERT_EQ(r.size(), 7u);
        EXPECT_NEAR(r[1], pressureAt({0.5, 0.5}), 1e-9);
        EXPECT_EQ(r[2], 0.0); // pressure_1
        EXPECT_NEAR(r[3], velocityAt({0.5, 0.5})[0], 1e-12);
        EXPECT_NEAR(r[4], velocityAt({0.5, 0.5})[1], 1e-12);
        EXPECT_EQ(r[5], 0.0); // vx_1
        EXPECT_EQ(r[6], 0.0); // vy_1
    }
    const std::string warn = "probe 1 (1.5, 1.5) has no material point within radius 0.15 m";
    const std::size_t first = err.find(warn);
    EXPECT_NE(first, std::string::npos) << err;
    EXPECT_EQ(err.find(warn, first + 1), std::string::npos) << "warned twice: " << err;
    EXPECT_EQ(err.find("probe 0"), std::string::npos) << err;
}

TEST_F(ProbesTest, SumsDoNotDependOnTheThreadCount) {
    // 40 000 random points (ten chunks of the fixed-order sum) and large radii.
    auto& p = scene_.p;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 2.0);
    p.resize(40000);
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.x[i] = Vec<2>(u(rng), u(rng));
        p.stress[i] = -u(rng) * 1e5 * Mat3::Identity();
        p.v[i] = Vec<2>(u(rng) - 1, u(rng) - 1);
        p.mass[i] = 1e-3 * (0.5 + u(rng));
        p.volume[i] = 1e-6;
    }
    const std::string yaml = "fields: [pressure, velocity]\nradius: 0.7\n"
                             "probeLocations: [[1.0, 0.5], [0.3, 1.7], [1.0, 1.0]]\n";
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const Output one = scene_.run(yaml);
    omp_set_num_threads(3);
    const Output three = scene_.run(yaml);
    omp_set_num_threads(threads);
    ASSERT_EQ(one.rows.size(), 1u);
    EXPECT_EQ(one.rows, three.rows); // bit-identical (as written, 10 digits at least)
    // And the same as a plain loop up to rounding (the file has 11 significant digits).
    const Vec<2> x0(1.0, 1.0);
    double sw = 0, swp = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double q = 1 - (p.x[i] - x0).squaredNorm() / 0.49;
        if (q <= 0) continue;
        sw += q * q * p.mass[i];
        swp += q * q * p.mass[i] * (-p.stress[i].trace() / 3);
    }
    EXPECT_NEAR(one.rows[0][3], swp / sw, 1e-9 * swp / sw);
}

TEST_F(ProbesTest, InputErrors) {
    const auto error = [&](const std::string& yaml) {
        return test::catchInputError([&] { scene_.make(yaml); });
    };
    const auto contains = [](const InputError& e, const std::string& text) {
        return std::string(e.what()).find(text) != std::string::npos;
    };
    InputError e = error("fields: [pressure, pressur]\nprobeLocations: [[1, 1]]\n");
    EXPECT_EQ(e.key(), "fields");
    EXPECT_EQ(e.line(), 2);
    EXPECT_TRUE(contains(e, "unknown field 'pressur' (valid: pressure, density, velocity, "
                            "stress, plasticStrain, slip)"))
        << e.what();

    e = error("probeLocations: [[1, 1], [2.5, 1]]\n");
    EXPECT_EQ(e.key(), "probeLocations");
    EXPECT_TRUE(contains(e, "probe 1 (2.5, 1) is outside the grid box (0, 0) to (2, 2)"))
        << e.what();

    e = error("probeLocations: [[1, 1, 1]]\n");
    EXPECT_TRUE(contains(e, "expected a sequence of 2 numbers")) << e.what();
    e = error("fields: [pressure]\n");
    EXPECT_EQ(e.key(), "probeLocations");
    EXPECT_TRUE(contains(e, "missing required key")) << e.what();
    e = error("probeLocations: []\n");
    EXPECT_TRUE(contains(e, "expected at least one probe location")) << e.what();
    e = error("fields: []\nprobeLocations: [[1, 1]]\n");
    EXPECT_TRUE(contains(e, "expected at least one field name")) << e.what();
    e = error("fields: [velocity, pressure, velocity]\nprobeLocations: [[1, 1]]\n");
    EXPECT_TRUE(contains(e, "field 'velocity' is listed twice")) << e.what();
    e = error("fields: pressure\nprobeLocations: [[1, 1]]\n");
    EXPECT_TRUE(contains(e, "expected a sequence of strings")) << e.what();
    e = error("radius: 0\nprobeLocations: [[1, 1]]\n");
    EXPECT_EQ(e.key(), "radius");
    // The grid's corners are inside.
    EXPECT_NO_THROW(scene_.make("probeLocations: [[0, 0], [2, 2]]\n"));
}

TEST(Probes3D, LinearVelocityAndStressAreExact) {
    // A 10 × 10 × 10 lattice (spacing 0.05 m) over [0.25, 0.75]³ in a unit grid (h = 0.1 m):
    // the six stress components and three velocity components at two probes.
    test::TempDir tmp;
    Scene<3> scene(tmp.path(), "bounds: {min: [0, 0, 0], max: [1, 1, 1]}\ncellSize: 0.1\n");
    auto& p = scene.p;
    lattice(p, 0.25, 0.05, 10);
    const auto sigma = [](const Vec<3>& x) {
        Mat3 s;
        s << 1 + x[0], 4 - x[1], 6 + 2 * x[2],       //
            4 - x[1], 2 + 3 * x[1], 5 - x[0] + x[2], //
            6 + 2 * x[2], 5 - x[0] + x[2], 3 - 2 * x[2];
        return s;
    };
    const auto velocity = [](const Vec<3>& x) {
        return Vec<3>(x[0] - x[1], 2 * x[2], 1 + x[0] + x[1] + x[2]);
    };
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.stress[i] = sigma(p.x[i]);
        p.v[i] = velocity(p.x[i]);
    }
    const Output out = scene.run("fields: [velocity, stress]\n"
                                 "probeLocations: [[0.5, 0.5, 0.5], [0.45, 0.55, 0.5]]\n");
    EXPECT_EQ(out.header.back(), "# time vx_0 vy_0 vz_0 vx_1 vy_1 vz_1 xx_0 yy_0 zz_0 xy_0 yz_0 "
                                 "xz_0 xx_1 yy_1 zz_1 xy_1 yz_1 xz_1");
    ASSERT_EQ(out.rows.size(), 1u);
    const std::vector<double>& r = out.rows[0];
    ASSERT_EQ(r.size(), 1u + 6 + 12);
    const std::vector<Vec<3>> probes{{0.5, 0.5, 0.5}, {0.45, 0.55, 0.5}};
    for (std::size_t k = 0; k < 2; ++k) {
        const Vec<3> v = velocity(probes[k]);
        const Mat3 s = sigma(probes[k]);
        for (int d = 0; d < 3; ++d)
            EXPECT_NEAR(r[1 + 3 * k + d], v[d], 1e-12);
        const double expected[6] = {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)};
        for (int c = 0; c < 6; ++c)
            EXPECT_NEAR(r[7 + 6 * k + c], expected[c], 1e-12) << "probe " << k << " comp " << c;
    }
}

} // namespace
} // namespace mpm
