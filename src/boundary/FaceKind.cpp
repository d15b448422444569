// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/FaceKind.hpp"
#include "boundary/BoundaryCondition.hpp"

#include <algorithm>

namespace mpm {

FaceKind faceKind(const std::string& type) {
    if (type == "open") return FaceKind::open;
    if (type == "periodic") return FaceKind::periodic;
    return FaceKind::constrained;
}

std::vector<std::string> faceKindWords() {
    return {"open", "periodic"};
}

template <int dim> std::vector<std::string> boundaryTypeNames() {
    std::vector<std::string> names = faceKindWords();
    for (const auto& entry : BoundaryConditionRegistry<dim>::table())
        names.push_back(entry.first);
    std::sort(names.begin(), names.end());
    return names;
}

template std::vector<std::string> boundaryTypeNames<2>();
template std::vector<std::string> boundaryTypeNames<3>();

namespace {

/// MPM_FAMILY's work for the condition registry of dimension `dim`, with the face kinds listed
/// among its types (`mpmFoam -list boundaryConditions`, ModelCatalogue::check).
template <int dim> struct JoinFamily {
    JoinFamily() {
        using R = BoundaryConditionRegistry<dim>;
        R::family() = "boundaryConditions";
        static const ModelCatalogue::AddTypes types(
            "boundaryConditions", dim,
            {[] { return boundaryTypeNames<dim>(); },
             [] {
                 std::vector<std::string> out;
                 for (const auto& entry : R::refused())
                     out.push_back(entry.first);
                 return out;
             },
             [] { // a condition registered twice, or under a face kind's word
                 std::vector<std::string> out = R::duplicates();
                 for (const std::string& word : faceKindWords())
                     if (R::table().count(word)) out.push_back(word);
                 return out;
             }});
    }
};

const JoinFamily<2> joinFamily2;
const JoinFamily<3> joinFamily3;

} // namespace

MPM_FAMILY_INFO("boundaryConditions",
                {"boundary.<face>.type or boundary.<face>.<patch>.type in constant/grid (or the "
                 "type alone: boundary.<face>: noSlip)",
                 "4. constant/grid",
                 {{"type", "word", "-", "required", "the condition"},
                  {"box", "map {min, max}", "m", "whole face",
                   "named patches only: the face's nodes whose tangential coordinates lie in it"},
                  {"from", "scalar", "s", "-inf", "start of the patch's time window"},
                  {"until", "scalar", "s", "+inf", "end of the window (> from)"}}});
MPM_SCHEMA("boundaryConditions", "open",
           {"no condition; points more than a cell beyond it are removed", {}, "{type: open}"});
MPM_SCHEMA("boundaryConditions", "periodic",
           {"the face and its opposite face are one periodic pair (whole faces only)",
            {},
            "{type: periodic}"});

} // namespace mpm
