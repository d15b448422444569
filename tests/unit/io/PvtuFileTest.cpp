// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/PvtuFile.hpp"

#include "io/ParticleFile.hpp"
#include "io/XmlFile.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using mpm::io::PointArray;
using mpm::io::PointCloud;
namespace fs = std::filesystem;
using mpm::test::readText;

/// A fresh, empty folder per test, removed afterwards.
using PvtuFileTest = mpm::test::TempDirTest;

/// Clouds with an Int64 × 2 array `flags` (10 i, −i) (test::idCloud).
PointCloud makeCloud(const std::vector<std::int64_t>& ids) {
    return mpm::test::idCloud(ids, "flags", 2, [](std::int64_t i) {
        return std::vector<std::int64_t>{i * 10, -i};
    });
}

struct ParallelRead {
    vtkNew<mpm::io::ErrorObserver> errors;
    vtkNew<vtkXMLPUnstructuredGridReader> reader;
    vtkUnstructuredGrid* grid = nullptr;

    explicit ParallelRead(const fs::path& file) {
        reader->AddObserver(vtkCommand::ErrorEvent, errors);
        reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
        reader->SetFileName(file.string().c_str());
        reader->Update();
        grid = reader->GetOutput();
    }
};

/// Two pieces, the second without points, as rank 0 of a parallel run indexes them.
TEST_F(PvtuFileTest, VtkReadsEveryPieceWithItsArrays) {
    const PointCloud first = makeCloud({4, 0, 7});
    const PointCloud empty = makeCloud({});
    fs::create_directories(dir_ / "processor0/0.1");
    fs::create_directories(dir_ / "processor1/0.1");
    fs::create_directories(dir_ / "0.1");
    mpm::io::writeVtu(dir_ / "processor0/0.1/particles.vtu", first);
    mpm::io::writeVtu(dir_ / "processor1/0.1/particles.vtu", empty);
    // The layout is the empty piece: the types come from the arrays' `integer` flags.
    const fs::path file = dir_ / "0.1/particles.pvtu";
    mpm::io::writePvtu(file, empty,
                       {"../processor0/0.1/particles.vtu", "../processor1/0.1/particles.vtu"});
    EXPECT_FALSE(fs::exists(mpm::io::tmpName(file)));

    ParallelRead read(file);
    ASSERT_FALSE(read.errors->failed()) << read.errors->message();
    ASSERT_NE(read.grid, nullptr);
    vtkUnstructuredGrid& grid = *read.grid;
    ASSERT_EQ(grid.GetNumberOfPoints(), 3);
    EXPECT_EQ(grid.GetNumberOfCells(), 3);
    EXPECT_EQ(grid.GetCellType(2), VTK_VERTEX);

    vtkPointData* pd = grid.GetPointData();
    ASSERT_EQ(pd->GetNumberOfArrays(), 4);
    const std::vector<std::string> names{"id", "mass", "velocity", "flags"};
    const std::vector<int> components{1, 1, 3, 2};
    for (int k = 0; k < 4; ++k) {
        vtkDataArray* a = pd->GetArray(k);
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->GetName(), names[k]);
        EXPECT_EQ(a->GetNumberOfComponents(), components[k]) << names[k];
        const bool integer = names[k] == "id" || names[k] == "flags";
        EXPECT_EQ(a->GetDataTypeSize(), 8) << names[k];
        EXPECT_EQ(a->GetDataType() == VTK_DOUBLE, !integer) << names[k];
    }
    vtkDataArray* id = pd->GetArray("id");
    vtkDataArray* mass = pd->GetArray("mass");
    vtkDataArray* velocity = pd->GetArray("velocity");
    vtkDataArray* flags = pd->GetArray("flags");
    for (vtkIdType i = 0; i < 3; ++i) {
        const double x = static_cast<double>(first.arrays[0].i64[static_cast<std::size_t>(i)]);
        EXPECT_EQ(id->GetComponent(i, 0), x);
        EXPECT_EQ(mass->GetComponent(i, 0), 0.5 + x / 3.0);
        EXPECT_EQ(velocity->GetComponent(i, 2), -1e5 * x);
        EXPECT_EQ(flags->GetComponent(i, 0), 10 * x);
        EXPECT_EQ(flags->GetComponent(i, 1), -x);
        double p[3];
        grid.GetPoint(i, p);
        EXPECT_EQ(p[0], x);
        EXPECT_EQ(p[1], 2 * x);
        EXPECT_EQ(p[2], -x);
    }
}

TEST_F(PvtuFileTest, HeaderMatchesWhatWriteVtuWrites) {
    const fs::path file = dir_ / "particles.pvtu";
    mpm::io::writePvtu(file, makeCloud({1, 2}), {"../processor0/0/particles.vtu"});
    const std::string text = readText(file);
    for (const char* expected :
         {"type=\"PUnstructuredGrid\" version=\"1.0\"", "byte_order=\"LittleEndian\"",
          "header_type=\"UInt64\"", "<PDataArray type=\"Int64\" Name=\"id\"/>",
          "<PDataArray type=\"Float64\" Name=\"mass\"/>",
          "<PDataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"/>",
          "<PDataArray type=\"Int64\" Name=\"flags\" NumberOfComponents=\"2\"/>",
          "<PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>",
          "<PDataArray type=\"Int64\" Name=\"connectivity\"/>",
          "<PDataArray type=\"Int64\" Name=\"offsets\"/>",
          "<PDataArray type=\"UInt8\" Name=\"types\"/>",
          "<Piece Source=\"../processor0/0/particles.vtu\"/>"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
    }
    // The cells' types are those of a .vtu written by writeVtu.
    mpm::io::writeVtu(dir_ / "piece.vtu", makeCloud({1, 2}));
    const std::string piece = readText(dir_ / "piece.vtu");
    for (const char* cells : {"type=\"Int64\" Name=\"connectivity\"",
                              "type=\"Int64\" Name=\"offsets\"", "type=\"UInt8\" Name=\"types\""}) {
        EXPECT_NE(piece.find(cells), std::string::npos) << cells;
    }
}

TEST_F(PvtuFileTest, EscapesNamesAndSourcesAndThrowsWhenUnwritable) {
    PointCloud layout;
    layout.arrays.push_back(PointArray{"a<b>&\"c\"", 1, {}, {}});
    const fs::path file = dir_ / "particles.pvtu";
    mpm::io::writePvtu(file, layout, {"../p&q/0/particles.vtu"});
    const std::string text = readText(file);
    EXPECT_NE(text.find("Name=\"a&lt;b&gt;&amp;&quot;c&quot;\""), std::string::npos) << text;
    EXPECT_NE(text.find("Source=\"../p&amp;q/0/particles.vtu\""), std::string::npos) << text;
    EXPECT_THROW(mpm::io::writePvtu(dir_ / "missing/particles.pvtu", layout, {}),
                 std::runtime_error);
}

} // namespace
