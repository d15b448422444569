// SPDX-License-Identifier: GPL-3.0-or-later
#include "parallel/Subdomain.hpp"

#include "core/Log.hpp"
#include "parallel/Migration.hpp"

#include <algorithm>

namespace mpm {

template <int dim>
Subdomain<dim>::Subdomain(const Case& cs, const Grid<dim>& grid, const Comm& comm)
    : comm_(comm), grid_(grid),
      decomposition_(Decomposition<dim>::read(cs, "constant/decomposition", grid.blocks())),
      dict_(cs.read("system/decomposeParDict")), rebalance_(RebalanceSettings::read(dict_)) {
    if (decomposition_.size() != comm_.size())
        throw InputError(cs.root().string() + "/constant/decomposition", 0, "numberOfSubdomains",
                         "the case is decomposed into " + std::to_string(decomposition_.size()) +
                             " subdomains but the run has " + std::to_string(comm_.size()) +
                             " ranks: run mpirun -np " + std::to_string(decomposition_.size()) +
                             ", or decomposePar again");
    halo_ = std::make_unique<GridHalo<dim>>(comm_, decomposition_);
}

template <int dim> void Subdomain<dim>::readTime(const Case& cs, const std::string& from) {
    const std::string file = from + "/uniform/decomposition";
    if (cs.exists(file)) decomposition_ = Decomposition<dim>::read(cs, file, grid_.blocks());
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
    if (rebalance_.enabled() && step % rebalance_.interval == 0) rebalance(p, step);
    return migrate(p, grid_, decomposition_, comm_, scratch);
}

template <int dim> void Subdomain<dim>::rebalance(const Particles<dim>& p, long step) {
    const double n = static_cast<double>(p.size());
    const double mean = comm_.sum(n) / comm_.size();
    const double before = mean > 0 ? comm_.max(n) / mean : 1.0;
    if (before <= rebalance_.maxImbalance) return;
    std::vector<Index> load(static_cast<std::size_t>(grid_.numBlocks()), 0);
    for (const Vec<dim>& x : p.x) {
        const Vec<dim> xh = (x - grid_.origin()) * grid_.invH();
        if (grid_.insideArrays(xh)) ++load[static_cast<std::size_t>(grid_.blockOf(xh))];
    }
    comm_.sum(load.data(), load.size()); // integers: exact in any order
    Decomposition<dim> next = Decomposition<dim>::build(dict_, grid_.blocks(), load);
    const std::vector<Index> after = next.loads(load);
    const double most = static_cast<double>(*std::max_element(after.begin(), after.end()));
    if (most / mean >= before) return; // the blocks allow no better: no migration for nothing
    decomposition_ = std::move(next);
    log() << "Rebalanced at step " << step << ": points per rank max/mean " << before << " -> "
          << most / mean << '\n';
}

template class Subdomain<2>;
template class Subdomain<3>;

} // namespace mpm
