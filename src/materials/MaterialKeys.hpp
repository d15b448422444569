// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/KeySchema.hpp"

namespace mpm {

/// Key schemas shared by the material types (core/KeySchema.hpp; docs/caseFormat.md §6): the
/// elastic constants (ElasticConstants) and the keys of the granular types `druckerPrager` and
/// `muI` (ElastoPlastic, readConeFit).
inline KeyList elasticKeys() {
    return {{"E", "scalar", "Pa", "required", "Young's modulus (> 0)"},
            {"nu", "scalar", "-", "required", "Poisson's ratio ν, in (-1, 0.5)"}};
}

inline KeyList granularKeys() {
    return {{"elasticity", "word", "-", "hencky", "the elastic law: hencky or hypoelastic"},
            {"frictionAngle", "scalar", "deg", "required", "friction angle φ, in (0, 90)"},
            {"coneFit", "word", "-", "planeStrain",
             "how angles give the cone's coefficients: planeStrain or compression"},
            {"transPhase", "bool", "-", "true", "trans-phase gasification [000 Eq. 10] on/off"},
            {"criticalDensity", "scalar", "kg/m³", "density",
             "ρ_c (≥ 0): a point whose neighbourhood density is below it is gasified"},
            {"gasVolume", "word", "-", "neighbourhood",
             "a gasified point's volume: neighbourhood (m_p/ρ̄_p, not next to bodies: resting "
             "deposits carry their weight) or point (its own); point without trans-phase"}};
}

} // namespace mpm
