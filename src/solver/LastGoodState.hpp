// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Time.hpp"
#include "particles/Particles.hpp"
#include "rigid/BodySet.hpp"

#include <string>
#include <vector>

namespace mpm {

/// A recent state known to be good (particles, bodies, time), kept so that a run that fails
/// writes it before stopping rather than the broken one.
template <int dim> class LastGoodState {
public:
    void save(const Particles<dim>& p, const BodySet<dim>& bodies, const Time& time) {
        particles_ = p;
        bodies_ = bodies.saveState();
        time_ = time.value();
        index_ = time.index();
        deltaT_ = time.deltaT();
        valid_ = true;
    }
    /// Put the saved state back (false if none was saved).
    bool restore(Particles<dim>& p, BodySet<dim>& bodies, Time& time) const {
        if (!valid_) return false;
        p = particles_;
        bodies.restoreState(bodies_);
        time.setStart(time_, index_, deltaT_);
        return true;
    }

private:
    Particles<dim> particles_;
    std::vector<std::string> bodies_;
    double time_ = 0, deltaT_ = 0;
    long index_ = 0;
    bool valid_ = false;
};

} // namespace mpm
