// SPDX-License-Identifier: GPL-3.0-or-later
// The isolatedPoints function object on hand-placed points: a lattice has none, a point
// farther than r from every other is one, a pair closer than r is none.
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

class IsolatedPointsTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("mpmFoam_isolated_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "system");
        std::ofstream(dir_ / "system/controlDict")
            << "endTime: 1\ndeltaT: 0.001\nwriteInterval: 10\n";
        for (auto& r : reactions_)
            r.setZero();
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// The points at `x`; returns the row [isolated, fraction] and the header's first line.
    std::vector<double> row(const std::vector<Vec<2>>& x, const std::string& extra,
                            std::string* header = nullptr) {
        Particles<2> p;
        p.resize(x.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            p.x[i] = x[i];
        const Case cs(dir_);
        const Time time(cs);
        const auto g = BodyAcceleration<2>::create(
            Dictionary::fromString("value: [0, -9.81]\n", "constant/g"));
        const Vec<2> gravity(0, -9.81);
        State<2> s(p, grid_, materials_, gravity, reactions_, bodies_, *g);
        s.time = time.value();
        auto f = FunctionObjectRegistry<2>::create(
            Dictionary::fromString("type: isolatedPoints\n" + extra, "system/controlDict"), "gas");
        f->prepare(s, time);
        f->open(cs, time);
        f->executeNow(s, time);
        f.reset();
        std::ifstream in(dir_ / "postProcessing/gas/0/gas.dat");
        std::string line;
        std::getline(in, line); // # gas
        std::getline(in, line); // # points with no other point within r
        if (header) *header = line;
        std::getline(in, line);
        EXPECT_EQ(line, "# time isolated fraction");
        std::getline(in, line);
        std::istringstream is(line);
        double t = 0, n = 0, fraction = 0;
        is >> t >> n >> fraction;
        return {n, fraction};
    }

    fs::path dir_;
    Grid<2> grid_{Dictionary::fromString("bounds: {min: [0, 0], max: [2, 2]}\ncellSize: 0.1\n",
                                         "constant/grid")};
    std::vector<std::unique_ptr<Material<2>>> materials_;
    std::vector<std::unique_ptr<RigidBody<2>>> bodies_;
    std::array<Vec<2>, 4> reactions_;
};

TEST_F(IsolatedPointsTest, ALatticeHasNoneAndAStrayPointIsOne) {
    // 10 × 10 points 0.05 apart (h/2): none isolated; one more 0.3 away from the lattice: one;
    // two more 0.09 apart, far from the rest: none (within r = h = 0.1), 0.11 apart: two.
    std::vector<Vec<2>> x;
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i)
            x.emplace_back(0.1 + 0.05 * i, 0.1 + 0.05 * j);
    EXPECT_EQ(row(x, ""), (std::vector<double>{0, 0}));
    x.emplace_back(0.1 + 0.45 + 0.3, 0.1);
    std::vector<double> r = row(x, "");
    EXPECT_EQ(r[0], 1);
    EXPECT_NEAR(r[1], 1.0 / 101, 1e-9);
    x.emplace_back(1.5, 1.5);
    x.emplace_back(1.59, 1.5);
    EXPECT_EQ(row(x, "")[0], 1);
    x.back() = Vec<2>(1.61, 1.5);
    EXPECT_EQ(row(x, "")[0], 3);
    // A radius of its own: 0.2 links the pair again; 0.04 leaves every lattice point alone.
    std::string header;
    EXPECT_EQ(row(x, "radius: 0.2\n", &header)[0], 1);
    EXPECT_NE(header.find("within r = 0.2"), std::string::npos);
    // Every point alone: above warnAbove (default 0.05), a warning names the fraction.
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(row(x, "radius: 0.04\n")[0], 103);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("100 % of the points have no other point within 0.04 m"), std::string::npos);
    ::testing::internal::CaptureStderr();
    row(x, "radius: 0.04\nwarnAbove: 1\n");
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(IsolatedPointsTest, BadRadiusOrThresholdIsAnInputError) {
    const std::vector<Vec<2>> x{{0.5, 0.5}};
    EXPECT_THROW(row(x, "radius: 0\n"), InputError);
    EXPECT_THROW(row(x, "warnAbove: 1.5\n"), InputError);
}

} // namespace
} // namespace mpm
