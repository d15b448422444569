// SPDX-License-Identifier: GPL-3.0-or-later
// Processor cases of a parallel run: time directories of their own, system/ and constant/ read
// from the root case unless the processor directory has the file.
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

TEST_F(CaseTest, AMissingProcessorDirectoryIsAnInputError) {
    write(dir_ / "system" / "controlDict", "endTime: 1\n");
    const Case root(dir_);
    const InputError e = test::catchInputError([&] { (void)root.processor(3); });
    EXPECT_NE(std::string(e.what()).find("processor3"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("decomposePar"), std::string::npos);
}

} // namespace
} // namespace mpm
