// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/PostProcess.hpp"

#include "case/Case.hpp"
#include "case/Time.hpp"
#include "case/TimeSelection.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "monitors/FunctionObject.hpp"
#include "solver/MpmSimulation.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <vector>

namespace mpm {

namespace fs = std::filesystem;

namespace {

/// "a, b, c" (or "none").
std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

} // namespace

bool PostProcess::requested(const Application& app) {
    return app.has("-postProcess") || app.has("-func") || app.has("-time") ||
           app.has("-latestTime");
}

PostProcess::PostProcess(const Application& app, const Comm& comm)
    : caseDir_(app.caseDir()), func_(app.value("-func")), times_(app.value("-time")),
      latestTime_(app.has("-latestTime")) {
    for (const char* option : {"-func", "-time", "-latestTime"})
        if (app.has(option) && !app.has("-postProcess"))
            throw InputError("", 0, "",
                             std::string(option) + " goes with -postProcess (mpmFoam " +
                                 "-postProcess " + option + " …)");
    if (app.has("-time") && latestTime_)
        throw InputError("", 0, "", "-time and -latestTime exclude each other");
    for (const char* option : {"-dry-run", "-noFunctionObjects"})
        if (app.has(option))
            throw InputError("", 0, "",
                             std::string(option) + " does not go with -postProcess, which takes "
                                                   "no step and runs only the function objects");
    if (comm.parallel())
        throw InputError("", 0, "",
                         "-postProcess runs serially on the reconstructed times: run "
                         "reconstructPar, then mpmFoam -postProcess without -parallel");
}

void PostProcess::run() const {
    const Case cs(caseDir_);
    const Dictionary grid = cs.read("constant/grid");
    if (grid.getInt("dimension", Bounds::closed(2, 3)) == 2)
        process<2>(cs, grid);
    else
        process<3>(cs, grid);
}

template <int dim> void PostProcess::process(const Case& cs, const Dictionary& grid) const {
    Time time(cs);

    // The written times: the root's (a parallel run's, once reconstructPar merged them).
    const TimeSelection::TimeList written = cs.timeDirectories();
    const bool decomposed = fs::is_directory(cs.path("processor0"));
    if (written.empty())
        throw InputError(cs.root().string(), 0, "",
                         decomposed ? "no reconstructed time to post-process: the times of this "
                                      "decomposed case are in its processor folders; run "
                                      "reconstructPar first, then mpmFoam -postProcess"
                                    : "no time directory with particles.vtu to post-process");
    if (decomposed) {
        std::vector<std::string> only; // processor0's times that are not reconstructed
        for (const auto& [value, name] : timeDirectories(cs.path("processor0"), true))
            if (std::none_of(written.begin(), written.end(),
                             [&](const auto& t) { return t.second == name; }))
                only.push_back(name);
        if (!only.empty())
            log() << "Not reconstructed, left out: " << joined(only)
                  << " (reconstructPar to include them)\n";
    }
    const TimeSelection::TimeList selected = latestTime_ ? TimeSelection::TimeList{written.back()}
                                             : times_.empty()
                                                 ? written
                                                 : TimeSelection(times_).select(written);

    // The function objects: those a written time determines (all, or -func's).
    auto all = FunctionObject<dim>::createAll(time.dict());
    const auto typeOf = [&](const FunctionObject<dim>& f) {
        return time.dict().subDict("functions").subDict(f.name()).getString("type");
    };
    std::vector<std::string> valid;
    for (const auto& f : all)
        if (f->needsStep().empty()) valid.push_back(f->name());
    std::vector<std::unique_ptr<FunctionObject<dim>>> functions;
    for (auto& f : all) {
        if (!func_.empty() && f->name() != func_) continue;
        const std::string why = f->needsStep();
        if (why.empty())
            functions.push_back(std::move(f));
        else if (!func_.empty())
            throw InputError("", 0, "",
                             "-func " + func_ + ": " + func_ + " (" + typeOf(*f) + ") " + why +
                                 ", which a written time does not hold (those that can be "
                                 "post-processed: " +
                                 joined(valid) + ")");
        else
            log() << f->name() << " (" << typeOf(*f) << "): " << why << "; skipped\n";
    }
    if (!func_.empty() && functions.empty())
        throw InputError("", 0, "",
                         "-func " + func_ + ": no function object '" + func_ +
                             "' in the functions of system/controlDict (valid: " + joined(valid) +
                             ")");
    if (functions.empty()) {
        log() << "No function object to evaluate from the written times: nothing written\n\nEnd\n";
        return;
    }

    // The state of each time, read as a restart reads it; prepared with the earliest one.
    MpmSimulation<dim> sim(cs, RunOptions{false, true}, grid, serialComm());
    std::string current = written.front().second;
    sim.readTime(time, current);
    for (auto& f : functions)
        f->prepare(sim.state(), time);
    log() << "Post-processing " << selected.size() << (selected.size() == 1 ? " time" : " times")
          << " (" << selected.front().second << " to " << selected.back().second
          << ") without stepping\n\n";
    for (const auto& [value, name] : selected) {
        if (name != current) sim.readTime(time, name);
        current = name;
        if (&name == &selected.front().second)
            for (auto& f : functions) {
                const fs::path file = f->file(cs, time);
                if (fs::exists(file))
                    log() << "Replacing " << fs::relative(file, cs.root()).string()
                          << " (written by an earlier run or post-processing)\n";
                f->open(cs, time);
            }
        const State<dim> state = sim.state();
        for (auto& f : functions)
            f->executeNow(state, time);
        log() << "Time = " << name << '\n';
    }
    log() << "\nEnd\n";
}

} // namespace mpm
