// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

namespace mpm {

/// `type: open`: no constraint and no reaction; a particle more than one cell beyond an
/// active open patch has left the domain and is removed (BoundaryConditions::removeOutflow).
template <int dim> class Open final : public BoundaryCondition<dim> {
public:
    explicit Open(const Dictionary&) {}
    void apply(const std::vector<Index>&, const FaceNormal&, const NodeArray<double>&,
               NodeArray<Vec<dim>>&, double) const override {}
    bool open() const override { return true; }
};

} // namespace mpm
