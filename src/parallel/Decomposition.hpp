// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mpm {

/// Which subdomain (MPI rank) owns each block of the grid (Grid::blocks(), 4^dim nodes each):
/// a rank owns whole blocks and the material points in them. Made by decomposePar from
/// system/decomposeParDict and the points' load per block, written to
/// `processor<r>/constant/decomposition` and read back by the parallel solver.
///
/// Methods (system/decomposeParDict `method`):
/// - `simple` (`simpleCoeffs.n`): slabs of equal block counts along each axis, block
///   coordinate c on axis d in slab ⌊c n_d / nb_d⌋; owner sx + nx (sy + ny sz).
/// - `hierarchical` (`hierarchicalCoeffs.n`, `order`, default xyz): split along the first axis
///   of `order` into n_a slabs of equal load, then each slab along the next axis by its own
///   load, and so on; owners numbered as simple. A slab with no load splits geometrically.
/// - `bisection`: recursive coordinate bisection balancing the load, for any number of
///   subdomains: a box of blocks with N ranks is cut across the longest axis of its loaded
///   blocks' bounding box (of the box itself without load; ties: the lowest)
///   into ⌊N/2⌋ and N − ⌊N/2⌋ ranks where the cumulative load best matches ⌊N/2⌋/N (a box with
///   no load: in that proportion of its length); ranks numbered depth first, lower part first.
///   A single block with N > 1 ranks goes to the first of them: the others own no block
///   (emptySubdomains() counts them), which happens only when N exceeds the number of blocks
///   of some branch.
/// Every method is deterministic: the same blocks and load give the same owners.
/// Run-time load balancing of system/decomposeParDict (`rebalance: {maxImbalance, interval}`):
/// every `interval` steps (default 50) a parallel run whose largest rank holds more than
/// `maxImbalance` times the mean number of points decomposes again by the current points, with
/// the dictionary's method (hierarchical or bisection: simple ignores the points).
struct RebalanceSettings {
    double maxImbalance = 0; ///< 0: never rebalance
    long interval = 50;      ///< steps between checks

    bool enabled() const { return maxImbalance > 0; }
    /// Read (and check) the optional `rebalance` entry; InputErrors name the key.
    static RebalanceSettings read(const Dictionary& dict);
};

/// A method of system/decomposeParDict (`method`; DecompositionMethodRegistry, family
/// `decompositionMethods`): simple, hierarchical or bisection, as above.
template <int dim> class DecompositionMethod {
public:
    virtual ~DecompositionMethod() = default;
    /// owner[b] ∈ [0, size) for every block b of the nb box, `load[b]` its points; reads (and
    /// checks) the method's coefficients in `dict`.
    virtual void assign(const Dictionary& dict, const std::vector<Index>& load, const IVec<dim>& nb,
                        int size, std::vector<std::int32_t>& owner) const = 0;
    /// True when the subdomains follow the points (a rebalance needs such a method).
    virtual bool balancesPoints() const = 0;
};

template <class Base, class... Args> class Registry; // case/Registry.hpp
template <int dim> using DecompositionMethodRegistry = Registry<DecompositionMethod<dim>>;

template <int dim> class Decomposition {
public:
    /// One subdomain (a serial run): every block owned by 0, method "none".
    explicit Decomposition(const IVec<dim>& blocks);

    /// From system/decomposeParDict: numberOfSubdomains, method and the method's coefficients
    /// (whose unknown keys are errors); the other methods' coefficient maps are allowed, as in
    /// OpenFOAM. The top-level dictionary's unknown keys are left to the caller
    /// (dict.checkUnknownKeys() after reading its own entries). `load[b]`: material points in
    /// block b (size: the product of `blocks`). Bad entries are InputErrors naming the key.
    static Decomposition build(const Dictionary& dict, const IVec<dim>& blocks,
                               const std::vector<Index>& load);

    /// Read a file written by write(), `relativeFile` of the case (e.g.
    /// "constant/decomposition"). An InputError naming that file when it is missing or
    /// malformed, or when its block counts differ from `blocks` (the grid changed since
    /// decomposePar ran).
    static Decomposition read(const Case& cs, const std::string& relativeFile,
                              const IVec<dim>& blocks);

    /// Write atomically as YAML: numberOfSubdomains, method, blocks [nbx, nby(, nbz)] and
    /// owner [rank, runLength, …], the owners run-length coded in block-index order. The
    /// folder must exist.
    void write(const std::filesystem::path& file) const;

    /// numberOfSubdomains.
    int size() const { return size_; }
    /// Rank owning block b (b = cx + nbx (cy + nby cz), Grid::blockOf).
    int owner(Index block) const { return owner_[static_cast<std::size_t>(block)]; }
    /// The owner of every block, in block-index order.
    const std::vector<std::int32_t>& owners() const { return owner_; }
    /// Blocks along each axis.
    const IVec<dim>& blocks() const { return blocks_; }
    /// "none" (serial), "simple", "hierarchical" or "bisection".
    const std::string& method() const { return method_; }

    /// Points per subdomain for `load[b]` points in block b.
    std::vector<Index> loads(const std::vector<Index>& load) const;
    /// Blocks owned by each subdomain.
    std::vector<Index> blockCounts() const;
    /// Subdomains that own no block (bisection with more ranks than a branch has blocks).
    int emptySubdomains() const;

    /// Same subdomains, method, blocks and owners.
    bool operator==(const Decomposition& o) const {
        return size_ == o.size_ && method_ == o.method_ && blocks_ == o.blocks_ &&
               owner_ == o.owner_;
    }
    bool operator!=(const Decomposition& o) const { return !(*this == o); }

private:
    Decomposition(const IVec<dim>& blocks, int size, std::string method);

    IVec<dim> blocks_;
    int size_ = 1;
    std::string method_;
    std::vector<std::int32_t> owner_; ///< one per block of the box
};

} // namespace mpm
