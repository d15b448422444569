// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Log.hpp"
#include "core/Types.hpp"
#include "particles/ParticleSeeder.hpp"
#include "solver/PhaseTimer.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

/// The quiet window of the preload: a period of the slowest vertical mode, 4 L/c, with L the
/// extent of the box `size` along g (an upper bound of the material's height) [s].
template <int dim> double preloadWindow(const Vec<dim>& g, const Vec<dim>& size, double c) {
    double extent = 0;
    for (int d = 0; d < dim; ++d)
        extent += std::fabs(g[d]) / g.norm() * size[d];
    return 4.0 * extent / c;
}

/// The gravity preload [000 §4.2]: the material is loaded by gravity with local damping until
/// its kinetic energy is nearly zero; bodies wait. E_k also vanishes at the turning points of an
/// oscillation, so it must stay below `tolerance` × its peak for a whole `window` (a period of
/// the slowest vertical mode). `stepFn(k, dt)` takes damped step k, sets its size dt and returns
/// E_k after it.
/// Returns the number of steps taken.
template <class StepFn>
long runGravityPreload(const PreloadSettings& s, double window, StepFn&& stepFn) {
    const double t0 = PhaseTimer::now();
    double peak = 0, kinetic = 0, quiet = 0;
    long k = 0;
    for (; k < s.maxSteps; ++k) {
        double dt = 0;
        kinetic = stepFn(k, dt);
        peak = std::max(peak, kinetic);
        quiet = kinetic <= s.tolerance * peak ? quiet + dt : 0.0;
        if (quiet >= window) break;
    }
    const double ratio = kinetic / std::max(peak, 1e-300);
    if (k == s.maxSteps)
        warning() << "gravity preload: kinetic energy still " << ratio << " of its peak after " << k
                  << " steps (maxSteps); continuing\n";
    log() << "Gravity preload: " << k << " steps, kinetic energy " << kinetic << " J (" << ratio
          << " of its peak), " << PhaseTimer::now() - t0 << " s\n";
    return k;
}

} // namespace mpm
