// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mpm::io {

/// The 0/ that a fresh start writes is generated from the case's inputs (the seeding of
/// constant/particles in the grid of constant/grid, with the materials, gravity and bodies of
/// constant/, and the gravity preload's steps under system/mpmSchemes). It records what it was
/// generated from in `0/uniform/seeding`: one line `<hash>  <file>` for every file under the
/// case's constant/ (hidden files and editor backups `*~` left out) and, after a gravity
/// preload, system/mpmSchemes; the hash is FNV-1a 64 of the file's bytes. A restart from a time
/// directory with such a record whose inputs have changed since seeds again instead
/// (docs/caseFormat.md §9); a time directory without one (later times, or a 0/ written by hand or
/// by a script) is used as it is.

/// Relative path (from the whole case's root) and hash of each input, sorted by path.
using SeedingInputs = std::vector<std::pair<std::string, std::string>>;

/// The inputs of a fresh start of `cs` (a processor case reads the root case's constant/);
/// `preload`: the seeding ran a gravity preload, so system/mpmSchemes is one too.
SeedingInputs seedingInputs(const Case& cs, bool preload);

/// The text of `<time>/uniform/seeding` for `inputs`.
std::string seedingRecord(const SeedingInputs& inputs);

/// What changed since time directory `timeDir` of `cs` was seeded, e.g. "constant/grid has
/// changed" or "constant/bodyContact is new" (at most three, then how many more); "" when it
/// has no uniform/seeding (not seeded by mpmFoam: kept as it is) or nothing changed.
std::string seedingChange(const Case& cs, const std::string& timeDir);

/// FNV-1a 64 of the bytes of `file` as 16 hexadecimal digits ("" when it cannot be read).
std::string fileHash(const std::filesystem::path& file);

} // namespace mpm::io
