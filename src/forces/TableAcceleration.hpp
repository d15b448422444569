// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "forces/BodyAcceleration.hpp"

#include <vector>

namespace mpm {

/// `type: table`: `table` rows [t, gx, gy(, gz)] [s, m/s²] with strictly increasing t;
/// g is interpolated linearly in t between rows and held at the first (last) row before
/// (after) the table.
template <int dim> class TableAcceleration final : public BodyAcceleration<dim> {
public:
    explicit TableAcceleration(const Dictionary& dict);

    Vec<dim> at(double t) const override;
    /// True if every row holds the same g.
    bool isConstant() const override;
    /// max over rows of |g| (|g| is convex along each linear piece).
    double maxMagnitude() const override;
    /// Σ |g_{i+1} − g_i| (exact for a piecewise-linear g).
    double totalVariation() const override;

private:
    std::vector<double> times_;
    std::vector<Vec<dim>> values_;
};

} // namespace mpm
