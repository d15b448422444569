// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <Eigen/Dense>
#include <cstdint>

namespace mpm {

/// Spatial vector of a dim-dimensional scene (double precision).
template <int dim> using Vec = Eigen::Matrix<double, dim, 1>;
/// Second-order tensor of a dim-dimensional scene.
template <int dim> using Mat = Eigen::Matrix<double, dim, dim>;
/// Integer grid coordinate.
template <int dim> using IVec = Eigen::Matrix<int, dim, 1>;

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Index = std::int64_t;

} // namespace mpm
