// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "particles/Particles.hpp"

#include <cstddef>
#include <vector>

namespace mpm::test {

/// n particles at rest (L = 0, F = bᵉ = 1, σ = 0, no plastic strain) of seeding volume V⁰ and
/// mass m, compressed to V = (1 − compression) V⁰ (ρ = m/V above ρ₀ = m/V⁰ for compression > 0).
template <int dim>
Particles<dim> restingParticles(int n, double volume0, double mass, double compression) {
    Particles<dim> p;
    p.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        p.L[i].setZero();
        p.F[i].setIdentity();
        p.be[i].setIdentity();
        p.stress[i].setZero();
        p.volume0[i] = volume0;
        p.volume[i] = (1.0 - compression) * volume0;
        p.mass[i] = mass;
        p.plasticStrain[i] = 0.0;
    }
    return p;
}

/// The indices 0 … n − 1.
inline std::vector<Index> allIndices(std::size_t n) {
    std::vector<Index> ids(n);
    for (std::size_t i = 0; i < n; ++i)
        ids[i] = static_cast<Index>(i);
    return ids;
}

} // namespace mpm::test
