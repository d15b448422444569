// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "rigid/RigidBody.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace mpm {

/// Write every body's surface at its world pose x + R p into one .vtp (triangles in 3D, line
/// segments in 2D, z = 0), with cell data `body` (index in `bodies`) and point data `velocity`
/// (rigid velocity v + ω × r at the point, 3 components).
template <int dim>
void writeRigidBodies(const std::filesystem::path& vtpFile,
                      const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies);

/// Write `<time>/uniform/rigidBodies`: a YAML map body name → RigidBody::writeState, in full
/// precision, atomically (parent folders are created).
template <int dim>
void writeRigidBodyState(const std::filesystem::path& file,
                         const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies);

/// Read the state written by writeRigidBodyState back into `bodies`: every body must be present
/// and no other (InputError otherwise).
template <int dim>
void readRigidBodyState(const Dictionary& dict,
                        const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies);

} // namespace mpm
