// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace mpm {

/// What a face or patch of the grid box is, by its `type:` word: constrained by a registered
/// condition (BoundaryCondition: slip, noSlip, …), `open` (no constraint and no reaction; a
/// point more than a cell beyond it has left and is removed) or `periodic` (one face of a
/// periodic pair, whole faces only, its partner the opposite face; the lattice is folded
/// instead, PeriodicLattice). The registry holds only the conditions; BoundaryConditions
/// handles open and periodic itself.
enum class FaceKind { constrained, open, periodic };
/// The kind the word `type` names: open, periodic, or constrained (any other word).
FaceKind faceKind(const std::string& type);
/// The words of the kinds that are not conditions, sorted: open, periodic.
std::vector<std::string> faceKindWords();

/// Every valid `type:` of a face or patch in dimension `dim`, sorted: the registered conditions
/// and the face kinds. The family boundaryConditions (`mpmFoam -list`) lists these.
template <int dim> std::vector<std::string> boundaryTypeNames();

} // namespace mpm
