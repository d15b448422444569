// SPDX-License-Identifier: GPL-3.0-or-later
// reconstructPar: merge the processor<r>/<time>/particles.vtu of a parallel run into
// <time>/particles.vtu (ordered by particle id), copy processor0's restart state (uniform/,
// rigidBodies.vtp) into <time>/ and index the merged files in particles.pvd.
#include "case/Case.hpp"
#include "core/Log.hpp"
#include "io/PvdIndex.hpp"
#include "io/Reconstruct.hpp"
#include "solver/Application.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace mpm;
namespace fs = std::filesystem;

namespace {

using TimeList = std::vector<std::pair<double, std::string>>;

/// The time of `times` named `wanted` (by name, else by value), or an error listing them.
TimeList selectTime(const TimeList& times, const std::string& wanted) {
    for (const auto& t : times)
        if (t.second == wanted) return {t};
    char* end = nullptr;
    const double value = std::strtod(wanted.c_str(), &end);
    if (!wanted.empty() && end == wanted.c_str() + wanted.size()) {
        for (const auto& t : times)
            if (std::abs(t.first - value) <= 1e-12 * std::max(1.0, std::abs(value))) return {t};
    }
    std::string names;
    for (const auto& t : times)
        names += (names.empty() ? "" : " ") + t.second;
    throw std::runtime_error("-time " + wanted + ": no such time in processor0/ (times: " + names +
                             ")");
}

/// Index `<time>/<file>` for each of `times` in `<case>/<series>.pvd`, keeping the timestep of
/// an existing entry of that time directory (the run wrote the exact time, the name rounds it).
void index(const fs::path& root, const std::string& series, const std::string& file,
           const TimeList& times) {
    io::PvdIndex pvd(root / (series + ".pvd"));
    for (const auto& [value, name] : times) {
        if (!fs::is_regular_file(root / name / file)) continue;
        double timestep = value;
        const std::string dir = name + "/";
        for (const io::PvdIndex::Entry& e : pvd.entries())
            if (e.file.compare(0, dir.size(), dir) == 0) timestep = e.time;
        pvd.remove(name);
        pvd.add(timestep, dir + file);
    }
}

} // namespace

int main(int argc, char* argv[]) {
    const Application app(
        argc, argv, "reconstructPar",
        "Merge the processor<N>/<time>/particles.vtu of a parallel run into <time>/particles.vtu "
        "(ordered by particle id), copy processor0's <time>/uniform/ and rigidBodies.vtp into "
        "<time>/, and index the merged times in particles.pvd (and rigidBodies.pvd).",
        {{"-latestTime", "reconstruct only the latest time"},
         {"-time <t>", "reconstruct only time <t> (a time directory name or value)"}});
    return app.run([&] {
        const std::string timeOption = app.value("-time");
        if (!timeOption.empty() && app.has("-latestTime"))
            throw std::runtime_error("-time and -latestTime exclude each other");
        const Case cs(app.caseDir());
        const fs::path& root = cs.root();
        const int numProcessors = io::countProcessors(root);
        if (numProcessors == 0)
            throw std::runtime_error(root.string() +
                                     " has no processor<N> directories: nothing to reconstruct "
                                     "(they are written by a parallel run, mpirun -np N mpmFoam)");
        TimeList times = io::processorTimes(root, numProcessors);
        if (times.empty())
            throw std::runtime_error(root.string() +
                                     "/processor0 has no time directory with particles.vtu");
        if (!timeOption.empty())
            times = selectTime(times, timeOption);
        else if (app.has("-latestTime"))
            times = {times.back()};

        log() << "Reconstructing " << times.size() << (times.size() == 1 ? " time" : " times")
              << " from " << numProcessors << " processor directories\n\n";
        for (const auto& [value, name] : times) {
            const std::size_t points = io::reconstructTime(root, numProcessors, name);
            log() << "Time = " << name << "  points = " << points << "  pieces = " << numProcessors
                  << '\n';
        }
        index(root, "particles", "particles.vtu", times);
        index(root, "rigidBodies", "rigidBodies.vtp", times);
        log() << "\nEnd\n";
    });
}
