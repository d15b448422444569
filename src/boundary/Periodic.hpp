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
    void constrain(const PatchNodes&, const FaceNormal&, const NodeArray<double>&,
                   NodeArray<Vec<dim>>&, double) const override {}
    Vec<dim> constrainUpdate(const PatchNodes&, const FaceNormal&, const NodeState<dim>&,
                             NodeArray<Vec<dim>>&, const Vec<dim>&, double, double,
                             NodeArray<char>&) const override {
        return Vec<dim>::Zero();
    }
    bool periodic() const override { return true; }
};

} // namespace mpm
