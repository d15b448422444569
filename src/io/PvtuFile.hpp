// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "io/ParticleFile.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mpm::io {

/// Write the VTK XML `PUnstructuredGrid` (`.pvtu`) of a parallel run's particles: one
/// `<Piece Source="…"/>` per entry of `pieces` (paths relative to the `.pvtu`, e.g.
/// `../processor3/0.1/particles.vtu`), each a file written by writeVtu. The header declares
/// what writeVtu writes: version 1.0, the machine's byte order, UInt64 headers, every array of
/// `layout` (name, Float64 or Int64, components) as point data, Float64×3 points and the cells
/// (Int64 connectivity and offsets, UInt8 types). Only the arrays' names, types and components
/// of `layout` are used: it may have no points. Written atomically (writeTextAtomic); throws
/// std::runtime_error naming the file on failure.
void writePvtu(const std::filesystem::path& file, const PointCloud& layout,
               const std::vector<std::string>& pieces);

} // namespace mpm::io
