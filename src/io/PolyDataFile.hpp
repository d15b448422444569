// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mpm::io {

/// One point- or cell-data array of a surface file: `components` doubles per point (or cell),
/// tuple-major (x0 y0 z0 x1 y1 z1 …).
struct DataArray {
    std::string name;
    int components = 1;
    std::vector<double> values;
};

/// Write a surface as a VTK XML PolyData (.vtp): polygons (triangles in 3D) or, with `lines`,
/// line cells (2D outlines); each cell lists point indices. Appended raw binary, LZ4, UInt64
/// headers, Float64 arrays; written to `<file>.tmp` then renamed. Throws std::runtime_error
/// naming the file on failure (also for an index out of range or an array of the wrong size).
void writeVtp(const std::filesystem::path& file, const std::vector<Vec3>& points,
              const std::vector<std::vector<int>>& cells, bool lines,
              const std::vector<DataArray>& pointData = {},
              const std::vector<DataArray>& cellData = {});

} // namespace mpm::io
