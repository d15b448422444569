// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/ElastoPlastic.hpp"

namespace mpm {

/// `henckyElastic`: Hencky hyperelasticity in bᵉ [000 Eq. 4–5] (HenckyLaw), no plastic flow.
/// Keys: density, E, nu.
template <int dim> using HenckyElastic = ElastoPlastic<dim, HenckyLaw, NoPlasticity>;

extern template class ElastoPlastic<2, HenckyLaw, NoPlasticity>;
extern template class ElastoPlastic<3, HenckyLaw, NoPlasticity>;

} // namespace mpm
