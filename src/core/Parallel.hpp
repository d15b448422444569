// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

namespace mpm {

/// Loops shorter than this run on one thread: waking the team costs more than the work
/// (tiny 2D cases, tests). Results do not depend on it (every parallel loop is deterministic).
constexpr Index ParallelThreshold = 4096;

/// True if a loop of n items is worth a thread team (used in `omp parallel for if(…)`).
constexpr bool worthThreads(Index n) {
    return n >= ParallelThreshold;
}

} // namespace mpm
