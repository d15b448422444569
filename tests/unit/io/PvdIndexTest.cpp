// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/PvdIndex.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace {

using mpm::io::PvdIndex;
namespace fs = std::filesystem;

/// A fresh, empty folder per test, removed afterwards.
class PvdIndexTest : public mpm::test::TempDirTest {
protected:
    std::string text() const {
        std::ifstream in(file_, std::ios::binary);
        std::ostringstream out;
        out << in.rdbuf();
        return out.str();
    }

    fs::path file_ = dir_ / "particles.pvd";
};

const std::string head = "<?xml version=\"1.0\"?>\n"
                         "<VTKFile type=\"Collection\" version=\"0.1\" "
                         "byte_order=\"LittleEndian\">\n"
                         "  <Collection>\n";
const std::string tail = "  </Collection>\n"
                         "</VTKFile>\n";

std::string dataSet(const std::string& time, const std::string& file) {
    return "    <DataSet timestep=\"" + time + "\" group=\"\" part=\"0\" file=\"" + file + "\"/>\n";
}

TEST_F(PvdIndexTest, NoFileUntilFirstAdd) {
    PvdIndex index(file_);
    EXPECT_TRUE(index.entries().empty());
    EXPECT_FALSE(fs::exists(file_));
}

TEST_F(PvdIndexTest, ExactText) {
    PvdIndex index(file_);
    index.add(0.5, "0.5/particles.vtu");
    EXPECT_EQ(text(), head + dataSet("0.5", "0.5/particles.vtu") + tail);
    index.add(0.05, "0.05/particles.vtu");
    index.add(0, "0/particles.vtu");
    EXPECT_EQ(text(), head + dataSet("0", "0/particles.vtu") +
                          dataSet("0.050000000000000003", "0.05/particles.vtu") +
                          dataSet("0.5", "0.5/particles.vtu") + tail);
    EXPECT_FALSE(fs::exists(dir_ / "particles.pvd.tmp"));
}

TEST_F(PvdIndexTest, EmptyIndexText) {
    PvdIndex index(file_);
    index.add(1, "1/particles.vtu");
    index.remove("1/particles.vtu");
    EXPECT_EQ(text(), head + tail);
}

TEST_F(PvdIndexTest, AddKeepsSortedAndReplacesSameTime) {
    PvdIndex index(file_);
    index.add(0.3, "0.3/a.vtu");
    index.add(0.1, "0.1/a.vtu");
    index.add(0.2, "0.2/a.vtu");
    index.add(0.1, "0.1/b.vtu");
    ASSERT_EQ(index.entries().size(), 3u);
    EXPECT_EQ(index.entries()[0].time, 0.1);
    EXPECT_EQ(index.entries()[0].file, "0.1/b.vtu");
    EXPECT_EQ(index.entries()[1].time, 0.2);
    EXPECT_EQ(index.entries()[2].time, 0.3);
    EXPECT_EQ(text(), head + dataSet("0.10000000000000001", "0.1/b.vtu") +
                          dataSet("0.20000000000000001", "0.2/a.vtu") +
                          dataSet("0.29999999999999999", "0.3/a.vtu") + tail);
}

TEST_F(PvdIndexTest, RemoveByFileOrTimeDirectory) {
    PvdIndex index(file_);
    index.add(0.1, "0.1/particles.vtu");
    index.add(0.2, "0.2/particles.vtu");
    index.add(0.3, "0.3/particles.vtu");
    index.remove("0.2/particles.vtu");
    ASSERT_EQ(index.entries().size(), 2u);
    EXPECT_EQ(index.entries()[0].file, "0.1/particles.vtu");
    EXPECT_EQ(index.entries()[1].file, "0.3/particles.vtu");
    index.remove("0.1");
    ASSERT_EQ(index.entries().size(), 1u);
    EXPECT_EQ(index.entries()[0].file, "0.3/particles.vtu");
    index.remove("0.30"); // not the same directory
    index.remove("nothing/particles.vtu");
    EXPECT_EQ(index.entries().size(), 1u);
    EXPECT_EQ(text(), head + dataSet("0.29999999999999999", "0.3/particles.vtu") + tail);
}

TEST_F(PvdIndexTest, ReloadIsExact) {
    const double times[] = {0.0, 1e-7, 0.1, 1.0 / 3.0, 2.5, 1e5};
    {
        PvdIndex index(file_);
        for (const double t : times) {
            index.add(t, "dir/" + std::to_string(t) + ".vtu");
        }
    }
    const std::string before = text();
    PvdIndex reloaded(file_);
    ASSERT_EQ(reloaded.entries().size(), std::size(times));
    for (std::size_t i = 0; i < std::size(times); ++i) {
        EXPECT_EQ(reloaded.entries()[i].time, times[i]); // bit-exact through %.17g
        EXPECT_EQ(reloaded.entries()[i].file, "dir/" + std::to_string(times[i]) + ".vtu");
    }
    reloaded.add(7, "7/particles.vtu");
    reloaded.remove("7/particles.vtu");
    EXPECT_EQ(text(), before);
}

TEST_F(PvdIndexTest, KeepUpToDropsLaterEntries) {
    {
        PvdIndex index(file_);
        index.add(0.1, "0.1/particles.vtu");
        index.add(0.2, "0.2/particles.vtu");
        index.add(0.3, "0.3/particles.vtu");
    }
    PvdIndex restarted(file_, 0.2);
    ASSERT_EQ(restarted.entries().size(), 2u);
    EXPECT_EQ(restarted.entries()[1].file, "0.2/particles.vtu");
    // The dropped entry is gone from the file as well.
    EXPECT_EQ(PvdIndex(file_).entries().size(), 2u);
    restarted.add(0.25, "0.25/particles.vtu");
    EXPECT_EQ(PvdIndex(file_).entries().size(), 3u);
}

TEST_F(PvdIndexTest, ParsesForeignLayoutAndSkipsBadEntries) {
    std::ofstream(file_) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">"
                            "<Collection><DataSet part='0' file='b&amp;c.vtu' timestep = '2'/>"
                            "<DataSet timestep=\"abc\" file=\"bad.vtu\"/>"
                            "<DataSet timestep=\"1\"/>"
                            "<DataSet\n  timestep=\"1e-3\"\n  file=\"a.vtu\" />"
                            "</Collection></VTKFile>";
    PvdIndex index(file_);
    ASSERT_EQ(index.entries().size(), 2u);
    EXPECT_EQ(index.entries()[0].time, 1e-3);
    EXPECT_EQ(index.entries()[0].file, "a.vtu");
    EXPECT_EQ(index.entries()[1].time, 2.0);
    EXPECT_EQ(index.entries()[1].file, "b&c.vtu");
    index.add(3, "c.vtu");
    EXPECT_NE(text().find("file=\"b&amp;c.vtu\""), std::string::npos) << text();
}

TEST_F(PvdIndexTest, MalformedFileIsIgnored) {
    std::ofstream(file_) << "garbage <DataSet timestep=";
    PvdIndex index(file_);
    EXPECT_TRUE(index.entries().empty());
    index.add(1, "1/particles.vtu");
    EXPECT_EQ(text(), head + dataSet("1", "1/particles.vtu") + tail);
}

} // namespace
