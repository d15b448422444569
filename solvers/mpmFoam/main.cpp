// SPDX-License-Identifier: GPL-3.0-or-later
// mpmFoam: explicit material point method for granular media, run from an OpenFOAM-style case.
#include "case/Time.hpp"
#include "core/Log.hpp"
#include "solver/Application.hpp"
#include "solver/Simulation.hpp"

#include <omp.h>

#include <iomanip>

using namespace mpm;

int main(int argc, char* argv[]) {
    const Application app(argc, argv, "mpmFoam",
                          "Explicit MPM for soils and granular media (2D and 3D).",
                          {{"-dry-run", "check the case and take one step; write nothing"},
                           {"-noFunctionObjects", "do not run controlDict's functions"}});
    return app.run([&] {
        const Case cs(app.caseDir());
        Time time(cs);
        const RunOptions options{app.has("-dry-run"), app.has("-noFunctionObjects")};
        auto sim = Simulation::create(cs, options);
        sim->start(time);
        Time::installSignalHandlers();
        log() << "Starting time loop at t = " << time.value() << " s with " << sim->numParticles()
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
}
