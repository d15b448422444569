// SPDX-License-Identifier: GPL-3.0-or-later
#include "grid/Grid.hpp"

#include <cmath>
#include <sstream>

namespace mpm {

template <int dim> std::string Grid<dim>::faceName(int f) {
    static const char* axes = "xyz";
    return std::string(1, axes[f / 2]) + (f % 2 == 0 ? "Min" : "Max");
}

template <int dim> Grid<dim>::Grid(const Dictionary& dict) {
    h_ = dict.getScalar("cellSize", Bounds::positive());
    invH_ = 1.0 / h_;
    const Dictionary b = dict.subDict("bounds");
    const std::vector<double> lo = b.getVector("min", dim);
    const std::vector<double> hi = b.getVector("max", dim);
    b.checkUnknownKeys();
    for (int d = 0; d < dim; ++d) {
        lo_[d] = lo[d];
        hi_[d] = hi[d];
        const double extent = hi[d] - lo[d];
        if (!(extent > 0)) b.error("max", "max must exceed min in every direction");
        const double cells = extent / h_;
        const double rounded = std::round(cells);
        if (rounded < 1 || std::fabs(cells - rounded) > 1e-6 * std::max(1.0, cells)) {
            std::ostringstream os;
            os << "the box extent " << extent << " m along "
               << "xyz"[d] << " is not a whole number of cells of size " << h_ << " m";
            dict.error("cellSize", os.str());
        }
        if (rounded > 1e5) dict.error("cellSize", "more than 100000 cells in one direction");
        n_[d] = static_cast<int>(rounded) + 1 + 2 * Pad;
        nb_[d] = (n_[d] + BlockSize - 1) / BlockSize;
        origin_[d] = lo_[d] - Pad * h_;
        hi_[d] = lo_[d] + rounded * h_;
    }
    numNodes_ = 1;
    numBlocks_ = 1;
    for (int d = 0; d < dim; ++d) {
        stride_[d] = numNodes_;
        numNodes_ *= n_[d];
        numBlocks_ *= nb_[d];
    }
    if (numNodes_ > Index(400) * 1000 * 1000)
        dict.error("cellSize", "the grid would have more than 4e8 nodes");

    // Nodes on or beyond each face: layers 0..Pad on the low side, n-1-Pad..n-1 on the high side.
    for (int f = 0; f < NumFaces; ++f) {
        const int axis = f / 2;
        for (Index k = 0; k < numNodes_; ++k) {
            const int i = static_cast<int>((k / stride_[axis]) % n_[axis]);
            const bool on = (f % 2 == 0) ? i <= Pad : i >= n_[axis] - 1 - Pad;
            if (on) faceNodes_[f].push_back(k);
        }
    }

    mass.assign(numNodes_, 0.0);
    momentum.assign(numNodes_, Vec<dim>::Zero());
    force.assign(numNodes_, Vec<dim>::Zero());
    vOld.assign(numNodes_, Vec<dim>::Zero());
    v.assign(numNodes_, Vec<dim>::Zero());
}

template class Grid<2>;
template class Grid<3>;

} // namespace mpm
