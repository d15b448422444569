// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "case/Time.hpp"
#include "parallel/Comm.hpp"

#include <memory>
#include <ostream>
#include <string>

namespace mpm {

/// Command-line switches that change what a run does.
struct RunOptions {
    bool dryRun = false;            ///< check the case, take one step, write nothing
    bool noFunctionObjects = false; ///< skip controlDict `functions`
};

/// The dimension-independent face of a simulation, as `main` drives it.
class Simulation {
public:
    virtual ~Simulation() = default;

    /// Seed the particles from constant/ (fresh start) or read the time directory to restart
    /// from, set `time`'s start, and write the initial state on a fresh start.
    virtual void start(Time& time) = 0;
    /// The largest stable Δt now: maxCo · h / max(c + |v|) [s].
    virtual double stableDeltaT() const = 0;
    /// One explicit MPM step of size dt (docs/architecture.md).
    virtual void step(double dt) = 0;
    /// Run the function objects due at this time.
    virtual void executeFunctions() = 0;
    /// Write the current state as a time directory and update the .pvd index.
    virtual void write() = 0;
    /// Phase timings and particle-updates per second.
    virtual void report(std::ostream& os) const = 0;
    virtual long numParticles() const = 0;
    virtual int dimension() const = 0;

    /// Read constant/grid's `dimension` and build the 2D or 3D simulation of the case; `comm`:
    /// the ranks of a parallel run (then `cs` is this rank's processor case).
    static std::unique_ptr<Simulation> create(const Case& cs, const RunOptions& options,
                                              const Comm& comm = serialComm());
};

} // namespace mpm
