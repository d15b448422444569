// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "case/Dictionary.hpp"
#include "parallel/Comm.hpp"
#include "solver/Application.hpp"

#include <string>

namespace mpm {

/// `mpmFoam -postProcess [-func name] [-time list | -latestTime]` (OpenFOAM's
/// `solver -postProcess`): the function objects of system/controlDict evaluated on the written
/// time directories, without stepping. Each time is read as a restart reads it
/// (MpmSimulation::readTime: particles, uniform/time, the bodies' state, the body acceleration's
/// work), so a row equals the live run's row at that time. Every function object is prepared
/// with the earliest written time, as a fresh run prepares it with its initial state, and
/// writes one row per processed time into `postProcessing/<name>/<first processed time>/`,
/// replacing a file of that name (logged). Function objects that read data only a time step has
/// (FunctionObject::needsStep) are skipped with one line each; `-func` of one is an error.
/// Serial only: a decomposed case is post-processed on its reconstructed times (reconstructPar).
class PostProcess {
public:
    /// True when the command line asks for post-processing (-postProcess, or one of its
    /// options, which the constructor then refuses without it).
    static bool requested(const Application& app);

    /// The options of `app`; an InputError for -func, -time or -latestTime without
    /// -postProcess, -time with -latestTime, -dry-run or -noFunctionObjects with -postProcess,
    /// and -parallel (run reconstructPar, then post-process serially).
    PostProcess(const Application& app, const Comm& comm);

    /// Evaluate the function objects on the selected times and write their rows; an InputError
    /// for a case without written times (a decomposed one: reconstructPar first), a -time
    /// list that selects none, an unknown -func (listing the valid names) or one that needs a
    /// time step.
    void run() const;

private:
    template <int dim> void process(const Case& cs, const Dictionary& grid) const;

    std::string caseDir_;
    std::string func_;  ///< -func: only this function object ("": all)
    std::string times_; ///< -time list ("": all times)
    bool latestTime_ = false;
};

} // namespace mpm
