// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "case/Time.hpp"
#include "io/PvdIndex.hpp"
#include "parallel/Comm.hpp"
#include "particles/Particles.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mpm::io {

/// Writes a run's time directories — `<time>/particles.vtu`, `<time>/uniform/time` and what
/// else the caller adds — never half-written (a temporary folder renamed into place), indexes
/// them in the case's `.pvd` files for ParaView and purges the old ones (purgeWrite).
class TimeDirectoryWriter {
public:
    /// `indices`: the ParaView series, e.g. {"particles", "rigidBodies"}: `<case>/<name>.pvd`
    /// indexing `<time>/<name>.vtu|.vtp` (the extension is the file's own, given in write()).
    TimeDirectoryWriter(const Case& cs, std::vector<std::string> indices);

    /// Write the current time of `time`: `fill(folder)` writes every file into `folder`;
    /// `files[k]` is the file of series k inside the time directory (e.g. "particles.vtu").
    /// Records the write in `time` (Time::wrote) and purges the directories it names, or, when
    /// `purge` is given (a second writer of the same time: the root of a parallel run), purges
    /// those. Returns the directories purged.
    std::vector<std::string> write(Time& time,
                                   const std::function<void(const std::filesystem::path&)>& fill,
                                   const std::vector<std::string>& files,
                                   const std::vector<std::string>* purge = nullptr);

private:
    const Case& case_;
    std::vector<std::string> names_;
    std::vector<std::unique_ptr<PvdIndex>> pvd_;
};

/// The time directory a run starts from (system/controlDict startFrom: latestTime, firstTime,
/// or startTime when a directory has that time), or "" for a fresh start. A startTime other
/// than 0 without its directory is an InputError.
std::string restartDirectory(const Case& cs, const Time& time);

/// The time directory a run on the ranks of `comm` starts from, the same on every rank
/// (collective; a serial Comm gives restartDirectory(cs, time)). With startFrom latestTime: the
/// latest time every processor folder holds complete (a time directory with particles.vtu: the
/// writer renames it into place once written, a staging `.<time>.writing` folder is none), "" when
/// no processor holds a time; newer times only some processors hold (a run killed while writing)
/// are logged and left, to be overwritten as the run proceeds. Otherwise every rank must find
/// the same directory. An InputError on every rank when no time is common to all processors
/// (naming each one's times) or when a rank's startTime has no directory (naming its folder).
std::string restartDirectory(const Case& cs, const Time& time, const Comm& comm);

/// Read the particles of time directory `timeDir` (its particles.vtu) for a restart into `p`,
/// whose model state is declared; every restart field must be present and every material index
/// below `numMaterials` (InputError naming the file otherwise).
template <int dim>
void readParticles(const Case& cs, const std::string& timeDir, Particles<dim>& p,
                   std::size_t numMaterials);

} // namespace mpm::io
