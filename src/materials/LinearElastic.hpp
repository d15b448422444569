// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/ElastoPlastic.hpp"

namespace mpm {

/// `linearElastic`: hypoelastic linear elasticity with the Jaumann rate [001 Eq. 25, 36]
/// (HypoelasticLaw), no plastic flow. Keys: density, E, nu.
template <int dim> using LinearElastic = ElastoPlastic<dim, HypoelasticLaw, NoPlasticity>;

extern template class ElastoPlastic<2, HypoelasticLaw, NoPlasticity>;
extern template class ElastoPlastic<3, HypoelasticLaw, NoPlasticity>;

} // namespace mpm
