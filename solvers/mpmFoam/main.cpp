// SPDX-License-Identifier: GPL-3.0-or-later
// mpmFoam: explicit material point method for granular media, run from an OpenFOAM-style case.
#include "case/Time.hpp"
#include "core/Error.hpp"
#include "core/KeySchema.hpp"
#include "core/Log.hpp"
#include "parallel/Comm.hpp"
#include "solver/Application.hpp"
#include "solver/PostProcess.hpp"
#include "solver/Simulation.hpp"

#include <cstring>
#include <iostream>

using namespace mpm;

int main(int argc, char* argv[]) {
    bool parallel = false; // -parallel: MPI before anything else reads the command line
    for (int i = 1; i < argc; ++i)
        parallel = parallel || std::strcmp(argv[i], "-parallel") == 0;
    Comm comm = parallel ? Comm::initWorld(argc, argv) : Comm();
    quietLog(!comm.master()); // OpenFOAM's master-only log
    const Application app(
        argc, argv, "mpmFoam", "Explicit MPM for soils and granular media (2D and 3D).",
        {{"-dry-run", "check the case and take one step; write nothing"},
         {"-noFunctionObjects", "do not run controlDict's functions"},
         {"-list [family]", "list every model type (of one family) with its keys and exit"},
         {"-parallel", "run decomposed (mpirun -np N mpmFoam -parallel)"},
         {"-postProcess", "run controlDict's functions on the written times, without stepping"},
         {"-func <name>", "-postProcess: only this function object"},
         {"-time <list>", "-postProcess: these times (0.1, 0.1:0.3, 0.1,0.2, :0.2, 0.2:)"},
         {"-latestTime", "-postProcess: the latest time only"}},
        "Signals: SIGUSR1 writes now and continues; SIGUSR2 or SIGTERM write and "
        "stop.\nA file named 'stop' in the case directory also writes and stops.");
    if (app.has("-list")) { // the model catalogue (core/KeySchema.hpp), without the banner
        const int rc = !comm.master() ? 0 : reportingErrors([&] {
            ModelCatalogue::check();
            ModelCatalogue::list(std::cout, app.value("-list"));
            return 0;
        });
        return comm.finish(rc);
    }
    if (PostProcess::requested(app)) // the function objects on the written times, no stepping
        return comm.finish(app.run([&] { PostProcess(app, comm).run(); }));
    const int rc = app.run([&] {
        ModelCatalogue::check(); // the registrations: no name twice, dimensions declared
        const Case root(app.caseDir());
        const Case cs = comm.parallel() ? root.processor(comm.rank()) : root;
        Time time(cs);
        if (comm.parallel()) time.setAgreement([&comm](bool x) { return comm.any(x); });
        const RunOptions options{app.has("-dry-run"), app.has("-noFunctionObjects")};
        auto sim = Simulation::create(cs, options, comm);
        sim->start(time);
        if (time.restarted() && time.endReached()) { // a finished case, run again
            log() << "endTime " << time.endTime() << " reached at time " << time.name()
                  << ": nothing to do (raise endTime in system/controlDict to continue)\n\nEnd\n";
            return;
        }
        Time::installSignalHandlers();
        const long points = sim->numParticles();
        if (comm.parallel()) log() << "Parallel run on " << comm.size() << " ranks\n";
        log() << "Starting time loop at t = " << time.value() << " s with " << points
              << " particles (" << sim->dimension() << "D)\n\n";

        ProgressMeter progress(time);
        while (time.run()) {
            time.advance(sim->stableDeltaT());
            sim->step(time.deltaT());
            sim->executeFunctions();
            if (options.dryRun) break;
            if (time.writeTime()) {
                sim->write();
                progress.print();
            }
        }
        if (time.writeAtEnd() && !options.dryRun) {
            sim->write();
            progress.print();
        }
        if (options.dryRun)
            log() << "Dry run: the case is valid and one step ran; nothing written.\n";
        sim->report(log());
        reportPeakMemory(log());
        log() << "\nEnd\n";
    });
    // A rank that failed alone would leave the others waiting in a collective: finish stops
    // them all then; a failure every rank saw ends cleanly.
    return comm.finish(rc);
}
