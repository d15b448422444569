// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "grid/Grid.hpp"
#include "particles/Particles.hpp"

namespace mpm {

/// The particle fields a compute backend reads and writes, as pointers and a size (views, not
/// the containers): what a backend on another device mirrors. Read: x [m], mass [kg], volume
/// [m³], stress σ [Pa] (3×3), v [m/s], C [1/s] (APIC's affine velocity). Written by G2P: x, v,
/// C, and L [1/s] (the velocity gradient). The pointers stay valid while the particles are
/// neither added nor removed.
template <int dim> struct PointFields {
    Index count = 0;
    Vec<dim>* x = nullptr;
    Vec<dim>* v = nullptr;
    const double* mass = nullptr;
    const double* volume = nullptr;
    const Mat3* stress = nullptr;
    Mat<dim>* C = nullptr;
    Mat<dim>* L = nullptr;

    Index size() const { return count; }
};

/// The node fields a compute backend reads and writes (pointers into Grid's arrays, each
/// layout.numNodes() long), with the layout that numbers them (cell size, origin, axis offsets,
/// active blocks). mass [kg], momentum [kg m/s], force [N], vOld (the P2G velocity) and v (the
/// updated velocity) [m/s]; lines: the transfers' scratch, one 64-byte line per node.
template <int dim> struct NodeFields {
    const GridLayout<dim>* layout = nullptr;
    double* mass = nullptr;
    Vec<dim>* momentum = nullptr;
    Vec<dim>* force = nullptr;
    Vec<dim>* vOld = nullptr;
    Vec<dim>* v = nullptr;
    NodeLine* lines = nullptr;

    double h() const { return layout->h(); }
    double invH() const { return layout->invH(); }
    const Vec<dim>& origin() const { return layout->origin(); }
    Index axisOffset(int d, int i) const { return layout->axisOffset(d, i); }
    const std::vector<Index>& activeBlocks() const { return layout->activeBlocks(); }
};

template <int dim> PointFields<dim> fieldsOf(Particles<dim>& p) {
    return {static_cast<Index>(p.size()),
            p.x.data(),
            p.v.data(),
            p.mass.data(),
            p.volume.data(),
            p.stress.data(),
            p.C.data(),
            p.L.data()};
}

/// The views of points that the callee only reads (computeWeights, the scatters): it must not
/// write through the pointers of x, v, C and L.
template <int dim> PointFields<dim> readOnlyFieldsOf(const Particles<dim>& p) {
    return fieldsOf(const_cast<Particles<dim>&>(p));
}

template <int dim> NodeFields<dim> fieldsOf(Grid<dim>& g) {
    return {&g,         g.mass.data(), g.momentum.data(), g.force.data(), g.vOld.data(),
            g.v.data(), g.lines.data()};
}

} // namespace mpm
