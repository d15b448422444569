// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ParticleFile.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <vtkCellType.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace {

using mpm::io::PointArray;
using mpm::io::PointCloud;
namespace fs = std::filesystem;
using mpm::test::readText;

/// A fresh, empty folder per test, removed afterwards.
using ParticleFileTest = mpm::test::TempDirTest;

/// The XML header of a `.vtu` (everything before the appended raw data).
std::string xmlHeader(const fs::path& file) {
    const std::string text = readText(file);
    return text.substr(0, text.find("<AppendedData"));
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof(double)) == 0;
}

PointCloud makeCloud(std::size_t n) {
    PointCloud cloud;
    cloud.points.resize(3 * n);
    for (std::size_t i = 0; i < cloud.points.size(); ++i) {
        cloud.points[i] = std::sin(0.37 * static_cast<double>(i)) * 1e-3 + 1.0 / 3.0;
    }
    PointArray mass{"mass", 1, {}, {}};
    PointArray velocity{"velocity", 3, {}, {}};
    PointArray stress{"stress", 9, {}, {}};
    PointArray id{"id", 1, {}, {}};
    PointArray flags{"flags", 3, {}, {}};
    for (std::size_t i = 0; i < n; ++i) {
        mass.f64.push_back(0.1 + static_cast<double>(i) / 7.0);
        id.i64.push_back(static_cast<std::int64_t>(i) * 1000000007LL - 5);
        for (int c = 0; c < 3; ++c) {
            velocity.f64.push_back(std::cos(static_cast<double>(i * 3 + c)) * 1e5);
            flags.i64.push_back(-static_cast<std::int64_t>(i * 3 + c));
        }
        for (int c = 0; c < 9; ++c) {
            stress.f64.push_back(static_cast<double>(c) * 1e-300 + static_cast<double>(i));
        }
    }
    if (n > 0) {
        mass.f64[0] = std::numeric_limits<double>::denorm_min();
        id.i64[0] = std::numeric_limits<std::int64_t>::min();
        if (n > 1) {
            id.i64[1] = std::numeric_limits<std::int64_t>::max();
        }
    }
    mass.integer = false;
    id.integer = true;
    flags.integer = true;
    cloud.arrays = {mass, velocity, stress, id, flags};
    return cloud;
}

void expectSame(const PointCloud& expected, const PointCloud& actual) {
    ASSERT_EQ(expected.points.size(), actual.points.size());
    for (std::size_t i = 0; i < expected.points.size(); ++i) {
        ASSERT_TRUE(sameBits(expected.points[i], actual.points[i])) << "coordinate " << i;
    }
    ASSERT_EQ(expected.arrays.size(), actual.arrays.size());
    for (const PointArray& e : expected.arrays) {
        const PointArray* a = actual.find(e.name);
        ASSERT_NE(a, nullptr) << e.name;
        EXPECT_EQ(a->components, e.components) << e.name;
        EXPECT_EQ(a->isInteger(), e.isInteger()) << e.name;
        ASSERT_EQ(a->f64.size(), e.f64.size()) << e.name;
        ASSERT_EQ(a->i64, e.i64) << e.name;
        for (std::size_t i = 0; i < e.f64.size(); ++i) {
            ASSERT_TRUE(sameBits(e.f64[i], a->f64[i])) << e.name << " value " << i;
        }
    }
}

TEST_F(ParticleFileTest, RoundTripIsBitExact) {
    const PointCloud cloud = makeCloud(1000);
    const fs::path file = dir_ / "particles.vtu";
    mpm::io::writeVtu(file, cloud);
    expectSame(cloud, mpm::io::readVtu(file));
}

TEST_F(ParticleFileTest, RoundTripSinglePoint) {
    const PointCloud cloud = makeCloud(1);
    const fs::path file = dir_ / "one.vtu";
    mpm::io::writeVtu(file, cloud);
    expectSame(cloud, mpm::io::readVtu(file));
}

TEST_F(ParticleFileTest, RoundTripZeroPoints) {
    const PointCloud cloud = makeCloud(0);
    const fs::path file = dir_ / "empty.vtu";
    mpm::io::writeVtu(file, cloud);
    const PointCloud back = mpm::io::readVtu(file);
    EXPECT_EQ(back.size(), 0u);
    expectSame(cloud, back);
    EXPECT_TRUE(back.find("id")->isInteger());
    EXPECT_FALSE(back.find("mass")->isInteger());
    EXPECT_EQ(back.find("stress")->components, 9);
}

TEST_F(ParticleFileTest, RoundTripWithoutArrays) {
    PointCloud cloud;
    cloud.points = {1.0, 2.0, 3.0, -4.0, 0.5, 0.0};
    const fs::path file = dir_ / "bare.vtu";
    mpm::io::writeVtu(file, cloud);
    const PointCloud back = mpm::io::readVtu(file);
    EXPECT_EQ(back.points, cloud.points);
    EXPECT_TRUE(back.arrays.empty());
}

TEST_F(ParticleFileTest, HeaderIsAppendedLz4UInt64) {
    const fs::path file = dir_ / "particles.vtu";
    mpm::io::writeVtu(file, makeCloud(50));
    const std::string header = xmlHeader(file);
    EXPECT_NE(header.find("type=\"UnstructuredGrid\""), std::string::npos) << header;
    EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos) << header;
    EXPECT_NE(header.find("compressor=\"vtkLZ4DataCompressor\""), std::string::npos) << header;
    EXPECT_NE(header.find("format=\"appended\""), std::string::npos) << header;
    EXPECT_EQ(header.find("format=\"ascii\""), std::string::npos) << header;
    EXPECT_EQ(header.find("format=\"binary\""), std::string::npos) << header;
    EXPECT_NE(header.find("type=\"Float64\" Name=\"mass\""), std::string::npos) << header;
    EXPECT_NE(header.find("type=\"Int64\" Name=\"id\""), std::string::npos) << header;
    EXPECT_NE(header.find("NumberOfComponents=\"9\""), std::string::npos) << header;
    // Raw (not base64) appended data.
    EXPECT_NE(readText(file).find("<AppendedData encoding=\"raw\">"), std::string::npos);
}

TEST_F(ParticleFileTest, CellsAreVertices) {
    const std::size_t n = 123;
    const fs::path file = dir_ / "particles.vtu";
    mpm::io::writeVtu(file, makeCloud(n));

    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(n));
    ASSERT_EQ(grid->GetNumberOfCells(), static_cast<vtkIdType>(n));
    for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) {
        ASSERT_EQ(grid->GetCellType(i), VTK_VERTEX) << i;
        vtkIdType npts = 0;
        const vtkIdType* pts = nullptr;
        grid->GetCellPoints(i, npts, pts);
        ASSERT_EQ(npts, 1);
        ASSERT_EQ(pts[0], i);
    }
}

TEST_F(ParticleFileTest, ZeroPointFileIsValidVtk) {
    const fs::path file = dir_ / "empty.vtu";
    mpm::io::writeVtu(file, PointCloud{});
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    EXPECT_EQ(reader->GetErrorCode(), 0u);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_NE(xmlHeader(file).find("NumberOfPoints=\"0\""), std::string::npos);
}

TEST_F(ParticleFileTest, OverwriteIsAtomicAndLeavesNoTemporary) {
    const fs::path file = dir_ / "particles.vtu";
    mpm::io::writeVtu(file, makeCloud(10));
    mpm::io::writeVtu(file, makeCloud(20));
    EXPECT_EQ(mpm::io::readVtu(file).size(), 20u);
    EXPECT_FALSE(fs::exists(dir_ / "particles.vtu.tmp"));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) {
        ++files;
    }
    EXPECT_EQ(files, 1u);
}

TEST_F(ParticleFileTest, WriteIntoMissingFolderThrows) {
    const fs::path file = dir_ / "noSuchDir" / "particles.vtu";
    try {
        mpm::io::writeVtu(file, makeCloud(5));
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write " + file.string()), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(file));
}

TEST_F(ParticleFileTest, InconsistentArrayThrows) {
    PointCloud cloud = makeCloud(4);
    cloud.arrays[1].f64.pop_back();
    EXPECT_THROW(mpm::io::writeVtu(dir_ / "bad.vtu", cloud), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir_ / "bad.vtu"));
    EXPECT_FALSE(fs::exists(dir_ / "bad.vtu.tmp"));
}

TEST_F(ParticleFileTest, MissingFileThrowsNamingIt) {
    const fs::path file = dir_ / "missing.vtu";
    try {
        mpm::io::readVtu(file);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
}

TEST_F(ParticleFileTest, GarbageFileThrows) {
    const fs::path file = dir_ / "garbage.vtu";
    std::ofstream(file) << "this is not a VTK file\n";
    EXPECT_THROW(mpm::io::readVtu(file), std::runtime_error);
}

TEST_F(ParticleFileTest, TruncatedFileThrows) {
    const fs::path file = dir_ / "particles.vtu";
    mpm::io::writeVtu(file, makeCloud(2000));
    const std::string text = readText(file);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text.substr(0, text.size() / 2);
    EXPECT_THROW(mpm::io::readVtu(file), std::runtime_error);
}

TEST_F(ParticleFileTest, WriteTextAtomic) {
    const fs::path file = dir_ / "index.txt";
    mpm::io::writeTextAtomic(file, "first\n");
    mpm::io::writeTextAtomic(file, "second\n");
    EXPECT_EQ(readText(file), "second\n");
    EXPECT_FALSE(fs::exists(dir_ / "index.txt.tmp"));
    EXPECT_THROW(mpm::io::writeTextAtomic(dir_ / "noSuchDir" / "x.txt", "x"), std::runtime_error);
}

} // namespace
