// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/BoundaryCondition.hpp"

namespace mpm {

template <int dim>
std::unique_ptr<BoundaryCondition<dim>> BoundaryCondition<dim>::create(const Dictionary& dict) {
    return BoundaryConditionRegistry<dim>::createReadingMore(dict); // and the patch keys
}

template <int dim> std::vector<std::string> BoundaryCondition<dim>::typeNames() {
    std::vector<std::string> names;
    for (const auto& entry : BoundaryConditionRegistry<dim>::table())
        names.push_back(entry.first);
    return names;
}

template class BoundaryCondition<2>;
template class BoundaryCondition<3>;

MPM_FAMILY_INFO("boundaryConditions",
                {"boundary.<face>.type or boundary.<face>.<patch>.type in constant/grid (or the "
                 "type alone: boundary.<face>: noSlip)",
                 "4. constant/grid",
                 {{"type", "word", "-", "required", "the condition"},
                  {"box", "map {min, max}", "m", "whole face",
                   "named patches only: the face's nodes whose tangential coordinates lie in it"},
                  {"from", "scalar", "s", "-inf", "start of the patch's time window"},
                  {"until", "scalar", "s", "+inf", "end of the window (> from)"}}});
MPM_FAMILY(BoundaryConditionRegistry<2>, 2, "boundaryConditions");
MPM_FAMILY(BoundaryConditionRegistry<3>, 3, "boundaryConditions");

} // namespace mpm
