// SPDX-License-Identifier: GPL-3.0-or-later
#include "grid/GridLayout.hpp"

#include <cmath>
#include <sstream>

namespace mpm {

template <int dim> std::string GridLayout<dim>::faceName(int f) {
    static const char* axes = "xyz";
    return std::string(1, axes[f / 2]) + (f % 2 == 0 ? "Min" : "Max");
}

template <int dim> GridLayout<dim>::GridLayout(const Dictionary& dict) {
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
    numBlocks_ = 1;
    numFileNodes_ = 1;
    for (int d = 0; d < dim; ++d) {
        blockStride_[d] = NodesPerBlock * numBlocks_;
        numBlocks_ *= nb_[d];
        numFileNodes_ *= n_[d];
    }
    numNodes_ = numBlocks_ * NodesPerBlock;
    // The node fields are reserved, not committed (NodeArray): the limit is address space.
    if (numNodes_ > Index(4) * 1000 * 1000 * 1000)
        dict.error("cellSize", "the grid would have more than 4e9 nodes");

    edge_.assign(numBlocks_, 0);
    for (Index k = 0; k < numBlocks_; ++k) {
        const IVec<dim> c = blockCoord(k);
        for (int d = 0; d < dim; ++d)
            if ((c[d] + 1) * BlockSize > n_[d]) edge_[k] = 1;
    }

    // Nodes on or beyond each face: layers 0..Pad on the low side, n-1-Pad..n-1 on the high
    // side, listed x fastest.
    for (int f = 0; f < NumFaces; ++f) {
        const int axis = f / 2;
        IVec<dim> first = IVec<dim>::Zero(), end = n_;
        if (f % 2 == 0)
            end[axis] = Pad + 1;
        else
            first[axis] = n_[axis] - 1 - Pad;
        IVec<dim> i = first;
        while (true) {
            faceNodes_[f].push_back(nodeIndex(i));
            int d = 0;
            while (d < dim && ++i[d] >= end[d])
                i[d] = first[d], ++d;
            if (d == dim) break;
        }
    }

    activeFlag_.assign(numBlocks_, 0);
}

template class GridLayout<2>;
template class GridLayout<3>;

} // namespace mpm
