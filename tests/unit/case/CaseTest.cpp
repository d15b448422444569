// SPDX-License-Identifier: GPL-3.0-or-later
// Processor cases of a parallel run: time directories of their own, system/ and constant/ read
// from the root case unless the processor directory has the file; messages name the processor
// folder.
#include "case/Case.hpp"
#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace mpm {
namespace {

namespace fs = std::filesystem;

class CaseTest : public test::TempDirTest {
protected:
    void write(const fs::path& file, const std::string& text) {
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
    }
};

TEST_F(CaseTest, ProcessorCaseReadsTheRootsFilesAndKeepsItsOwnTimes) {
    write(dir_ / "system" / "controlDict", "endTime: 1\n");
    write(dir_ / "constant" / "grid", "cellSize: 0.1\n");
    write(dir_ / "processor1" / "constant" / "decomposition", "numberOfSubdomains: 2\n");
    write(dir_ / "0.5" / "particles.vtu", "");
    write(dir_ / "processor1" / "0.25" / "particles.vtu", "");
    const Case root(dir_);
    const Case p = root.processor(1);
    EXPECT_EQ(p.root(), dir_ / "processor1");
    EXPECT_EQ(p.globalRoot(), root.root());
    EXPECT_EQ(p.read("system/controlDict").getScalar("endTime"), 1.0);
    EXPECT_EQ(p.read("constant/grid").getScalar("cellSize"), 0.1);
    EXPECT_TRUE(p.exists("constant/decomposition"));
    EXPECT_FALSE(root.exists("constant/decomposition"));
    ASSERT_EQ(p.timeDirectories().size(), 1u);
    EXPECT_EQ(p.timeDirectories()[0].second, "0.25");
    EXPECT_EQ(root.timeDirectories()[0].second, "0.5");
}

TEST_F(CaseTest, ProcessorFilesAreNamedWithTheirFolderAndNeverTakenFromTheRoot) {
    write(dir_ / "system" / "controlDict", "endTime: 1\n");
    write(dir_ / "0.004" / "uniform" / "time", "value: 0.004\n"); // the root's (parallel run)
    write(dir_ / "processor1" / "0.004" / "particles.vtu", "");
    write(dir_ / "processor1" / "0.004" / "uniform" / "rigidBodies", "bodies: [1, 2\n");
    const Case p = Case(dir_).processor(1);
    EXPECT_EQ(p.displayName("system/controlDict"), "system/controlDict");
    EXPECT_EQ(p.displayName("system/mpmSchemes"), "system/mpmSchemes"); // missing: the root's
    EXPECT_EQ(p.displayName("0.004/uniform/time"), "processor1/0.004/uniform/time");
    EXPECT_EQ(Case(dir_).displayName("0.004/uniform/time"), "0.004/uniform/time");
    // A time directory's file is the processor's own: the root's copy does not stand in.
    EXPECT_FALSE(p.exists("0.004/uniform/time"));
    const InputError missing = test::catchInputError([&] { (void)p.read("0.004/uniform/time"); });
    EXPECT_EQ(missing.file(), "processor1/0.004/uniform/time");
    const InputError corrupt =
        test::catchInputError([&] { (void)p.read("0.004/uniform/rigidBodies"); });
    EXPECT_EQ(corrupt.file(), "processor1/0.004/uniform/rigidBodies");
}

TEST_F(CaseTest, AMissingProcessorDirectoryIsAnInputError) {
    write(dir_ / "system" / "controlDict", "endTime: 1\n");
    const Case root(dir_);
    const InputError e = test::catchInputError([&] { (void)root.processor(3); });
    EXPECT_NE(std::string(e.what()).find("processor3"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("decomposePar"), std::string::npos);
}

} // namespace
} // namespace mpm
