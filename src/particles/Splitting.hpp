// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "parallel/Comm.hpp"
#include "particles/Particles.hpp"

#include <cstddef>
#include <memory>
#include <vector>

namespace mpm {

/// Particle splitting: a point whose domain is stretched beyond `maxStretch` along some
/// direction is replaced by its two halves along that direction, so that the points keep
/// sampling the material they stand for.
///
/// Why: a point is a quadrature point of the material it was seeded for, and a large isochoric
/// stretch (the flowing layer of a collapsing column reaches 3–4) pulls neighbouring points apart
/// along one direction and together along the other. The points then line up in strings one
/// to two cells apart; the grid no longer sees material between them, the strings close in
/// without any point recording the compression, and the deposit ends denser in space than its
/// points' volumes say (a = 7 column, 2 points per cell and direction: the space under the
/// deposit is 0.79 Σ V_p; docs/settingsGuide.md). Seeding more points delays it everywhere;
/// splitting refines only where the stretch needs it.
///
/// The domain of point p is D_p = F_p S_p: F its deformation gradient and S_p (reference
/// configuration; 1 at seeding) the product of the halvings of its past splits. With σ² the
/// largest eigenvalue of D_pᵀ D_p and m its unit eigenvector (a reference direction), the point
/// is split when σ > maxStretch into two children at x_p ± (σ a_p / 4) u, u = D_p m / σ, where
/// a_p = (2^k V⁰_p)^(1/dim) is the side of the seeding cell it came from and k its splits so far.
/// Each child has half the mass, V and V⁰, S ← S (1 − ½ m mᵀ), k ← k + 1, and every other field
/// of the parent (v, F, bᵉ, σ, plastic strain, model state): mass, momentum, volume, stress and
/// the centre of mass are kept. The parent keeps its id; the child takes a new one, unique over
/// all ranks (the largest id + 1 on, in rank and index order).
///
/// Fields (declared by the constructor; restart state): `splitDomain` S − 1 (a tensor, zero for
/// a point as seeded) and `splitLevel` k (a flag).
template <int dim> class ParticleSplitting {
public:
    /// Deepest lineage: a point split this often is not split again (V⁰ 2⁻⁴⁰ of its seed's).
    static constexpr int MaxLevel = 40;

    /// Stretch at which a granular material's points split when the schemes do not say.
    static constexpr double GranularMaxStretch = 4.0;

    /// `maxStretch` > 1: the principal stretch of the domain beyond which a point is split.
    ParticleSplitting(double maxStretch, Particles<dim>& p);

    /// The splitting `system/mpmSchemes` selects: `splitting: {maxStretch: s}`, or
    /// `splitting: off`; absent, on with maxStretch 4 when the scene has a granular material
    /// (`granular`: one with the trans-phase relation, whose flows stretch and whose deposits
    /// must fill their volume) and off otherwise. Returns null when off.
    static std::unique_ptr<ParticleSplitting> create(const Dictionary& schemes, bool granular,
                                                     Particles<dim>& p);

    /// Split every point whose domain is stretched beyond maxStretch (children appended in
    /// index order, so the result does not depend on the thread count), except
    /// - the points marked in `nearBody` (null: none): within a few cells of a coupled body a
    ///   child, put σ a/4 from its parent, could land inside the body's barrier, and there the
    ///   coupling, not the sampling, governs;
    /// - a point whose children would land more than a cell (`cellSize` h) away, σ a/4 > h: a
    ///   needle stretched far beyond maxStretch without a split (next to a body, or in one
    ///   step), whose halves would carry its mass further than a shape function reaches.
    /// Collective: every rank calls it. Returns the number of points split on all ranks (the
    /// same on every rank).
    Index apply(Particles<dim>& p, const Comm& comm, double cellSize,
                const int* nearBody = nullptr);

    /// k of every point (0 for all before any split).
    const std::vector<int>& levels(const Particles<dim>& p) const { return p.flag(level_); }

    double maxStretch() const { return maxStretch_; }
    /// True when the schemes did not name `splitting` (the granular default).
    bool byDefault() const { return byDefault_; }

private:
    double maxStretch_;
    bool byDefault_ = false;
    std::size_t domain_; ///< Particles::tensor handle of S − 1
    std::size_t level_;  ///< Particles::flag handle of k
    std::vector<char> split_;
};

} // namespace mpm
