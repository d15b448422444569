// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/PhaseTimer.hpp"

#include <omp.h>

#include <iomanip>

namespace mpm {

double PhaseTimer::now() {
    return omp_get_wtime();
}

PhaseTimer::Scope::Scope(PhaseTimer& timer, Phase phase) : acc_(timer.t_[phase]), t0_(now()) {}

PhaseTimer::Scope::~Scope() {
    acc_ += now() - t0_;
}

void PhaseTimer::report(std::ostream& os, long particles, bool coupled, bool bodies,
                        bool parallel) const {
    const double total = stepWall_ + t_[IO] + t_[Functions];
    auto line = [&](const char* name, double t) {
        os << "    " << std::left << std::setw(14) << name << std::right << std::setw(10)
           << std::fixed << std::setprecision(3) << t << " s " << std::setw(6)
           << std::setprecision(1) << (total > 0 ? 100.0 * t / total : 0.0) << " %\n";
    };
    os << "\nPhase timing (" << steps_ << " steps, " << particles << " particles, "
       << omp_get_max_threads() << " threads):\n";
    line("sort", t_[Sort]);
    if (coupled) line("contact", t_[Contact]);
    line("P2G", t_[P2G]);
    line("grid", t_[Grid]);
    line("G2P", t_[G2P]);
    line("constitutive", t_[Constitutive]);
    if (bodies) line("rigid bodies", t_[Bodies]);
    line("functions", t_[Functions]);
    line("IO", t_[IO]);
    line("total", total);
    if (parallel) line("of which comm", t_[Comm]);
}

} // namespace mpm
