// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "forces/BodyAcceleration.hpp"

namespace mpm {

/// `type: constant` (or no `type:`): g(t) = `value` [m/s²], e.g. `value: [0, -9.81]`.
template <int dim> class ConstantAcceleration final : public BodyAcceleration<dim> {
public:
    explicit ConstantAcceleration(const Dictionary& dict);
    explicit ConstantAcceleration(const Vec<dim>& g) : g_(g) {}

    Vec<dim> at(double) const override { return g_; }
    bool isConstant() const override { return true; }
    double maxMagnitude() const override { return g_.norm(); }
    double totalVariation() const override { return 0.0; }

private:
    Vec<dim> g_;
};

} // namespace mpm
