// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "levelset/SignedDistance.hpp"

#include <filesystem>

namespace mpm::levelset {

/// A body's signed-distance grid, in the body frame, with the mass properties of its surface.
struct LevelSet {
    RegularGrid grid;                     ///< φ (negative inside) at the grid nodes
    double volume = 0.0;                  ///< enclosed volume
    Vec3 centroid = Vec3::Zero();         ///< centroid in the mesh frame
    Vec3 principalMoments = Vec3::Zero(); ///< unit-density principal moments of inertia
    Mat3 rotation = Mat3::Identity();     ///< x_mesh = centroid + rotation · x_body
};

/// Write a `.vti` (vtkImageData): point array `phi` (Float32, or Float64 if `doublePrecision`),
/// Origin/Spacing/Dimensions of the grid, and field data `volume` (1), `centroid` (3),
/// `principalMoments` (3) and `rotation` (9, row-major). Written atomically (io/XmlFile.hpp).
void writeVti(const std::filesystem::path& file, const LevelSet& levelSet,
              bool doublePrecision = false);

/// Read a file written by writeVti; throws std::runtime_error naming the file if it is missing,
/// not vtkImageData, or lacks `phi` or a field-data entry.
LevelSet readVti(const std::filesystem::path& file);

} // namespace mpm::levelset
