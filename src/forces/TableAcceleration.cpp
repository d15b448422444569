// SPDX-License-Identifier: GPL-3.0-or-later
#include "forces/TableAcceleration.hpp"

#include "core/Format.hpp"

#include <algorithm>
#include <string>

namespace mpm {

template <int dim> TableAcceleration<dim>::TableAcceleration(const Dictionary& dict) {
    const std::vector<std::vector<double>> rows = dict.vectorList("table", 1 + dim);
    if (rows.empty()) dict.error("table", "the table needs at least one row [t, g...]");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (i > 0 && !(rows[i][0] > rows[i - 1][0]))
            dict.error("table", "rows must be sorted by strictly increasing time; row " +
                                    std::to_string(i) + " (t = " + fullPrecision(rows[i][0]) +
                                    ") is not after row " + std::to_string(i - 1) +
                                    " (t = " + fullPrecision(rows[i - 1][0]) + ")");
        times_.push_back(rows[i][0]);
        values_.push_back(Eigen::Map<const Vec<dim>>(rows[i].data() + 1));
    }
}

template <int dim> Vec<dim> TableAcceleration<dim>::at(double t) const {
    if (t <= times_.front()) return values_.front();
    if (t >= times_.back()) return values_.back();
    // First row after t; t lies in [times_[i − 1], times_[i]).
    const std::size_t i = static_cast<std::size_t>(
        std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
    const double w = (t - times_[i - 1]) / (times_[i] - times_[i - 1]);
    return (1.0 - w) * values_[i - 1] + w * values_[i];
}

template <int dim> bool TableAcceleration<dim>::isConstant() const {
    return std::all_of(values_.begin(), values_.end(),
                       [&](const Vec<dim>& g) { return g == values_.front(); });
}

template <int dim> double TableAcceleration<dim>::maxMagnitude() const {
    double m = 0;
    for (const auto& g : values_)
        m = std::max(m, g.norm());
    return m;
}

template <int dim> double TableAcceleration<dim>::totalVariation() const {
    double v = 0;
    for (std::size_t i = 1; i < values_.size(); ++i)
        v += (values_[i] - values_[i - 1]).norm();
    return v;
}

template class TableAcceleration<2>;
template class TableAcceleration<3>;

MPM_REGISTER_DIMS(BodyAccelerationRegistry, TableAcceleration, "table");
MPM_SCHEMA("bodyAccelerations", "table",
           {"g(t) from a table, linear in t",
            {{"table", "list of [t, gx, gy(, gz)]", "s, m/s²", "required",
              "≥ 1 row, t increasing"}},
            "{type: table, table: [[0, 0, -9.81], [1, 0, -4.9]]}"});

} // namespace mpm
