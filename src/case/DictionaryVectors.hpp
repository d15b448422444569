// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <string>
#include <vector>

namespace mpm {

/// The dim numbers of `key` as a vector (an InputError naming the key unless there are dim).
template <int dim> Vec<dim> readVec(const Dictionary& dict, const std::string& key) {
    const std::vector<double> v = dict.getVector(key, dim);
    return Eigen::Map<const Vec<dim>>(v.data());
}

/// readVec, or `fallback` when `dict` has no `key`.
template <int dim>
Vec<dim> readVecOr(const Dictionary& dict, const std::string& key, const Vec<dim>& fallback) {
    return dict.has(key) ? readVec<dim>(dict, key) : fallback;
}

} // namespace mpm
