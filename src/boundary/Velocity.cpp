// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Velocity.hpp"

#include <algorithm>

namespace mpm {

template <int dim> Velocity<dim>::Velocity(const Dictionary& dict) {
    const bool hasValue = dict.has("value"), hasTable = dict.has("table");
    if (hasValue == hasTable)
        dict.error(hasValue ? "table" : "value",
                   "a velocity wall needs exactly one of `value: [wx, wy" +
                       std::string(dim == 3 ? ", wz" : "") + "]` or `table: [[t, wx, wy" +
                       std::string(dim == 3 ? ", wz" : "") + "], …]`");
    if (hasValue) {
        const std::vector<double> w = dict.getVector("value", dim);
        times_.push_back(0.0);
        rows_.emplace_back(Eigen::Map<const Vec<dim>>(w.data()));
    } else {
        const std::vector<std::vector<double>> table = dict.vectorList("table", dim + 1);
        if (table.empty()) dict.error("table", "the table has no rows");
        for (const auto& row : table) {
            if (!times_.empty() && !(row[0] > times_.back()))
                dict.error("table", "the times of the table (first column) must increase strictly");
            times_.push_back(row[0]);
            rows_.emplace_back(Eigen::Map<const Vec<dim>>(row.data() + 1));
        }
    }
    slip_ = dict.getBoolOr("slip", false);
}

template <int dim> Vec<dim> Velocity<dim>::wallVelocity(double t) const {
    if (t <= times_.front()) return rows_.front();
    if (t >= times_.back()) return rows_.back();
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) -
                                 times_.begin()); // times_[k-1] ≤ t < times_[k]
    const double s = (t - times_[k - 1]) / (times_[k] - times_[k - 1]);
    return (1.0 - s) * rows_[k - 1] + s * rows_[k];
}

template class Velocity<2>;
template class Velocity<3>;

MPM_REGISTER_DIMS(BoundaryConditionRegistry, Velocity, "velocity");
MPM_SCHEMA("boundaryConditions", "velocity",
           {"wall moving with velocity w(t): a shear lid, a conveyor, an inflow",
            {{"value", "vector", "m/s", "none", "constant w (give value or table)"},
             {"table", "list of [t, vx, vy(, vz)]", "s, m/s", "none",
              "w(t), linear in t, held beyond the ends (give value or table)"},
             {"slip", "bool", "-", "no", "yes: smooth moving wall; no: rough, v = w"}},
            "{type: velocity, value: [0.1, 0]}"});

} // namespace mpm
