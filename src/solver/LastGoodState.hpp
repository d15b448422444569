// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Time.hpp"
#include "particles/Particles.hpp"
#include "rigid/BodySet.hpp"

#include <string>
#include <utility>
#include <vector>

namespace mpm {

/// What a written time directory holds besides the points and the bodies: the work of a
/// time-varying g (`uniform/accelerationWork`) and the walls' contact under USF
/// (`uniform/wallContact`, BoundaryConditions::wallContact).
struct SolverState {
    double accelerationWork = 0;                    ///< State::accelerationWork [J]
    std::vector<std::pair<Index, int>> wallContact; ///< (node, axis bits)
};

/// A recent state known to be good (particles, bodies, time and the solver's own restart state),
/// kept so that a run that fails writes it before stopping rather than the broken one: every
/// file of the written time directory belongs to that time.
template <int dim> class LastGoodState {
public:
    void save(const Particles<dim>& p, const BodySet<dim>& bodies, const Time& time,
              SolverState solver) {
        particles_ = p;
        bodies_ = bodies.saveState();
        solver_ = std::move(solver);
        time_ = time.value();
        index_ = time.index();
        deltaT_ = time.deltaT();
        valid_ = true;
    }
    /// Put the saved state back (false if none was saved).
    bool restore(Particles<dim>& p, BodySet<dim>& bodies, Time& time, SolverState& solver) const {
        if (!valid_) return false;
        p = particles_;
        bodies.restoreState(bodies_);
        solver = solver_;
        time.setStart(time_, index_, deltaT_);
        return true;
    }

private:
    Particles<dim> particles_;
    std::vector<std::string> bodies_;
    SolverState solver_;
    double time_ = 0, deltaT_ = 0;
    long index_ = 0;
    bool valid_ = false;
};

} // namespace mpm
