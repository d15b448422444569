// SPDX-License-Identifier: GPL-3.0-or-later
#include "parallel/Decomposition.hpp"

#include "case/Registry.hpp"
#include "case/Selection.hpp"
#include "io/ParticleFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace mpm {

namespace {

constexpr const char* axisNames = "xyz";

template <int dim> Index countBlocks(const IVec<dim>& nb) {
    Index n = 1;
    for (int d = 0; d < dim; ++d)
        n *= nb[d];
    return n;
}

/// A box of block coordinates, [lo, hi) along each axis.
template <int dim> struct Box { IVec<dim> lo, hi; };

/// Visit every block of `box` (x fastest): fn(block index, its coordinates).
template <int dim, class Fn> void forEachBlock(const Box<dim>& box, const IVec<dim>& nb, Fn&& fn) {
    for (int d = 0; d < dim; ++d)
        if (box.hi[d] <= box.lo[d]) return;
    IVec<dim> c = box.lo;
    while (true) {
        Index b = c[dim - 1];
        for (int d = dim - 2; d >= 0; --d)
            b = b * nb[d] + c[d];
        fn(b, c);
        int d = 0;
        while (d < dim && ++c[d] >= box.hi[d])
            c[d] = box.lo[d], ++d;
        if (d == dim) break;
    }
}

/// Cumulative load of the slices of `box` across axis a: cum[i] = load of the blocks whose
/// coordinate a lies in [lo_a, lo_a + i), i = 0 … hi_a − lo_a.
template <int dim>
std::vector<Index> cumulativeLoad(const std::vector<Index>& load, const IVec<dim>& nb,
                                  const Box<dim>& box, int a) {
    std::vector<Index> cum(static_cast<std::size_t>(box.hi[a] - box.lo[a]) + 1, 0);
    forEachBlock(box, nb, [&](Index b, const IVec<dim>& c) {
        cum[static_cast<std::size_t>(c[a] - box.lo[a]) + 1] += load[static_cast<std::size_t>(b)];
    });
    for (std::size_t i = 1; i < cum.size(); ++i)
        cum[i] += cum[i - 1];
    return cum;
}

/// The cut i in [first, last] that puts the fraction k/n of the load below it: the least
/// |cum[i] − (k/n) total|, then (equal load, as across empty slices or in a box with no load)
/// the least |i − (k/n) length|, then the highest i (a half rounds up). Integer arithmetic:
/// deterministic.
Index bestCut(const std::vector<Index>& cum, Index first, Index last, Index k, Index n) {
    const Index len = static_cast<Index>(cum.size()) - 1;
    const Index total = cum.back();
    Index best = first;
    std::pair<Index, Index> bestError{std::numeric_limits<Index>::max(), 0};
    for (Index i = first; i <= last; ++i) {
        const std::pair<Index, Index> e{
            std::llabs(cum[static_cast<std::size_t>(i)] * n - total * k),
            std::llabs(i * n - len * k)};
        if (e <= bestError) bestError = e, best = i;
    }
    return best;
}

template <int dim>
void assign(const Box<dim>& box, const IVec<dim>& nb, int rank, std::vector<std::int32_t>& owner) {
    forEachBlock(box, nb, [&](Index b, const IVec<dim>&) {
        owner[static_cast<std::size_t>(b)] = static_cast<std::int32_t>(rank);
    });
}

/// Rank sx + nx (sy + ny sz) of slab coordinates s.
template <int dim> int slabRank(const IVec<dim>& s, const IVec<dim>& n) {
    int r = s[dim - 1];
    for (int d = dim - 2; d >= 0; --d)
        r = r * n[d] + s[d];
    return r;
}

/// Hierarchical split of `box` along order[level], then its slabs along the next axes.
template <int dim>
void splitHierarchical(const std::vector<Index>& load, const IVec<dim>& nb, const IVec<dim>& n,
                       const IVec<dim>& order, int level, const Box<dim>& box, IVec<dim> slab,
                       std::vector<std::int32_t>& owner) {
    if (level == dim) {
        assign(box, nb, slabRank(slab, n), owner);
        return;
    }
    const int a = order[level];
    const std::vector<Index> cum = cumulativeLoad(load, nb, box, a);
    const Index len = box.hi[a] - box.lo[a]; // ≥ n[a], checked by build()
    Index prev = 0;
    for (int s = 0; s < n[a]; ++s) {
        // Each slab keeps at least one slice.
        const Index next =
            s + 1 == n[a] ? len : bestCut(cum, prev + 1, len - (n[a] - s - 1), s + 1, n[a]);
        Box<dim> sub = box;
        sub.lo[a] = box.lo[a] + static_cast<int>(prev);
        sub.hi[a] = box.lo[a] + static_cast<int>(next);
        slab[a] = s;
        splitHierarchical(load, nb, n, order, level + 1, sub, slab, owner);
        prev = next;
    }
}

/// Recursive bisection of `box` among the ranks [first, first + ranks).
template <int dim>
void bisect(const std::vector<Index>& load, const IVec<dim>& nb, const Box<dim>& box, int first,
            int ranks, std::vector<std::int32_t>& owner) {
    // The axis to cut: the longest extent of the loaded blocks (of the whole box when it has
    // no load), among the axes the box can be cut across (ties: the lowest). A tall column in a
    // wide box is then cut across its height, into compact subdomains.
    IVec<dim> lo = box.hi, hi = box.lo;
    bool loaded = false;
    forEachBlock(box, nb, [&](Index b, const IVec<dim>& c) {
        if (load[static_cast<std::size_t>(b)] == 0) return;
        loaded = true;
        for (int d = 0; d < dim; ++d)
            lo[d] = std::min(lo[d], c[d]), hi[d] = std::max(hi[d], c[d] + 1);
    });
    if (!loaded) lo = box.lo, hi = box.hi;
    int a = -1;
    for (int d = 0; d < dim; ++d)
        if (box.hi[d] - box.lo[d] >= 2 && (a < 0 || hi[d] - lo[d] > hi[a] - lo[a])) a = d;
    if (ranks == 1 || a < 0) { // a single block: the other ranks get none
        assign(box, nb, first, owner);
        return;
    }
    const Index len = box.hi[a] - box.lo[a];
    const int lower = ranks / 2;
    const std::vector<Index> cum = cumulativeLoad(load, nb, box, a);
    const Index cut = bestCut(cum, 1, len - 1, lower, ranks);
    Box<dim> below = box, above = box;
    below.hi[a] = box.lo[a] + static_cast<int>(cut);
    above.lo[a] = below.hi[a];
    bisect(load, nb, below, first, lower, owner);
    bisect(load, nb, above, first + lower, ranks - lower, owner);
}

/// `coeffs.n`: dim positive integers whose product is `size`, none above the blocks along its
/// axis (a subdomain would own no block).
template <int dim> IVec<dim> readCounts(const Dictionary& coeffs, int size, const IVec<dim>& nb) {
    const std::vector<double> v = coeffs.getVector("n", dim);
    IVec<dim> n;
    double product = 1;
    std::ostringstream os;
    for (int d = 0; d < dim; ++d) {
        if (!(v[d] >= 1 && v[d] <= 1e6 && v[d] == std::floor(v[d])))
            coeffs.error("n", "expected positive integers (subdomains along x, y" +
                                  std::string(dim == 3 ? ", z" : "") + ")");
        n[d] = static_cast<int>(v[d]);
        product *= v[d];
        os << (d ? " x " : "") << n[d];
    }
    if (product != size)
        coeffs.error("n", "the subdomains along the axes, " + os.str() + " = " +
                              std::to_string(static_cast<long long>(product)) +
                              ", must multiply to numberOfSubdomains (" + std::to_string(size) +
                              ")");
    for (int d = 0; d < dim; ++d) {
        if (n[d] > nb[d]) {
            std::ostringstream msg;
            msg << n[d] << " subdomains along " << axisNames[d] << " but the grid has only "
                << nb[d] << " blocks (of 4 nodes) along " << axisNames[d]
                << ": some subdomains would be empty (use fewer, or method bisection)";
            coeffs.error("n", msg.str());
        }
    }
    return n;
}

/// `coeffs.order`: a permutation of the axes' letters (default xyz, 2D xy).
template <int dim> IVec<dim> readOrder(const Dictionary& coeffs) {
    const std::string axes(axisNames, dim);
    const std::string order = coeffs.getStringOr("order", axes);
    std::string sorted = order;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != axes)
        coeffs.error("order", "expected a permutation of '" + axes + "' (the order of the " +
                                  "splits), got '" + order + "'");
    IVec<dim> o;
    for (int d = 0; d < dim; ++d)
        o[d] = static_cast<int>(order[static_cast<std::size_t>(d)] - 'x');
    return o;
}

/// An entry of a decomposition file that must be an integer in [lo, hi].
Index integerIn(const Dictionary& d, const std::string& key, double v, Index lo, Index hi) {
    if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi) && v == std::floor(v))) {
        std::ostringstream os;
        os << "expected integers in [" << lo << ", " << hi << "], got " << v
           << " (the file is written by decomposePar; run it again)";
        d.error(key, os.str());
    }
    return static_cast<Index>(v);
}

/// Slabs of equal block counts along each axis (simpleCoeffs.n).
template <int dim> class SimpleDecomposition : public DecompositionMethod<dim> {
public:
    explicit SimpleDecomposition(const Dictionary& /*dict*/) {}
    void assign(const Dictionary& dict, const std::vector<Index>& /*load*/, const IVec<dim>& nb,
                int size, std::vector<std::int32_t>& owner) const override {
        const Dictionary coeffs = dict.subDict("simpleCoeffs");
        const IVec<dim> n = readCounts(coeffs, size, nb);
        coeffs.checkUnknownKeys();
        forEachBlock(Box<dim>{IVec<dim>::Zero(), nb}, nb, [&](Index b, const IVec<dim>& c) {
            IVec<dim> s;
            for (int d = 0; d < dim; ++d)
                s[d] = static_cast<int>(static_cast<Index>(c[d]) * n[d] / nb[d]);
            owner[static_cast<std::size_t>(b)] = slabRank(s, n);
        });
    }
    bool balancesPoints() const override { return false; }
};

/// Slabs of equal load along the axes in `order` (hierarchicalCoeffs.n, order).
template <int dim> class HierarchicalDecomposition : public DecompositionMethod<dim> {
public:
    explicit HierarchicalDecomposition(const Dictionary& /*dict*/) {}
    void assign(const Dictionary& dict, const std::vector<Index>& load, const IVec<dim>& nb,
                int size, std::vector<std::int32_t>& owner) const override {
        const Dictionary coeffs = dict.subDict("hierarchicalCoeffs");
        const IVec<dim> n = readCounts(coeffs, size, nb);
        const IVec<dim> order = readOrder<dim>(coeffs);
        coeffs.checkUnknownKeys();
        splitHierarchical(load, nb, n, order, 0, Box<dim>{IVec<dim>::Zero(), nb},
                          IVec<dim>::Zero().eval(), owner);
    }
    bool balancesPoints() const override { return true; }
};

/// Recursive coordinate bisection of the load, any number of subdomains.
template <int dim> class BisectionDecomposition : public DecompositionMethod<dim> {
public:
    explicit BisectionDecomposition(const Dictionary& /*dict*/) {}
    void assign(const Dictionary& dict, const std::vector<Index>& load, const IVec<dim>& nb,
                int size, std::vector<std::int32_t>& owner) const override {
        if (dict.isDict("bisectionCoeffs")) dict.subDict("bisectionCoeffs").checkUnknownKeys();
        bisect(load, nb, Box<dim>{IVec<dim>::Zero(), nb}, 0, size, owner);
    }
    bool balancesPoints() const override { return true; }
};

MPM_FAMILY_INFO("decompositionMethods",
                {"method in system/decomposeParDict",
                 "12. system/decomposeParDict",
                 {{"method", "word", "-", "required", "how the blocks are shared out"}}});
MPM_FAMILY_DIMS(DecompositionMethodRegistry, "decompositionMethods");
MPM_REGISTER_DIMS(DecompositionMethodRegistry, SimpleDecomposition, "simple");
MPM_REGISTER_DIMS(DecompositionMethodRegistry, HierarchicalDecomposition, "hierarchical");
MPM_REGISTER_DIMS(DecompositionMethodRegistry, BisectionDecomposition, "bisection");
MPM_SCHEMA("decompositionMethods", "simple",
           {"slabs of equal block counts along each axis (ignores the points)",
            {{"simpleCoeffs", "map {n}", "-", "required",
              "n: subdomains per axis, their product numberOfSubdomains"}},
            "{method: simple, simpleCoeffs: {n: [2, 1]}}"});
MPM_SCHEMA("decompositionMethods", "hierarchical",
           {"slabs of equal load, axis by axis",
            {{"hierarchicalCoeffs", "map {n, order}", "-", "required",
              "n: subdomains per axis; order: the axes in splitting order (default xyz)"}},
            "{method: hierarchical, hierarchicalCoeffs: {n: [2, 1], order: xyz}}"});
MPM_SCHEMA("decompositionMethods", "bisection",
           {"recursive coordinate bisection of the load, any number of subdomains",
            {{"bisectionCoeffs", "map", "-", "none", "takes no key"}},
            "{method: bisection}"});

} // namespace

template <int dim>
Decomposition<dim>::Decomposition(const IVec<dim>& blocks, int size, std::string method)
    : blocks_(blocks), size_(size), method_(std::move(method)),
      owner_(static_cast<std::size_t>(countBlocks(blocks)), 0) {}

template <int dim>
Decomposition<dim>::Decomposition(const IVec<dim>& blocks) : Decomposition(blocks, 1, "none") {}

template <int dim>
Decomposition<dim> Decomposition<dim>::build(const Dictionary& dict, const IVec<dim>& blocks,
                                             const std::vector<Index>& load) {
    if (static_cast<Index>(load.size()) != countBlocks(blocks))
        throw std::invalid_argument("Decomposition::build: one load per block expected");
    const int size = dict.getInt("numberOfSubdomains", Bounds{1, 1e6});
    const std::string method =
        dict.getWord("method", registeredWords<DecompositionMethodRegistry<dim>>());
    for (const char* unused : {"simpleCoeffs", "hierarchicalCoeffs", "bisectionCoeffs"})
        dict.has(unused); // the other methods' coefficients may stay, as in OpenFOAM
    Decomposition dec(blocks, size, method);
    selectByWord<DecompositionMethodRegistry<dim>>(dict, "method", "")
        ->assign(dict, load, blocks, size, dec.owner_);
    return dec;
}

template <int dim>
Decomposition<dim> Decomposition<dim>::read(const Case& cs, const std::string& relativeFile,
                                            const IVec<dim>& blocks) {
    const Dictionary d = cs.read(relativeFile);
    const int size = d.getInt("numberOfSubdomains", Bounds{1, 1e6});
    std::vector<std::string> methods = registeredWords<DecompositionMethodRegistry<dim>>();
    methods.push_back("none");
    const std::string method = d.getWord("method", methods);
    const std::vector<double> nb = d.getVector("blocks", dim);
    for (int k = 0; k < dim; ++k) {
        if (nb[k] != blocks[k]) {
            std::ostringstream os;
            os << "made for a grid of";
            for (int j = 0; j < dim; ++j)
                os << (j ? " x " : " ") << nb[j];
            os << " blocks, but the grid has";
            for (int j = 0; j < dim; ++j)
                os << (j ? " x " : " ") << blocks[j];
            os << ": constant/grid changed since decomposePar ran; run decomposePar again";
            d.error("blocks", os.str());
        }
    }
    Decomposition dec(blocks, size, method);
    const std::vector<double> runs = d.getVector("owner");
    if (runs.size() % 2 != 0)
        d.error("owner", "expected pairs of rank and run length, got an odd count");
    const Index total = countBlocks(blocks);
    Index filled = 0;
    for (std::size_t k = 0; k < runs.size(); k += 2) {
        const Index rank = integerIn(d, "owner", runs[k], 0, size - 1);
        const Index count = integerIn(d, "owner", runs[k + 1], 1, total);
        if (count > total - filled)
            d.error("owner", "the runs cover more than the grid's " + std::to_string(total) +
                                 " blocks (run decomposePar again)");
        std::fill_n(dec.owner_.begin() + filled, count, static_cast<std::int32_t>(rank));
        filled += count;
    }
    if (filled != total)
        d.error("owner", "the runs cover " + std::to_string(filled) + " blocks of " +
                             std::to_string(total) + " (run decomposePar again)");
    d.checkUnknownKeys();
    return dec;
}

template <int dim> void Decomposition<dim>::write(const std::filesystem::path& file) const {
    std::ostringstream os;
    os << "# decomposePar: the owner (rank) of each block of 4^" << dim << " grid nodes,\n"
       << "# owner: [rank, blocks, rank, blocks, ...] run-length coded in block order\n"
       << "numberOfSubdomains: " << size_ << "\nmethod: " << method_ << "\nblocks: [";
    for (int d = 0; d < dim; ++d)
        os << (d ? ", " : "") << blocks_[d];
    os << "]\nowner: [";
    std::size_t runs = 0;
    for (std::size_t b = 0; b < owner_.size();) {
        std::size_t e = b;
        while (e < owner_.size() && owner_[e] == owner_[b])
            ++e;
        os << (runs == 0 ? "" : runs % 8 == 0 ? ",\n  " : ", ") << owner_[b] << ", " << e - b;
        ++runs;
        b = e;
    }
    os << "]\n";
    io::writeTextAtomic(file, os.str());
}

template <int dim>
std::vector<Index> Decomposition<dim>::loads(const std::vector<Index>& load) const {
    if (load.size() != owner_.size())
        throw std::invalid_argument("Decomposition::loads: one load per block expected");
    std::vector<Index> out(static_cast<std::size_t>(size_), 0);
    for (std::size_t b = 0; b < owner_.size(); ++b)
        out[static_cast<std::size_t>(owner_[b])] += load[b];
    return out;
}

template <int dim> std::vector<Index> Decomposition<dim>::blockCounts() const {
    std::vector<Index> out(static_cast<std::size_t>(size_), 0);
    for (const std::int32_t r : owner_)
        ++out[static_cast<std::size_t>(r)];
    return out;
}

template <int dim> int Decomposition<dim>::emptySubdomains() const {
    const std::vector<Index> counts = blockCounts();
    return static_cast<int>(std::count(counts.begin(), counts.end(), Index(0)));
}

RebalanceSettings RebalanceSettings::read(const Dictionary& dict) {
    RebalanceSettings r;
    if (!dict.has("rebalance")) return r;
    const Dictionary d = dict.subDict("rebalance");
    r.maxImbalance = d.getScalar("maxImbalance", Bounds{1.0, 1e300, false, true});
    r.interval = d.getIntOr("interval", 50, Bounds::closed(1, 1e9));
    d.checkUnknownKeys();
    if (!selectByWord<DecompositionMethodRegistry<2>>(dict, "method", "simple")->balancesPoints())
        dict.error("rebalance", "rebalancing needs a method that balances the points "
                                "(hierarchical or bisection); simple cuts the box geometrically");
    return r;
}

template class Decomposition<2>;
template class Decomposition<3>;

} // namespace mpm
