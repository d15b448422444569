// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/PvtuFile.hpp"

#include "io/XmlFile.hpp"

#include <cstdint>
#include <cstring>

namespace mpm::io {

namespace {

/// The byte order the VTK writers write: the machine's own.
const char* byteOrder() {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1 ? "LittleEndian" : "BigEndian";
}

std::string dataArray(const char* type, const std::string& name, int components) {
    std::string line =
        "      <PDataArray type=\"" + std::string(type) + "\" Name=\"" + escapeXml(name) + "\"";
    if (components != 1) {
        line += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    }
    return line + "/>\n";
}

} // namespace

void writePvtu(const std::filesystem::path& file, const PointCloud& layout,
               const std::vector<std::string>& pieces) {
    std::string text = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"" +
                       std::string(byteOrder()) +
                       "\" header_type=\"UInt64\">\n"
                       "  <PUnstructuredGrid GhostLevel=\"0\">\n"
                       "    <PPointData>\n";
    for (const PointArray& a : layout.arrays) {
        if (a.components < 1) {
            cannotWrite(file, "array '" + a.name + "' has fewer than one component");
        }
        text += dataArray(a.isInteger() ? "Int64" : "Float64", a.name, a.components);
    }
    text += "    </PPointData>\n"
            "    <PCellData>\n"
            "    </PCellData>\n"
            "    <PPoints>\n" +
            dataArray("Float64", "Points", 3) +
            "    </PPoints>\n"
            "    <PCells>\n" +
            dataArray("Int64", "connectivity", 1) + dataArray("Int64", "offsets", 1) +
            dataArray("UInt8", "types", 1) + "    </PCells>\n";
    for (const std::string& piece : pieces) {
        text += "    <Piece Source=\"" + escapeXml(piece) + "\"/>\n";
    }
    text += "  </PUnstructuredGrid>\n"
            "</VTKFile>\n";
    writeTextAtomic(file, text);
}

} // namespace mpm::io
