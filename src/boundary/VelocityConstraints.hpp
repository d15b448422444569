// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <array>
#include <string>
#include <vector>

namespace mpm {

/// Prescribed velocity components of a material's points (`constant/velocityConstraints`),
/// e.g. a block driven sideways at constant v_x with its vertical motion free [001 §5.2.2].
/// Each entry names a material and gives w(t), a constant `value: [wx, wy(, wz)]` or a
/// `table: [[t, wx, wy(, wz)], …]` (linear in t, held beyond the ends) [m/s], and the
/// `components` it prescribes (default all). Every grid node that a point of the material
/// reaches (Σ_p w_ip > 0 over its points) gets v_i,a ← w_a(t) for those components, after the
/// grid update and the boundary conditions (and on the P2G velocity under USF and MUSL), so the
/// points move with w_a (partition of unity), ∂v_a/∂x = 0 among them and the forces along a
/// (stress, contact, gravity) do not accelerate them: the constraint takes them up. Nodes
/// shared with other materials are constrained too. Not applied during a gravity preload.
template <int dim> class VelocityConstraints {
public:
    VelocityConstraints() = default;
    /// Reads the file; materialNames in constant/materials order.
    VelocityConstraints(const Dictionary& dict, const std::vector<std::string>& materialNames);

    bool empty() const { return entries_.empty(); }
    std::size_t size() const { return entries_.size(); }
    int material(std::size_t k) const { return entries_[k].material; }

    /// w(t) of entry k [m/s].
    Vec<dim> velocity(std::size_t k, double t) const;
    /// v_a ← w_a for the components entry k prescribes.
    void set(std::size_t k, const Vec<dim>& w, Vec<dim>& v) const {
        for (int a = 0; a < dim; ++a)
            if (entries_[k].axis[a]) v[a] = w[a];
    }

private:
    struct Entry {
        int material = -1;
        std::vector<double> times;
        std::vector<Vec<dim>> rows;
        std::array<bool, dim> axis{};
    };
    std::vector<Entry> entries_;
};

} // namespace mpm
