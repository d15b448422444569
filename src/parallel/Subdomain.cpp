// SPDX-License-Identifier: GPL-3.0-or-later
#include "parallel/Subdomain.hpp"

#include "core/Log.hpp"
#include "parallel/Migration.hpp"

#include <algorithm>

namespace mpm {

template <int dim>
Subdomain<dim>::Subdomain(const Case& cs, const Grid<dim>& grid, const Comm& comm,
                          std::function<void(std::vector<Index>&)> closeBlocks)
    : comm_(comm), grid_(grid),
      decomposition_(Decomposition<dim>::read(cs, "constant/decomposition", grid.blocks())),
      dict_(cs.read("system/decomposeParDict")), rebalance_(RebalanceSettings::read(dict_)),
      closeBlocks_(std::move(closeBlocks)) {
    if (decomposition_.size() != comm_.size())
        throw InputError(cs.root().string() + "/constant/decomposition", 0, "numberOfSubdomains",
                         "the case is decomposed into " + std::to_string(decomposition_.size()) +
                             " subdomains but the run has " + std::to_string(comm_.size()) +
                             (comm_.size() == 1 ? " rank" : " ranks") + ": run mpirun -np " +
                             std::to_string(decomposition_.size()) + ", or decomposePar again");
    halo_ = std::make_unique<GridHalo<dim>>(comm_, decomposition_);
    findNeighbours();
}

template <int dim> void Subdomain<dim>::findNeighbours() {
    const int me = comm_.rank();
    std::vector<Index> near;
    const IVec<dim> nb = grid_.blocks();
    for (Index b = 0; b < grid_.numBlocks(); ++b) {
        if (decomposition_.owner(b) != me) continue;
        const IVec<dim> c = grid_.blockCoord(b);
        for (int k = 0; k < (dim == 2 ? 9 : 27); ++k) { // the 3^dim neighbourhood
            IVec<dim> n;
            bool inside = true;
            for (int d = 0, code = k; d < dim; ++d, code /= 3) {
                n[d] = c[d] + code % 3 - 1;
                inside = inside && n[d] >= 0 && n[d] < nb[d];
            }
            if (!inside) continue;
            Index m = n[dim - 1];
            for (int d = dim - 2; d >= 0; --d)
                m = m * nb[d] + n[d];
            near.push_back(m);
        }
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    closeBlocks_(near);
    std::vector<char> listed(static_cast<std::size_t>(comm_.size()), 0);
    for (Index b : near)
        listed[static_cast<std::size_t>(decomposition_.owner(b))] = 1;
    listed[static_cast<std::size_t>(me)] = 0;
    // Symmetric: r is a neighbour when either lists the other (one full exchange).
    std::vector<std::vector<char>> send(listed.size());
    for (std::size_t r = 0; r < listed.size(); ++r)
        if (listed[r]) send[r].push_back(1);
    const std::vector<std::vector<char>> recv = comm_.exchange(send);
    neighbours_.clear();
    for (std::size_t r = 0; r < listed.size(); ++r)
        if (listed[r] || (static_cast<int>(r) != me && !recv[r].empty()))
            neighbours_.push_back(static_cast<int>(r));
    halo_->setNeighbours(&neighbours_);
}

template <int dim> void Subdomain<dim>::readTime(const Case& cs, const std::string& from) {
    const std::string file = from + "/uniform/decomposition";
    if (!cs.exists(file)) return;
    decomposition_ = Decomposition<dim>::read(cs, file, grid_.blocks());
    findNeighbours();
}

template <int dim> void Subdomain<dim>::writeTime(const std::filesystem::path& dir) const {
    if (!rebalance_.enabled()) return; // constant/decomposition holds
    std::filesystem::create_directories(dir / "uniform");
    decomposition_.write(dir / "uniform" / "decomposition");
}

template <int dim> void Subdomain<dim>::keepOwned(Particles<dim>& p) const {
    mpm::keepOwned(p, grid_, decomposition_, comm_.rank());
}

template <int dim>
bool Subdomain<dim>::exchangePoints(Particles<dim>& p, long step, PermuteBuffers<dim>& scratch) {
    const bool anywhere = !started_ || (rebalance_.enabled() && step % rebalance_.interval == 0 &&
                                        rebalance(p, step));
    started_ = true;
    return migrate(p, grid_, decomposition_, comm_, scratch, anywhere ? nullptr : &neighbours_);
}

template <int dim> bool Subdomain<dim>::rebalance(const Particles<dim>& p, long step) {
    const double n = static_cast<double>(p.size());
    const double mean = comm_.sum(n) / comm_.size();
    const double before = mean > 0 ? comm_.max(n) / mean : 1.0;
    if (before <= rebalance_.maxImbalance) return false;
    std::vector<Index> load(static_cast<std::size_t>(grid_.numBlocks()), 0);
    for (const Vec<dim>& x : p.x) {
        const Vec<dim> xh = (x - grid_.origin()) * grid_.invH();
        if (grid_.insideArrays(xh)) ++load[static_cast<std::size_t>(grid_.blockOf(xh))];
    }
    comm_.sum(load.data(), load.size()); // integers: exact in any order
    Decomposition<dim> next = Decomposition<dim>::build(dict_, grid_.blocks(), load);
    const std::vector<Index> after = next.loads(load);
    const double most = static_cast<double>(*std::max_element(after.begin(), after.end()));
    if (most / mean >= before) return false; // the blocks allow no better: keep the old one
    decomposition_ = std::move(next);
    findNeighbours();
    log() << "Rebalanced at step " << step << ": points per rank max/mean " << before << " -> "
          << most / mean << '\n';
    return true;
}

template class Subdomain<2>;
template class Subdomain<3>;

} // namespace mpm
