// SPDX-License-Identifier: GPL-3.0-or-later
#include "parallel/GridHalo.hpp"

#include <algorithm>

namespace mpm {

template <int dim>
std::vector<Index> GridHalo<dim>::exchangeBlocks(const std::vector<Index>& reached) {
    const int me = comm_.rank();
    const std::size_t n = static_cast<std::size_t>(comm_.size());
    for (auto& l : ghostOut_)
        l.clear();
    std::vector<Index> blocks;
    blocks.reserve(reached.size());
    for (Index b : reached) {
        const int r = decomposition_.owner(b);
        if (r == me)
            blocks.push_back(b);
        else
            ghostOut_[static_cast<std::size_t>(r)].push_back(b);
    }
    owned_ = blocks;
    std::vector<std::vector<char>> send(n);
    for (std::size_t r = 0; r < n; ++r)
        ByteWriter(send[r]).put(ghostOut_[r].data(), ghostOut_[r].size());
    const std::vector<std::vector<char>> recv = comm_.exchange(send, neighbours_);
    for (std::size_t r = 0; r < n; ++r) {
        ghostIn_[r].resize(recv[r].size() / sizeof(Index));
        ByteReader(recv[r]).get(ghostIn_[r].data(), ghostIn_[r].size());
        if (static_cast<int>(r) == me) ghostIn_[r].clear();
        owned_.insert(owned_.end(), ghostIn_[r].begin(), ghostIn_[r].end());
    }
    std::sort(owned_.begin(), owned_.end());
    owned_.erase(std::unique(owned_.begin(), owned_.end()), owned_.end());
    std::vector<Index> active = owned_;
    for (std::size_t r = 0; r < n; ++r)
        active.insert(active.end(), ghostOut_[r].begin(), ghostOut_[r].end());
    std::sort(active.begin(), active.end());
    return active;
}

template class GridHalo<2>;
template class GridHalo<3>;

} // namespace mpm
