// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "particles/Particles.hpp"

#include <sstream>
#include <string>

namespace mpm {

/// The point a failure names, "[rank r: ]particle <id> at (<x>) ", or "" where `particle` is not
/// one of `p`'s: negative (no point), or out of range, as the fastest point of a rank that holds
/// none in a parallel run (checked before anything of the point is read). `rank` ≥ 0 is printed
/// (a parallel run), −1 not.
template <int dim> std::string describePoint(const Particles<dim>& p, Index particle, int rank) {
    if (particle < 0 || particle >= static_cast<Index>(p.size())) return "";
    std::ostringstream os;
    if (rank >= 0) os << "rank " << rank << ": ";
    os << "particle " << p.id[particle] << " at (" << p.x[particle].transpose() << ") ";
    return os.str();
}

} // namespace mpm
