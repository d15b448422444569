// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "particles/Particles.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace mpm {

/// Grid node fields folded by PeriodicLattice::fold (bit set).
enum FoldField : unsigned {
    FoldMass = 1u,
    FoldMomentum = 2u,
    FoldForce = 4u,
    FoldMassMomentum = FoldMass | FoldMomentum,
    FoldAll = FoldMass | FoldMomentum | FoldForce
};

/// The periodic identification of the grid lattice along the periodic axes.
///
/// With P cells along a periodic axis, the box nodes are Pad … Pad + P; node i and node i ± P
/// are the same physical node. The owner of a class is the node with Pad ≤ i < Pad + P; the
/// others (the ghost layers 0 … Pad − 1, the duplicate node Pad + P on the far face and the
/// ghost layers beyond it) are its images. After P2G every image's contribution is added onto
/// its owner and the owner's total is copied back to every image, so each later node-wise
/// operation and G2P sees identical values on both sides of the seam: the lattice is seamless
/// for every kernel (stencils reach at most Pad layers beyond the box).
template <int dim> class PeriodicLattice {
public:
    PeriodicLattice(const Grid<dim>& grid, const std::array<bool, dim>& periodic);

    bool periodic(int axis) const { return periodic_[axis]; }
    bool any() const { return any_; }
    /// Period L along each axis (hi − lo; 0 on non-periodic axes) [m].
    const Vec<dim>& period() const { return period_; }

    /// Integer coordinate of the owner of node coordinate i along `axis` (i itself on a
    /// non-periodic axis): Pad + ((i − Pad) mod P).
    int ownerCoord(int axis, int i) const;
    /// True if node k is its own owner along every periodic axis.
    bool isOwner(Index k) const;
    /// Owner of node k.
    Index owner(Index k) const;

    /// Fold the image nodes of the active blocks onto their owners and copy the owners back
    /// (mass, momentum and/or force, `fields` a FoldField set). Serial, in a fixed order
    /// (active blocks ascending, images ascending): deterministic for any thread count.
    /// `activeBlocks` must be closed (closeActiveBlocks).
    void fold(Grid<dim>& g, const std::vector<Index>& activeBlocks, unsigned fields) const;
    /// The same for any node field q (one entry per node), e.g. F̄'s nodal scalar.
    template <class T>
    void foldField(NodeArray<T>& q, const std::vector<Index>& activeBlocks) const {
        if (!any_) return;
        for (Index b : activeBlocks)
            for (Index k = imageStart_[b]; k < imageStart_[b + 1]; ++k)
                q[owners_[k]] += q[images_[k]];
        for (Index b : activeBlocks)
            for (Index k = imageStart_[b]; k < imageStart_[b + 1]; ++k)
                q[images_[k]] = q[owners_[k]];
    }

    /// Visit the images of block b: fn(image node, its owner node), images ascending.
    template <class Fn> void forImagesOf(Index b, Fn&& fn) const {
        if (!any_) return;
        for (Index k = imageStart_[b]; k < imageStart_[b + 1]; ++k)
            fn(images_[k], owners_[k]);
    }

    /// Add to the (sorted) list of active node blocks every block holding a node of the same
    /// class as a node of a listed block (its owner or an image), and keep it sorted: then
    /// fold writes only active blocks, and every owner and all its images are zeroed, updated
    /// and constrained together.
    void closeActiveBlocks(std::vector<Index>& blocks);

    /// x ← x ∓ L along the periodic axes for points outside [lo, hi).
    void wrap(Particles<dim>& p) const;
    /// A position brought into [lo, hi) along the periodic axes (a body's centre).
    Vec<dim> wrapPosition(Vec<dim> x) const;
    /// Shortest periodic separation a − b (minimum image: each periodic component in
    /// [−L/2, L/2]) [m].
    Vec<dim> separation(const Vec<dim>& a, const Vec<dim>& b) const;
    /// Whole periods n (0 on non-periodic axes) such that x − n∘L is the image of x nearest c:
    /// n = round((x − c)/L) per periodic axis.
    IVec<dim> imageIndex(const Vec<dim>& x, const Vec<dim>& c) const;
    /// The image of x nearest c, x − n∘L with n = imageIndex(x, c), so that each periodic
    /// component of the result minus c lies in [−L/2, L/2]; x itself, bit for bit, along
    /// non-periodic axes and when no shift is needed [m]. A body at c interacts with the image
    /// of a point nearest it: φ(imageNear(x, c)), lever arm imageNear(x, c) − c.
    Vec<dim> imageNear(Vec<dim> x, const Vec<dim>& c) const {
        for (int d = 0; d < dim; ++d)
            if (periodic_[d]) x[d] -= period_[d] * std::round((x[d] - c[d]) / period_[d]);
        return x;
    }

private:
    const Grid<dim>& grid_;
    IVec<dim> n_;
    std::array<int, dim> cells_{}; ///< P along each axis
    std::array<bool, dim> periodic_{};
    bool any_ = false;
    Vec<dim> lo_, hi_, period_;
    IVec<dim> nb_;
    /// Images of each block: images_[imageStart_[b] .. imageStart_[b+1]) with owners_ alike.
    std::vector<Index> imageStart_, images_, owners_;
    /// Per axis and block coordinate c: the block coordinates holding a node of the same
    /// class as a node of block c (c included).
    std::array<std::vector<std::vector<int>>, dim> related_;
    std::vector<char> mark_;    ///< closeActiveBlocks scratch
    std::vector<Index> closed_; ///< closeActiveBlocks scratch
};

} // namespace mpm
