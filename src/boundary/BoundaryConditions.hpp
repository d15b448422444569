// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"
#include "boundary/FaceKind.hpp"
#include "boundary/PeriodicLattice.hpp"
#include "case/Dictionary.hpp"
#include "grid/Grid.hpp"
#include "particles/Particles.hpp"

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// The boundary conditions of the grid box (`constant/grid` boundary), built once from the
/// dictionary and the Grid.
///
/// Each of the 2·dim faces holds either one condition for the whole face (`xMin: slip`,
/// `xMin: {type: friction, friction: 0.3}`) or named patches (`yMin: {wall: {type: noSlip},
/// orifice: {type: open, box: {min, max}, from: 0.5}}`). A patch acts on the face's nodes —
/// those on the face and in the Pad ghost layers beyond it (Grid::faceNodes) — whose
/// tangential coordinates lie in its `box` (the box's normal coordinate is ignored: the
/// ghost layers belong to the face); at most one patch of a face has no box and takes the
/// nodes no box selects; boxed patches must not share a node. Outside its time window
/// [from, until) a patch is inactive and its nodes obey the face's box-less patch, or slip if
/// there is none (or if that one is inactive too). Nodes no patch selects obey slip.
///
/// Periodic faces (`xMin: periodic` with `xMax: periodic`) constrain nothing; the lattice
/// along that axis is made seamless by PeriodicLattice (fold, closed active blocks, particle
/// wrap). Along a periodic tangential axis, a box is tested on the owner node's coordinate,
/// so images follow their owners, and only owner nodes count in the reactions.
template <int dim> class BoundaryConditions {
public:
    static constexpr int NumFaces = 2 * dim;
    using Reactions = std::array<Vec<dim>, NumFaces>;

    /// Reads `gridDict`'s optional `boundary` map (every face slip without it) and checks it.
    BoundaryConditions(const Dictionary& gridDict, const Grid<dim>& grid);

    /// Every valid `type:` of a face or patch, sorted: the registered conditions and the face
    /// kinds open and periodic.
    static std::vector<std::string> typeNames() { return boundaryTypeNames<dim>(); }

    /// Constrain the P2G velocity v (g.vOld) at time t (the start of the step, tⁿ). On a
    /// unilateral patch (slip, friction, smooth velocity) the normal velocity is set to the
    /// wall's where the last constrainUpdate found the node pressed against the wall, and left
    /// free elsewhere: the
    /// velocity gradient then sees the wall the motion saw (this step's under MUSL, the last
    /// step's under USF), never a second decision of its own.
    void constrain(const Grid<dim>& g, NodeArray<Vec<dim>>& v, double t) const;
    /// Constrain the updated velocity g.v at time t (the end of the step, tⁿ⁺¹) and store each
    /// face's reaction, F_f = Σ m_i (v_i⁻ − v_i⁺)/Δt over its owner nodes [N] (per metre in
    /// 2D), in `reactions` (zero on open and periodic faces); faces act in the order xMin,
    /// xMax, yMin, …, and the first face acting on a node measures from the undamped update
    /// v⁰ + Δt (f/m + g), later ones from what is left. `gravity` g [m/s²].
    void constrainUpdate(Grid<dim>& g, const Vec<dim>& gravity, double t, double dt,
                         Reactions& reactions);

    /// Select the patch nodes in the grid's active blocks for this step's constrain and
    /// constrainUpdate (after Grid::activate): the walls' work follows the material, not the
    /// size of the faces. Wall contact of the nodes whose block the material left is cleared
    /// (constrainUpdate would have found no mass there).
    void selectActive(const Grid<dim>& g) {
        selectActive(g, [&g](Index b) { return g.isActive(b); });
    }
    /// The same over the blocks `take(b)` accepts: a parallel run's active blocks this rank owns
    /// (every node is constrained by its owner, its reaction counted once).
    void selectActive(const Grid<dim>& g, const std::function<bool(Index)>& take);

    /// Some face has a unilateral condition (at some time): wall contact is state.
    bool hasUnilateral() const { return hasUnilateral_; }
    /// Wall contact of the last constrainUpdate, as (node, axis bits) pairs in node order
    /// (bit a: pressed against a wall normal to axis a): restart state under USF.
    std::vector<std::pair<Index, int>> wallContact() const;
    /// Restore wallContact() (nodes checked by the caller: 0 ≤ node < numNodes).
    void setWallContact(const std::vector<std::pair<Index, int>>& contact);

    /// Remove the particles more than one cell beyond an open patch active at time t,
    /// keeping the order of the others; returns how many left. Throws RunError if none is
    /// left.
    Index removeOutflow(Particles<dim>& p, double t) const;
    /// True if a point beyond face f (outside the box along its axis) lies under an open
    /// patch active at time t: a box-less open patch, or within one cell (tangentially) of
    /// the nodes of a boxed one. removeOutflow applies it to points more than one cell out.
    bool open(int face, const Vec<dim>& x, double t) const;
    /// Some patch is open (at some time): removeOutflow has work to do.
    bool hasOpen() const { return hasOpen_; }

    bool periodic(int axis) const { return lattice_->periodic(axis); }
    bool anyPeriodic() const { return lattice_->any(); }
    const PeriodicLattice<dim>& lattice() const { return *lattice_; }
    /// PeriodicLattice::fold, foldField, closeActiveBlocks, wrap, wrapPosition, separation
    /// (all no-ops or identities without periodic faces).
    void fold(Grid<dim>& g, const std::vector<Index>& activeBlocks,
              unsigned fields = FoldAll) const {
        lattice_->fold(g, activeBlocks, fields);
    }
    template <class T>
    void foldField(NodeArray<T>& q, const std::vector<Index>& activeBlocks) const {
        lattice_->foldField(q, activeBlocks);
    }
    void closeActiveBlocks(std::vector<Index>& blocks) { lattice_->closeActiveBlocks(blocks); }
    void wrap(Particles<dim>& p) const { lattice_->wrap(p); }
    Vec<dim> wrapPosition(const Vec<dim>& x) const { return lattice_->wrapPosition(x); }
    Vec<dim> separation(const Vec<dim>& a, const Vec<dim>& b) const {
        return lattice_->separation(a, b);
    }

    /// Patches of face f: patch 0 takes the nodes no box selects (the box-less patch, named
    /// after the face when it is the whole face or implicit slip); the boxed ones follow in
    /// file order.
    int numPatches(int f) const { return static_cast<int>(faces_[f].patches.size()); }
    const std::string& patchName(int f, int k) const { return faces_[f].patches[k].name; }
    /// Nodes of patch k of face f: owners first, then periodic images.
    const std::vector<Index>& patchNodes(int f, int k) const { return faces_[f].patches[k].nodes; }
    /// True if patch k of face f is active at time t (from ≤ t < until).
    bool active(int f, int k, double t) const { return faces_[f].patches[k].active(t); }
    /// Reaction of the last constrainUpdate through patch k of face f (whichever condition
    /// governed its nodes) [N].
    const Vec<dim>& patchReaction(int f, int k) const { return faces_[f].patches[k].reaction; }

private:
    struct Patch {
        std::string name;
        FaceKind kind = FaceKind::constrained;
        std::unique_ptr<BoundaryCondition<dim>> condition; ///< constrained patches only
        bool boxed = false;
        Vec<dim> boxMin = Vec<dim>::Zero(), boxMax = Vec<dim>::Zero();
        Vec<dim> extentMin = Vec<dim>::Zero(), extentMax = Vec<dim>::Zero(); ///< its nodes
        double from = -std::numeric_limits<double>::infinity();
        double until = std::numeric_limits<double>::infinity();
        std::vector<Index> nodes; ///< owners first, then images
        Index owners = 0;
        /// The nodes grouped by grid block (owners, then images; x fastest within a block):
        /// the nodes of blocks[k] are byBlock[start[k] .. start[k + 1]).
        std::vector<Index> byBlock, blocks, start;
        Index ownerBlocks = 0;   ///< blocks[0 .. ownerBlocks) hold owners, the rest images
        std::vector<Index> live; ///< this step's nodes in active blocks (owners first)
        Index liveOwners = 0;
        Vec<dim> reaction = Vec<dim>::Zero();
        bool active(double t) const { return from <= t && t < until; }
    };
    struct Face {
        std::vector<Patch> patches; ///< [0]: the box-less patch (implicit slip if none given)
        int partner = -1;           ///< a periodic face's partner (the opposite face), else -1
        bool periodic() const { return partner >= 0; }
    };

    void readFace(const Dictionary& boundary, int f);
    Patch readPatch(const Dictionary& dict, const std::string& name, int f, bool whole) const;
    Patch wordPatch(const Dictionary& parent, const std::string& key) const;
    /// An unknown `type` (read from `key` of `dict`) is an input error listing typeNames().
    static void checkType(const Dictionary& dict, const std::string& key, const std::string& type);
    /// A patch of face `name` with the implicit condition slip.
    static Patch slipPatch(const std::string& name);
    void assignNodes(const Dictionary* faceDict, int f);
    void groupByBlock(Patch& p) const;
    /// The condition governing patch k of face f at time t; nullptr where an open patch
    /// governs (no constraint).
    const BoundaryCondition<dim>* governing(const Face& face, std::size_t k, double t) const;
    /// Apply `condition` to the updated velocities of p's live nodes and return the reaction,
    /// the force the material exerts on the patch, F = Σ m_i (v_i⁻ − v_i⁺)/Δt over its owner
    /// nodes [N] (per metre in 2D) [000 §4.2]: v⁻ is the undamped update v⁰ + Δt (f/m + g) for
    /// the first condition acting on a node this step, otherwise the velocity the previous
    /// condition left (edges and corners; `touched_`). Periodic images are constrained alike
    /// but not counted.
    Vec<dim> constrainAndReact(const BoundaryCondition<dim>& condition, const Patch& p,
                               const FaceNormal& n, Grid<dim>& g, const Vec<dim>& gravity, double t,
                               double dt);

    const Grid<dim>& grid_;
    std::array<Face, NumFaces> faces_;
    std::unique_ptr<BoundaryCondition<dim>> slip_;  ///< fallback
    std::unique_ptr<PeriodicLattice<dim>> lattice_; ///< built once the faces are read
    bool hasOpen_ = false;
    bool hasUnilateral_ = false;
    NodeArray<char> touched_;          ///< a condition acted on the node this step
    std::vector<Vec<dim>> before_;     ///< scratch: v⁻ of a patch's owner nodes
    NodeArray<unsigned char> contact_; ///< per node: bit a = pressed against an axis-a wall
};

} // namespace mpm
