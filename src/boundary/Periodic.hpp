// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

namespace mpm {

/// `type: periodic`: one face of a periodic pair (xMin with xMax, …). It constrains nothing:
/// the lattice is made seamless by PeriodicLattice (fold of the image nodes onto their
/// owners, particles wrapped across the seam).
template <int dim> class Periodic final : public BoundaryCondition<dim> {
public:
    explicit Periodic(const Dictionary&) {}
    void apply(const std::vector<Index>&, const FaceNormal&, const NodeArray<double>&,
               NodeArray<Vec<dim>>&, double) const override {}
    bool periodic() const override { return true; }
};

} // namespace mpm
