// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Parallel.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mpm {

/// Material points as a structure of arrays, one array per field (DESIGN §7).
///
/// Stress and the elastic left Cauchy–Green tensor are 3×3 in 2D too: 2D scenes are plane
/// strain, so σ_zz is carried and the return maps work in 3D principal space.
template <int dim> struct Particles {
    std::vector<Vec<dim>> x;           ///< position [m]
    std::vector<Vec<dim>> v;           ///< velocity [m/s]
    std::vector<Mat<dim>> C;           ///< APIC affine velocity B_p D_p⁻¹ [1/s] [000 Eq. 13, 17]
    std::vector<Mat<dim>> L;           ///< velocity gradient of the last step [1/s] [002 Eq. 75]
    std::vector<Mat<dim>> F;           ///< deformation gradient since seeding [-]
    std::vector<Mat3> be;              ///< elastic left Cauchy–Green tensor bᵉ [-] [000 Eq. 4]
    std::vector<Mat3> stress;          ///< Cauchy stress σ [Pa], tension positive
    std::vector<double> mass;          ///< m_p [kg] (per metre of depth in 2D)
    std::vector<double> volume0;       ///< V_p at seeding [m³]
    std::vector<double> volume;        ///< V_p = J V_p⁰ [m³]
    std::vector<double> plasticStrain; ///< accumulated plastic shear strain [-]
    std::vector<double> slip;          ///< accumulated contact slip u_T [004 Eq. 37] [m]
    std::vector<Index> id;             ///< stable identity, kept across sorting and restart
    std::vector<int> material;         ///< index into the material list

    std::size_t size() const { return x.size(); }

    void resize(std::size_t n) {
        forEachArray([n](auto& a) { a.resize(n); });
    }

    /// Apply `f` to every per-particle array (sorting, compaction, resizing).
    template <class Fn> void forEachArray(Fn&& f) {
        f(x), f(v), f(C), f(L), f(F), f(be), f(stress);
        f(mass), f(volume0), f(volume), f(plasticStrain), f(slip), f(id), f(material);
    }

    /// Apply `f(a, b)` to every pair of corresponding arrays of this and `other`.
    template <class Fn> void forEachArrayPair(Particles& o, Fn&& f) {
        f(x, o.x), f(v, o.v), f(C, o.C), f(L, o.L), f(F, o.F), f(be, o.be), f(stress, o.stress);
        f(mass, o.mass), f(volume0, o.volume0), f(volume, o.volume);
        f(plasticStrain, o.plasticStrain), f(slip, o.slip), f(id, o.id), f(material, o.material);
    }

    /// permute() through `scratch`, whose arrays keep their memory between calls (the periodic
    /// reorder then touches no fresh pages).
    void permute(const std::vector<Index>& order, Particles& scratch) {
        const Index n = static_cast<Index>(order.size());
        forEachArrayPair(scratch, [&order, n](auto& a, auto& b) {
            b.resize(order.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
            for (Index k = 0; k < n; ++k)
                b[k] = a[order[k]];
            a.swap(b);
        });
    }

    /// Reorder all arrays so that new particle k is old particle order[k] (order may be shorter
    /// than size(): the particles left out are removed).
    void permute(const std::vector<Index>& order) {
        forEachArray([&order](auto& a) {
            std::remove_reference_t<decltype(a)> b(order.size());
#pragma omp parallel for if (worthThreads(static_cast <Index>(order.size()))) schedule(static)
            for (Index k = 0; k < static_cast<Index>(order.size()); ++k)
                b[k] = a[order[k]];
            a.swap(b);
        });
    }
};

} // namespace mpm
