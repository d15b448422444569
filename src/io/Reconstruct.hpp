// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mpm::io {

/// The number N of `processor<r>` directories of a parallel run's case; they must be
/// processor0 … processor(N−1), without gap (std::runtime_error naming the first missing one
/// otherwise). 0 when the case has none.
int countProcessors(const std::filesystem::path& caseRoot);

/// The time directories (value, name) of a parallel run: those of processor0 that hold a
/// particles.vtu, sorted by value. Every other processor directory must have the same times
/// (std::runtime_error naming the missing `processor<r>/<time>/particles.vtu` otherwise).
std::vector<std::pair<double, std::string>> processorTimes(const std::filesystem::path& caseRoot,
                                                           int numProcessors);

/// Reconstruct time `timeName` of a parallel run (reconstructPar): concatenate the particles of
/// `processor<r>/<time>/particles.vtu`, r < numProcessors, ordered by their `id` array (stable),
/// into `<case>/<time>/particles.vtu`, and copy every other entry of `processor0/<time>/`
/// (uniform/, rigidBodies.vtp, …) into `<case>/<time>/`, overwriting; `<case>/<time>/` keeps
/// its other files (particles.pvtu). Returns the number of points. Throws std::runtime_error
/// naming the piece for a missing or unreadable piece, arrays that differ from processor0's
/// (names, types or components), a missing or non-integer `id` array, or a duplicate id.
std::size_t reconstructTime(const std::filesystem::path& caseRoot, int numProcessors,
                            const std::string& timeName);

} // namespace mpm::io
