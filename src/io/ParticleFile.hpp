// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mpm::io {

/// One point-data array of a particle file. Exactly one of f64 / i64 is filled, with
/// components × number-of-points entries (tuple-major: x0 y0 z0 x1 y1 z1 ...).
struct PointArray {
    std::string name;
    int components = 1;
    std::vector<double> f64;
    std::vector<std::int64_t> i64;

    bool isInteger() const { return !i64.empty() || (f64.empty() && integer); }
    bool integer = false; ///< type of an empty array
};

/// Particles as written to / read from a `.vtu`: points always 3D (z = 0 in 2D scenes).
struct PointCloud {
    std::vector<double> points; ///< 3 × n
    std::vector<PointArray> arrays;

    std::size_t size() const { return points.size() / 3; }
    const PointArray* find(const std::string& name) const;
};

/// Write `cloud` as a VTK XML UnstructuredGrid with one VTK_VERTEX cell per point:
/// appended raw binary, LZ4-compressed, UInt64 headers, Float64 / Int64 arrays.
/// Written to `<file>.tmp` then renamed, so a reader never sees a half-written file.
/// Throws std::runtime_error on failure.
void writeVtu(const std::filesystem::path& file, const PointCloud& cloud);

/// Read a file written by writeVtu (any VTK XML UnstructuredGrid with point data).
/// Throws std::runtime_error naming the file when it is missing or unreadable.
PointCloud readVtu(const std::filesystem::path& file);

/// Write text to `file` atomically (temporary name in the same folder, then rename).
void writeTextAtomic(const std::filesystem::path& file, const std::string& text);

/// Write `key: value` (17 significant digits, read back exactly) to `file` atomically, creating
/// its folder: a number of the restart state such as `<time>/uniform/accelerationWork`.
void writeScalarFile(const std::filesystem::path& file, const std::string& key, double value);

/// Write a list of (index, flags) pairs as `key: [i, …]` and `flags: [f, …]` to `file`
/// atomically, creating its folder (restart state such as `<time>/uniform/wallContact`).
void writeIndexFlags(const std::filesystem::path& file, const std::string& key,
                     const std::vector<std::pair<Index, int>>& pairs);

} // namespace mpm::io
