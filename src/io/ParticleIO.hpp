// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "io/ParticleFile.hpp"
#include "particles/Particles.hpp"

#include <string>

namespace mpm::io {

/// The written fields of `p` (Particles::visitTable, in its order) as a point cloud: positions as
/// points, doubles as Float64 and integers as Int64 arrays, vectors with 3 and tensors with 9
/// components (2D zero-padded; a deformation gradient with zz = 1).
template <int dim> PointCloud toPointCloud(const Particles<dim>& p);

/// Read the restart fields of `p` (whose model state is declared) from `cloud`; `file` names the
/// source in errors (an array missing or with the wrong number of components).
template <int dim>
void fromPointCloud(const PointCloud& cloud, Particles<dim>& p, const std::string& file);

} // namespace mpm::io
