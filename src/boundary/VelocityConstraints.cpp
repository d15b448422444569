// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/VelocityConstraints.hpp"

#include <algorithm>

namespace mpm {

template <int dim>
VelocityConstraints<dim>::VelocityConstraints(const Dictionary& dict,
                                              const std::vector<std::string>& materialNames) {
    const std::string vec = dim == 3 ? "wx, wy, wz" : "wx, wy";
    for (const std::string& name : dict.keys()) {
        if (!dict.isDict(name))
            dict.error(name, "expected a map {material: …, value: [" + vec + "], components: …}");
        const Dictionary c = dict.subDict(name);
        Entry e;
        const std::string mat = c.getString("material");
        for (std::size_t m = 0; m < materialNames.size(); ++m)
            if (materialNames[m] == mat) e.material = static_cast<int>(m);
        if (e.material < 0) {
            std::string valid;
            for (const auto& n : materialNames)
                valid += (valid.empty() ? "" : " ") + n;
            c.error("material",
                    "unknown material '" + mat + "'; constant/materials defines: " + valid);
        }
        const bool hasValue = c.has("value"), hasTable = c.has("table");
        if (hasValue == hasTable)
            c.error(hasValue ? "table" : "value",
                    "give exactly one of `value: [" + vec + "]` or `table: [[t, " + vec + "], …]`");
        if (hasValue) {
            const std::vector<double> w = c.getVector("value", dim);
            e.times.push_back(0.0);
            e.rows.emplace_back(Eigen::Map<const Vec<dim>>(w.data()));
        } else {
            const std::vector<std::vector<double>> table = c.vectorList("table", dim + 1);
            if (table.empty()) c.error("table", "the table has no rows");
            for (const auto& row : table) {
                if (!e.times.empty() && !(row[0] > e.times.back()))
                    c.error("table", "the times of the table (first column) must increase "
                                     "strictly");
                e.times.push_back(row[0]);
                e.rows.emplace_back(Eigen::Map<const Vec<dim>>(row.data() + 1));
            }
        }
        if (c.has("components")) {
            const std::vector<std::string> axes = c.getStringList("components");
            if (axes.empty())
                c.error("components",
                        "expected at least one of x y" + std::string(dim == 3 ? " z" : ""));
            for (const std::string& a : axes) {
                const int d = a == "x" ? 0 : a == "y" ? 1 : a == "z" && dim == 3 ? 2 : -1;
                if (d < 0)
                    c.error("components", "unknown component '" + a + "'; expected x y" +
                                              std::string(dim == 3 ? " z" : ""));
                if (e.axis[d]) c.error("components", "component '" + a + "' given twice");
                e.axis[d] = true;
            }
        } else {
            e.axis.fill(true);
        }
        c.checkUnknownKeys();
        entries_.push_back(std::move(e));
    }
    if (entries_.empty()) dict.error("", "no constraint given (the file is an empty map)");
}

template <int dim> Vec<dim> VelocityConstraints<dim>::velocity(std::size_t k, double t) const {
    const Entry& e = entries_[k];
    if (t <= e.times.front()) return e.rows.front();
    if (t >= e.times.back()) return e.rows.back();
    const std::size_t j = static_cast<std::size_t>(
        std::upper_bound(e.times.begin(), e.times.end(), t) - e.times.begin());
    const double s = (t - e.times[j - 1]) / (e.times[j] - e.times[j - 1]);
    return (1.0 - s) * e.rows[j - 1] + s * e.rows[j];
}

template class VelocityConstraints<2>;
template class VelocityConstraints<3>;

} // namespace mpm
