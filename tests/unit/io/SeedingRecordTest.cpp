// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/SeedingRecord.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace {

using namespace mpm;
namespace fs = std::filesystem;

/// A case folder (system/, constant/, 0/) in a fresh temporary folder.
class SeedingRecordTest : public test::TempDirTest {
protected:
    SeedingRecordTest() {
        fs::create_directories(dir_ / "system");
        fs::create_directories(dir_ / "constant/levelSets");
        fs::create_directories(dir_ / "0/uniform");
        write("system/controlDict", "endTime: 1\n");
        write("system/mpmSchemes", "kernel: linear\n");
        write("constant/grid", "cellSize: 0.01\n");
        write("constant/particles", "block: {}\n");
        write("constant/levelSets/rock.vti", "levelSet\n");
    }
    void write(const std::string& relative, const std::string& text) {
        std::ofstream(dir_ / relative, std::ios::binary) << text;
    }
    /// Record the current inputs in 0/uniform/seeding.
    void record(bool preload = false) {
        write("0/uniform/seeding", io::seedingRecord(io::seedingInputs(Case(dir_), preload)));
    }
};

TEST_F(SeedingRecordTest, FileHashIsFnv1a64) {
    write("a", "a");
    write("empty", "");
    EXPECT_EQ(io::fileHash(dir_ / "a"), "af63dc4c8601ec8c");
    EXPECT_EQ(io::fileHash(dir_ / "empty"), "cbf29ce484222325");
    EXPECT_EQ(io::fileHash(dir_ / "absent"), "");
}

TEST_F(SeedingRecordTest, InputsAreTheFilesOfConstantSorted) {
    write("constant/.particles.swp", "editor");
    write("constant/grid~", "backup");
    fs::create_directories(dir_ / "constant/.hidden");
    write("constant/.hidden/x", "x");
    const io::SeedingInputs inputs = io::seedingInputs(Case(dir_), false);
    ASSERT_EQ(inputs.size(), 3u);
    EXPECT_EQ(inputs[0].first, "constant/grid");
    EXPECT_EQ(inputs[1].first, "constant/levelSets/rock.vti");
    EXPECT_EQ(inputs[2].first, "constant/particles");
    EXPECT_EQ(inputs[0].second, io::fileHash(dir_ / "constant/grid"));
    const io::SeedingInputs preload = io::seedingInputs(Case(dir_), true);
    ASSERT_EQ(preload.size(), 4u);
    EXPECT_EQ(preload[3].first, "system/mpmSchemes");
}

TEST_F(SeedingRecordTest, UnchangedInputsOrNoRecordMeanNoChange) {
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), ""); // no record: 0/ is kept as it is
    record();
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), "");
    write("system/controlDict", "endTime: 2\n");  // not an input of the seeding
    write("system/mpmSchemes", "kernel: gimp\n"); // one only after a preload
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), "");
}

TEST_F(SeedingRecordTest, ChangedNewAndGoneFilesAreNamed) {
    record();
    write("constant/grid", "cellSize: 0.005\n");
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), "constant/grid has changed");
    write("constant/rigidBodies", "rock: {}\n");
    fs::remove(dir_ / "constant/levelSets/rock.vti");
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"),
              "constant/grid has changed, constant/levelSets/rock.vti is gone, "
              "constant/rigidBodies is new");
    write("constant/a", "");
    write("constant/b", "");
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"),
              "constant/grid has changed, constant/levelSets/rock.vti is gone, constant/a is "
              "new and 2 more");
}

TEST_F(SeedingRecordTest, PreloadRecordsTheSchemes) {
    record(true);
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), "");
    write("system/mpmSchemes", "kernel: gimp\n");
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), "system/mpmSchemes has changed");
    fs::remove(dir_ / "system/mpmSchemes");
    EXPECT_EQ(io::seedingChange(Case(dir_), "0"), "system/mpmSchemes is gone");
}

TEST_F(SeedingRecordTest, ProcessorCaseReadsTheRootConstant) {
    fs::create_directories(dir_ / "processor1/0/uniform");
    const Case processor = Case(dir_).processor(1);
    write("processor1/0/uniform/seeding", io::seedingRecord(io::seedingInputs(processor, false)));
    EXPECT_EQ(io::seedingChange(processor, "0"), "");
    write("constant/grid", "cellSize: 0.005\n");
    EXPECT_EQ(io::seedingChange(processor, "0"), "constant/grid has changed");
}

} // namespace
