// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <ostream>

namespace mpm {

/// Wall time spent in each phase of the step, the steps taken and the particle-update rate.
class PhaseTimer {
public:
    /// Comm: the messages of a parallel run (halo, migration, reductions), a part of the phases
    /// it happens in (reported separately, not added to the total).
    enum Phase {
        Sort,
        Contact,
        P2G,
        Grid,
        G2P,
        Constitutive,
        Bodies,
        IO,
        Functions,
        Comm,
        NumPhases
    };

    /// Adds the wall time of its scope to one phase.
    class Scope {
    public:
        Scope(PhaseTimer& timer, Phase phase);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        double& acc_;
        double t0_;
    };

    Scope operator()(Phase phase) { return Scope(*this, phase); }
    /// Count one step that took `wall` seconds in all.
    void stepDone(double wall) {
        stepWall_ += wall;
        ++steps_;
    }
    long steps() const { return steps_; }
    /// Particle-updates per second over the steps counted.
    double updatesPerSecond(long particles) const {
        return stepWall_ > 0 ? static_cast<double>(particles) * steps_ / stepWall_ : 0.0;
    }
    void reset() { *this = PhaseTimer(); }

    /// The phase table (phases that cannot occur in the run left out) and the particle-updates
    /// per second over the steps.
    void report(std::ostream& os, long particles, bool coupled, bool bodies,
                bool parallel = false) const;
    double seconds(Phase phase) const { return t_[phase]; }
    double stepSeconds() const { return stepWall_; }

    static double now();

private:
    std::array<double, NumPhases> t_{};
    double stepWall_ = 0;
    long steps_ = 0;
};

} // namespace mpm
