// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/Reconstruct.hpp"

#include "io/ParticleFile.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using mpm::io::PointArray;
using mpm::io::PointCloud;
namespace fs = std::filesystem;
using mpm::test::readText;

void writeText(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
}

/// Clouds with an Int64 array `material` (i mod 3) (test::idCloud).
PointCloud makeCloud(const std::vector<std::int64_t>& ids) {
    return mpm::test::idCloud(ids, "material", 1,
                              [](std::int64_t i) { return std::vector<std::int64_t>{i % 3}; });
}

/// A parallel run's case: processor0..2 with times 0.05 and 0.1, ids shuffled across the
/// pieces (processor1 has none), processor0's restart state in uniform/.
class ReconstructTest : public mpm::test::TempDirTest {
protected:
    const std::vector<std::vector<std::int64_t>> ids_{{5, 0, 7}, {}, {3, 1, 6, 2, 4}};

    fs::path piece(int r, const std::string& time) const {
        return dir_ / ("processor" + std::to_string(r)) / time / "particles.vtu";
    }

    void SetUp() override {
        for (const std::string time : {"0.1", "0.05"}) {
            for (int r = 0; r < 3; ++r) {
                fs::create_directories(piece(r, time).parent_path());
                mpm::io::writeVtu(piece(r, time), makeCloud(ids_[static_cast<std::size_t>(r)]));
            }
        }
        writeText(dir_ / "processor0/0.1/uniform/time", "value: 0.1\n");
        writeText(dir_ / "processor0/0.1/rigidBodies.vtp", "<VTKFile/>\n");
        fs::create_directories(dir_ / "processor0/0.2"); // no particles.vtu: not a time
        fs::create_directories(dir_ / "processor0/constant");
        writeText(dir_ / "0.1/particles.pvtu", "pvtu\n"); // written by rank 0
        writeText(dir_ / "0.1/uniform/time", "stale\n");
    }

    /// The message of the std::runtime_error `f` throws ("" and a failure when none).
    static std::string errorOf(const std::function<void()>& f) {
        try {
            f();
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        ADD_FAILURE() << "expected a std::runtime_error";
        return "";
    }
};

TEST_F(ReconstructTest, ListsProcessorsAndTimes) {
    EXPECT_EQ(mpm::io::countProcessors(dir_), 3);
    const auto times = mpm::io::processorTimes(dir_, 3);
    ASSERT_EQ(times.size(), 2u);
    EXPECT_EQ(times[0].second, "0.05");
    EXPECT_EQ(times[0].first, 0.05);
    EXPECT_EQ(times[1].second, "0.1");
}

TEST_F(ReconstructTest, MergesThePiecesOrderedByIdAndCopiesTheRestartState) {
    EXPECT_EQ(mpm::io::reconstructTime(dir_, 3, "0.1"), 8u);
    const PointCloud merged = mpm::io::readVtu(dir_ / "0.1/particles.vtu");
    const PointCloud expected = makeCloud({0, 1, 2, 3, 4, 5, 6, 7});
    ASSERT_EQ(merged.size(), 8u);
    EXPECT_EQ(merged.points, expected.points);
    ASSERT_EQ(merged.arrays.size(), expected.arrays.size());
    for (std::size_t k = 0; k < expected.arrays.size(); ++k) {
        const PointArray& a = merged.arrays[k];
        const PointArray& b = expected.arrays[k];
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.components, b.components) << a.name;
        EXPECT_EQ(a.isInteger(), b.isInteger()) << a.name;
        EXPECT_EQ(a.f64, b.f64) << a.name;
        EXPECT_EQ(a.i64, b.i64) << a.name;
    }
    EXPECT_EQ(readText(dir_ / "0.1/uniform/time"), "value: 0.1\n");
    EXPECT_EQ(readText(dir_ / "0.1/rigidBodies.vtp"), "<VTKFile/>\n");
    EXPECT_EQ(readText(dir_ / "0.1/particles.pvtu"), "pvtu\n");
    EXPECT_FALSE(fs::exists(dir_ / "0.1/particles.vtu.tmp"));

    // A second reconstruction (e.g. after the run went on) overwrites everything.
    EXPECT_EQ(mpm::io::reconstructTime(dir_, 3, "0.1"), 8u);
    EXPECT_EQ(mpm::io::readVtu(dir_ / "0.1/particles.vtu").points, expected.points);
}

TEST_F(ReconstructTest, AllPiecesEmpty) {
    for (int r = 0; r < 3; ++r)
        mpm::io::writeVtu(piece(r, "0.05"), makeCloud({}));
    EXPECT_EQ(mpm::io::reconstructTime(dir_, 3, "0.05"), 0u);
    const PointCloud merged = mpm::io::readVtu(dir_ / "0.05/particles.vtu");
    EXPECT_EQ(merged.size(), 0u);
    ASSERT_NE(merged.find("velocity"), nullptr);
    EXPECT_EQ(merged.find("velocity")->components, 3);
}

TEST_F(ReconstructTest, MissingPieceIsAnErrorNamingIt) {
    fs::remove(piece(1, "0.1"));
    EXPECT_NE(
        errorOf([&] { mpm::io::processorTimes(dir_, 3); }).find("processor1/0.1/particles.vtu"),
        std::string::npos);
    EXPECT_NE(errorOf([&] {
                  mpm::io::reconstructTime(dir_, 3, "0.1");
              }).find("processor1/0.1/particles.vtu"),
              std::string::npos);
}

TEST_F(ReconstructTest, DuplicateIdIsAnErrorNamingIt) {
    mpm::io::writeVtu(piece(2, "0.1"), makeCloud({3, 1, 5, 2, 4}));
    const std::string message = errorOf([&] { mpm::io::reconstructTime(dir_, 3, "0.1"); });
    EXPECT_NE(message.find("duplicate particle id 5"), std::string::npos) << message;
    EXPECT_NE(message.find("processor0/0.1/particles.vtu"), std::string::npos) << message;
    EXPECT_NE(message.find("processor2/0.1/particles.vtu"), std::string::npos) << message;
    EXPECT_FALSE(fs::exists(dir_ / "0.1/particles.vtu"));
}

TEST_F(ReconstructTest, MissingIdIsAnError) {
    for (int r = 0; r < 3; ++r) {
        PointCloud cloud = makeCloud(ids_[static_cast<std::size_t>(r)]);
        cloud.arrays.erase(cloud.arrays.begin());
        mpm::io::writeVtu(piece(r, "0.1"), cloud);
    }
    const std::string message = errorOf([&] { mpm::io::reconstructTime(dir_, 3, "0.1"); });
    EXPECT_NE(message.find("'id'"), std::string::npos) << message;
}

TEST_F(ReconstructTest, MismatchedArraysAreAnErrorNamingThePiece) {
    const auto expectError = [&](PointCloud cloud, const std::string& what) {
        mpm::io::writeVtu(piece(2, "0.1"), cloud);
        const std::string message = errorOf([&] { mpm::io::reconstructTime(dir_, 3, "0.1"); });
        EXPECT_NE(message.find("processor2/0.1/particles.vtu"), std::string::npos) << message;
        EXPECT_NE(message.find(what), std::string::npos) << message;
    };
    PointCloud components = makeCloud(ids_[2]);
    components.arrays[2].components = 1; // velocity: one component instead of 3
    components.arrays[2].f64.resize(5);
    expectError(components, "'velocity'");
    PointCloud type = makeCloud(ids_[2]);
    type.arrays[3].f64.assign(type.arrays[3].i64.begin(), type.arrays[3].i64.end());
    type.arrays[3].i64.clear();
    type.arrays[3].integer = false;
    expectError(type, "'material'");
    PointCloud missing = makeCloud(ids_[2]);
    missing.arrays.pop_back();
    expectError(missing, "'material'");
    PointCloud extra = makeCloud(ids_[2]);
    extra.arrays.push_back(PointArray{"extra", 1, std::vector<double>(5, 1.0), {}});
    expectError(extra, "'extra'");
}

TEST_F(ReconstructTest, ProcessorDirectoriesMustBeNumberedWithoutGap) {
    const fs::path other = dir_ / "other";
    fs::create_directories(other);
    EXPECT_EQ(mpm::io::countProcessors(other), 0);
    fs::create_directories(other / "processor0");
    fs::create_directories(other / "processor2");
    fs::create_directories(other / "processorX"); // not a processor directory
    const std::string gap = errorOf([&] { mpm::io::countProcessors(other); });
    EXPECT_NE(gap.find("processor1 is missing"), std::string::npos) << gap;
    fs::create_directories(other / "processor1");
    EXPECT_EQ(mpm::io::countProcessors(other), 3);
    fs::create_directories(other / "processor03");
    const std::string zeros = errorOf([&] { mpm::io::countProcessors(other); });
    EXPECT_NE(zeros.find("processor03"), std::string::npos) << zeros;
    EXPECT_FALSE(errorOf([&] { mpm::io::countProcessors(dir_ / "none"); }).empty());
}

} // namespace
