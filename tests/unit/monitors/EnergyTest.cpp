// SPDX-License-Identifier: GPL-3.0-or-later
// The energy function object on a hand-built State: potential for a constant body
// acceleration, the accumulated work for a time-varying one.
#include "forces/BodyAcceleration.hpp"
#include "monitors/FunctionObject.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace mpm {
namespace {

namespace fs = std::filesystem;

class EnergyTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("mpmFoam_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "system");
        std::ofstream(dir_ / "system/controlDict")
            << "endTime: 1\ndeltaT: 0.001\nwriteInterval: 10\n";

        // Two points of a linear elastic material (K = E / (3 (1 − 2ν)) = 2/3 MPa) under an
        // isotropic pressure, and one rigid disk.
        materials_.push_back(Material<2>::create(
            Dictionary::fromString("type: linearElastic\ndensity: 1000\nE: 1e6\nnu: 0.25\n",
                                   "constant/materials"),
            "sand"));
        p_.resize(2);
        for (std::size_t i = 0; i < 2; ++i) {
            p_.mass[i] = 1.5 + static_cast<double>(i);
            p_.volume[i] = 1e-3;
            p_.material[i] = 0;
        }
        p_.x[0] = Vec<2>(0.1, 0.2);
        p_.x[1] = Vec<2>(-0.3, 0.7);
        p_.v[0] = Vec<2>(1.0, -2.0);
        p_.v[1] = Vec<2>(0.5, 0.0);
        p_.stress[0] = -1e4 * Mat3::Identity();
        p_.stress[1] = -2e4 * Mat3::Identity();
        bodies_.push_back(std::make_unique<RigidBody<2>>(
            Dictionary::fromString("shape: {type: disk, radius: 0.1}\ndensity: 2000\n"
                                   "position: [0.4, 0.9]\nvelocity: [0, -3]\n",
                                   "constant/rigidBodies"),
            "disk"));
        for (auto& r : reactions_)
            r.setZero();
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// The values row [kinetic, strain, gravitational, total] the monitor writes for a State
    /// with body acceleration `g` and accumulated work `work`.
    std::vector<double> row(const BodyAcceleration<2>& g, double work) {
        const Case cs(dir_);
        const Time time(cs);
        const Vec<2> gravity = g.at(time.value());
        State<2> s(p_, grid_, materials_, gravity, reactions_, bodies_, g);
        s.time = time.value();
        s.accelerationWork = work;
        auto f = FunctionObjectRegistry<2>::create(
            Dictionary::fromString("type: energy\n", "system/controlDict"), "energy");
        f->prepare(s, time);
        f->open(cs, time);
        f->executeNow(s, time);
        f.reset(); // close the file
        std::ifstream in(dir_ / "postProcessing/energy/0/energy.dat");
        std::string line, last;
        std::getline(in, line);
        EXPECT_EQ(line, "# energy");
        std::getline(in, line);
        EXPECT_EQ(line, "# time kinetic strain gravitational total");
        std::getline(in, last);
        std::istringstream is(last);
        std::vector<double> values;
        double v = 0;
        is >> v; // time
        while (is >> v)
            values.push_back(v);
        EXPECT_EQ(values.size(), 4u);
        values.resize(4);
        return values;
    }

    double kinetic() const {
        return 0.5 * 1.5 * 5.0 + 0.5 * 2.5 * 0.25 + 0.5 * bodies_[0]->mass() * 9.0;
    }
    /// p² V / (2K) for each point.
    double strain() const {
        const double K = 1e6 / 1.5;
        return (1e8 + 4e8) * 1e-3 / (2 * K);
    }

    fs::path dir_;
    Grid<2> grid_{Dictionary::fromString("bounds: {min: [-1, -1], max: [1, 1]}\ncellSize: 0.1\n",
                                         "constant/grid")};
    std::vector<std::unique_ptr<Material<2>>> materials_;
    Particles<2> p_;
    std::vector<std::unique_ptr<RigidBody<2>>> bodies_;
    std::array<Vec<2>, 4> reactions_;
};

TEST_F(EnergyTest, ConstantFieldHasAPotential) {
    const auto g =
        BodyAcceleration<2>::create(Dictionary::fromString("value: [1, -9.81]\n", "constant/g"));
    // −Σ m g·x of points and the disk; the work argument is not used.
    const double mb = bodies_[0]->mass();
    const double potential =
        -(1.5 * (0.1 - 9.81 * 0.2) + 2.5 * (-0.3 - 9.81 * 0.7) + mb * (0.4 - 9.81 * 0.9));
    const std::vector<double> v = row(*g, 123.0);
    EXPECT_NEAR(v[0], kinetic(), 1e-9 * kinetic());
    EXPECT_NEAR(v[1], strain(), 1e-9 * strain());
    EXPECT_NEAR(v[2], potential, 1e-9 * std::fabs(potential));
    EXPECT_NEAR(v[3], kinetic() + strain() + potential, 1e-9 * std::fabs(potential));
    // A table whose rows are all equal is constant too.
    const auto table = BodyAcceleration<2>::create(Dictionary::fromString(
        "type: table\ntable: [[0, 1, -9.81], [1, 1, -9.81]]\n", "constant/g"));
    EXPECT_NEAR(row(*table, 123.0)[2], potential, 1e-9 * std::fabs(potential));
}

TEST_F(EnergyTest, TimeVaryingFieldReportsMinusTheWork) {
    // No potential: gravitational = −W, total = kinetic + strain − W, whatever the positions.
    for (const char* yaml : {"type: sinusoidal\nvalue: [0, -9.81]\namplitude: 0.003\n"
                             "frequency: 15\ndirection: [0, 1]\n",
                             "type: ramp\nvalue: [0, -9.81]\nduration: 0.1\nstart: -1\n"}) {
        const auto g = BodyAcceleration<2>::create(Dictionary::fromString(yaml, "constant/g"));
        for (double work : {0.0, 2.5, -0.75}) {
            const std::vector<double> v = row(*g, work);
            EXPECT_NEAR(v[0], kinetic(), 1e-9 * kinetic());
            EXPECT_NEAR(v[1], strain(), 1e-9 * strain());
            EXPECT_EQ(v[2], -work);
            EXPECT_NEAR(v[3], kinetic() + strain() - work, 1e-9 * kinetic());
        }
        p_.x[1] += Vec<2>(0.2, -0.4);
        EXPECT_EQ(row(*g, 2.5)[2], -2.5);
    }
}

} // namespace
} // namespace mpm
