// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Parallel.hpp"
#include "core/Types.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace mpm {

/// What a particle field is to the rest of the code: its name in the `.vtu` (ParaView), whether a
/// restart needs it and whether it is written. Values of type double are Float64 with one
/// component, int and Index Int64 with one, Vec<dim> three (zero-padded in 2D), Mat<dim> and Mat3
/// nine (2D: zero-padded, or the identity's 1 in zz when `identityPad`).
struct FieldInfo {
    std::string name;
    bool restart = true;      ///< read back on restart (so always written)
    bool written = true;      ///< written to the time directories' particles.vtu
    bool identityPad = false; ///< a 2D Mat<dim> written with zz = 1 (a deformation gradient)
    bool points = false;      ///< the positions: the VTU's points, not a data array
};

/// Per-particle state a model declares at set-up (a material's σᵉ, plastic strain rate, flag):
/// one array in the field table, sorted, written and restarted with the others.
template <class T> struct StateField {
    FieldInfo info;
    std::vector<T> data;
};

/// Material points as a structure of arrays, one array per field (docs/architecture.md).
///
/// The field table (visitTable) declares every field once — name, type, whether a restart needs
/// it, whether it is written — and sorting, compaction, VTU writing, restart reading and the
/// failure snapshot all iterate it; a model adds state with addScalar/addTensor/addFlag and it is
/// handled like the built-in fields without any other file changing.
///
/// Stress and the elastic left Cauchy–Green tensor are 3×3 in 2D too: 2D scenes are plane
/// strain, so σ_zz is carried and the return maps work in 3D principal space.
/// Reorder buffers of Particles::permute, one array per field type.
template <int dim> struct PermuteBuffers {
    std::vector<Vec<dim>> vectors;
    std::vector<Mat<dim>> matrices;
    std::vector<Mat3> tensors; ///< unused in 3D (Mat<3> is Mat3)
    std::vector<double> scalars;
    std::vector<Index> indices;
    std::vector<int> ints;
    template <class T> std::vector<T>& of() {
        if constexpr (std::is_same_v<T, Vec<dim>>)
            return vectors;
        else if constexpr (std::is_same_v<T, Mat<dim>>)
            return matrices;
        else if constexpr (std::is_same_v<T, Mat3>)
            return tensors;
        else if constexpr (std::is_same_v<T, double>)
            return scalars;
        else if constexpr (std::is_same_v<T, Index>)
            return indices;
        else
            return ints;
    }
};

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
    std::vector<double> volume;        ///< V_p = J V_p⁰, or from the rate [002 Eq. 76] [m³]
    std::vector<double> plasticStrain; ///< accumulated plastic shear strain [-]
    std::vector<Index> id;             ///< stable identity, kept across sorting and restart
    std::vector<int> material;         ///< index into the material list

    /// Model state declared at set-up, in order of declaration.
    std::vector<StateField<double>> scalars;
    std::vector<StateField<Mat3>> tensors;
    std::vector<StateField<int>> flags;

    std::size_t size() const { return x.size(); }

    /// The field table: `stored(info, array…)` for every stored array (the same array of each of
    /// `ps`, which share their declared state) and `derived(name, fn)` for every written value
    /// computed from them (fn(p, i) → double), in the order of the `.vtu`.
    template <class Stored, class Derived, class P, class... Ps>
    static void visitTable(Stored&& stored, Derived&& derived, P& p, Ps&... ps) {
        stored(FieldInfo{"id"}, p.id, ps.id...);
        stored(FieldInfo{"material"}, p.material, ps.material...);
        stored(FieldInfo{"velocity"}, p.v, ps.v...);
        stored(FieldInfo{"stress"}, p.stress, ps.stress...);
        derived(
            "pressure", +[](const Particles& q, Index i) { return -q.stress[i].trace() / 3.0; });
        derived(
            "density", +[](const Particles& q, Index i) { return q.mass[i] / q.volume[i]; });
        stored(FieldInfo{"volume"}, p.volume, ps.volume...);
        stored(FieldInfo{"mass"}, p.mass, ps.mass...);
        stored(FieldInfo{"plasticStrain"}, p.plasticStrain, ps.plasticStrain...);
        stored(FieldInfo{"initialVolume"}, p.volume0, ps.volume0...);
        stored(FieldInfo{"deformationGradient", true, true, true}, p.F, ps.F...);
        stored(FieldInfo{"elasticLeftCauchyGreen"}, p.be, ps.be...);
        stored(FieldInfo{"affineVelocity"}, p.C, ps.C...);
        stored(FieldInfo{"velocityGradient", false, false}, p.L, ps.L...); // recomputed each step
        stored(FieldInfo{"position", true, true, false, true}, p.x, ps.x...);
        for (std::size_t k = 0; k < p.scalars.size(); ++k)
            stored(p.scalars[k].info, p.scalars[k].data, ps.scalars[k].data...);
        for (std::size_t k = 0; k < p.tensors.size(); ++k)
            stored(p.tensors[k].info, p.tensors[k].data, ps.tensors[k].data...);
        for (std::size_t k = 0; k < p.flags.size(); ++k)
            stored(p.flags[k].info, p.flags[k].data, ps.flags[k].data...);
    }

    /// Apply `f(info, array)` to every stored array.
    template <class Fn> void forEachField(Fn&& f) {
        visitTable(
            f, [](const char*, auto) {}, *this);
    }
    template <class Fn> void forEachField(Fn&& f) const {
        visitTable(
            f, [](const char*, auto) {}, *this);
    }
    /// Apply `f(array)` to every stored array (sorting, compaction, resizing).
    template <class Fn> void forEachArray(Fn&& f) {
        forEachField([&f](const FieldInfo&, auto& a) { f(a); });
    }

    void resize(std::size_t n) {
        forEachArray([n](auto& a) { a.resize(n); });
    }

    /// Kinematics of a step: F ← (1 + Δt L) F, and V = det(F) V⁰, or, for the particles of a
    /// material flagged in `volumeFromRate` (indexed by material), V ← V exp(Δt tr L)
    /// [002 Eq. 76]. Returns the first particle whose volume is not positive and finite (det F ≤ 0:
    /// an inverted element), or size() if none.
    Index updateDeformation(double dt, const std::vector<char>& volumeFromRate) {
        // Chosen once: without rate-form materials no point's material is looked up.
        if (std::none_of(volumeFromRate.begin(), volumeFromRate.end(), [](char c) { return c; }))
            return advanceDeformation(dt, [](Index) { return false; });
        return advanceDeformation(dt, [&](Index i) { return volumeFromRate[material[i]] != 0; });
    }

private:
    template <class FromRate> Index advanceDeformation(double dt, FromRate&& fromRate) {
        const Index n = static_cast<Index>(size());
        Index inverted = n;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : inverted)
        for (Index i = 0; i < n; ++i) {
            // The new F and V from registers: det F is not re-read from the stores just made.
            const Mat<dim> Fn = (Mat<dim>::Identity() + dt * L[i]) * F[i];
            F[i] = Fn;
            const double Vn = fromRate(i) ? volume[i] * std::exp(dt * L[i].trace())
                                          : Fn.determinant() * volume0[i];
            volume[i] = Vn;
            if (!(Vn > 0 && Vn < std::numeric_limits<double>::infinity()))
                inverted = std::min(inverted, i);
        }
        return inverted;
    }

public:
    /// Stop every point: v = 0 and C = 0 (the end of a gravity preload).
    void stop() {
        for (std::size_t i = 0; i < size(); ++i) {
            v[i].setZero();
            C[i].setZero();
        }
    }

    /// Declare model state (a no-op returning the existing handle when a field of that name and
    /// type exists: two materials of one model share it). New entries get `init` on every
    /// present particle. Returns the handle for scalar()/tensor()/flag().
    std::size_t addScalar(const FieldInfo& info, double init = 0.0) {
        return addField(scalars, info, init);
    }
    std::size_t addTensor(const FieldInfo& info, const Mat3& init = Mat3::Zero()) {
        return addField(tensors, info, init);
    }
    std::size_t addFlag(const FieldInfo& info, int init = 0) {
        return addField(flags, info, init);
    }
    std::vector<double>& scalar(std::size_t h) {
        return scalars[h].data;
    }
    const std::vector<double>& scalar(std::size_t h) const {
        return scalars[h].data;
    }
    std::vector<Mat3>& tensor(std::size_t h) {
        return tensors[h].data;
    }
    const std::vector<Mat3>& tensor(std::size_t h) const {
        return tensors[h].data;
    }
    std::vector<int>& flag(std::size_t h) {
        return flags[h].data;
    }
    const std::vector<int>& flag(std::size_t h) const {
        return flags[h].data;
    }

    /// An empty set of particles with the same declared model state (names, no values).
    Particles emptyLike() const {
        Particles r;
        auto infos = [](const auto& from, auto& to) {
            to.resize(from.size());
            for (std::size_t k = 0; k < from.size(); ++k)
                to[k].info = from[k].info;
        };
        infos(scalars, r.scalars), infos(tensors, r.tensors), infos(flags, r.flags);
        return r;
    }

    /// Reorder all arrays so that new particle k is old particle order[k] (order may be shorter
    /// than size(): the particles left out are removed). One buffer per field type is filled
    /// and swapped with each field in turn, so a reorder costs one array of each type, not a
    /// second copy of every field; `buffers` keeps its memory between calls (the periodic
    /// reorder then touches no fresh pages).
    void permute(const std::vector<Index>& order, PermuteBuffers<dim>& buffers) {
        const Index n = static_cast<Index>(order.size());
        forEachArray([&](auto& a) {
            auto& b = buffers.template of<typename std::decay_t<decltype(a)>::value_type>();
            b.resize(order.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
            for (Index j = 0; j < n; ++j)
                b[j] = a[order[j]];
            a.swap(b);
        });
    }
    void permute(const std::vector<Index>& order) {
        PermuteBuffers<dim> buffers;
        permute(order, buffers);
    }

private:
    template <class T>
    std::size_t addField(std::vector<StateField<T>>& fields, const FieldInfo& info, const T& init) {
        for (std::size_t k = 0; k < fields.size(); ++k)
            if (fields[k].info.name == info.name) return k;
        fields.push_back({info, std::vector<T>(size(), init)});
        return fields.size() - 1;
    }
};

} // namespace mpm
