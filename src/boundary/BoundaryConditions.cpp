// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/BoundaryConditions.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace mpm {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names)
        s += (s.empty() ? "" : ", ") + n;
    return s;
}

template <int dim> std::string point(const Vec<dim>& x) {
    std::ostringstream os;
    os << '(';
    for (int d = 0; d < dim; ++d)
        os << (d ? ", " : "") << x[d];
    os << ')';
    return os.str();
}

} // namespace

template <int dim>
void BoundaryConditions<dim>::checkType(const Dictionary& dict, const std::string& key,
                                        const std::string& type) {
    if (faceKind(type) == FaceKind::constrained &&
        BoundaryConditionRegistry<dim>::table().count(type) == 0)
        dict.error(key, "unknown type '" + type +
                            "'; valid types are: " + joined(boundaryTypeNames<dim>()) +
                            " (mpmFoam -list boundaryConditions shows their keys)");
}

template <int dim>
BoundaryConditions<dim>::BoundaryConditions(const Dictionary& gridDict, const Grid<dim>& grid)
    : grid_(grid),
      slip_(BoundaryCondition<dim>::create(Dictionary::fromString("{type: slip}", "(default)"))) {
    const Dictionary boundary = gridDict.has("boundary")
                                    ? gridDict.subDict("boundary")
                                    : Dictionary::fromString("{}", gridDict.fileName());
    std::array<std::optional<Dictionary>, NumFaces> faceDicts;
    for (int f = 0; f < NumFaces; ++f) {
        readFace(boundary, f);
        const std::string key = Grid<dim>::faceName(f);
        if (boundary.isDict(key)) faceDicts[f] = boundary.subDict(key);
    }
    boundary.checkUnknownKeys();

    std::array<bool, dim> periodic{};
    for (int a = 0; a < dim; ++a) {
        const bool lo = faces_[2 * a].periodic(), hi = faces_[2 * a + 1].periodic();
        if (lo != hi) {
            const std::string p = Grid<dim>::faceName(lo ? 2 * a : 2 * a + 1);
            const std::string q = Grid<dim>::faceName(lo ? 2 * a + 1 : 2 * a);
            boundary.error(p, p + " is periodic but " + q +
                                  " is not: periodic faces come in pairs (" +
                                  Grid<dim>::faceName(2 * a) + ": periodic, " +
                                  Grid<dim>::faceName(2 * a + 1) + ": periodic)");
        }
        periodic[a] = lo;
    }
    lattice_ = std::make_unique<PeriodicLattice<dim>>(grid, periodic);

    for (int f = 0; f < NumFaces; ++f)
        if (!faces_[f].periodic()) assignNodes(faceDicts[f] ? &*faceDicts[f] : nullptr, f);
    touched_.reset(grid.numNodes());
    contact_.reset(grid.numNodes());
    for (const Face& face : faces_)
        for (const Patch& p : face.patches)
            hasUnilateral_ = hasUnilateral_ || (p.condition && p.condition->unilateral());
    // An inactive patch hands its nodes to the face's box-less patch or to slip.
    for (const Face& face : faces_)
        for (const Patch& p : face.patches)
            if (!face.periodic() && (p.from > -std::numeric_limits<double>::infinity() ||
                                     p.until < std::numeric_limits<double>::infinity()))
                hasUnilateral_ = true;
}

template <int dim>
typename BoundaryConditions<dim>::Patch
BoundaryConditions<dim>::wordPatch(const Dictionary& parent, const std::string& key) const {
    const std::string type = parent.getString(key);
    Patch p;
    p.name = key;
    p.kind = faceKind(type);
    if (p.kind != FaceKind::constrained) return p;
    checkType(parent, key, type);
    try {
        p.condition = BoundaryCondition<dim>::create(
            Dictionary::fromString("{type: " + type + "}", parent.fileName()));
    } catch (const InputError& e) {
        parent.error(key, "type '" + type + "' needs parameters (" + e.key() +
                              "); write it as a map: {type: " + type + ", " + e.key() + ": …}");
    }
    return p;
}

template <int dim>
typename BoundaryConditions<dim>::Patch
BoundaryConditions<dim>::readPatch(const Dictionary& dict, const std::string& name, int f,
                                   bool whole) const {
    const int axis = f / 2;
    Patch p;
    p.name = name;
    const std::string type = dict.getString("type");
    p.kind = faceKind(type);
    checkType(dict, "type", type);
    if (p.kind == FaceKind::constrained)
        p.condition = BoundaryCondition<dim>::create(dict);
    else
        setKeyHelp(dict, "boundaryConditions", type);
    if (dict.has("box")) {
        if (whole)
            dict.error("box", "a face map with `type` is one patch covering the whole face; to "
                              "limit a condition to a box, name the face's patches: {<name>: "
                              "{type: …, box: {min: […], max: […]}}, …}");
        const Dictionary b = dict.subDict("box");
        const std::vector<double> lo = b.getVector("min", dim), hi = b.getVector("max", dim);
        b.checkUnknownKeys();
        for (int d = 0; d < dim; ++d) {
            p.boxMin[d] = lo[d];
            p.boxMax[d] = hi[d];
            if (d != axis && !(hi[d] >= lo[d]))
                b.error("max", "the box's max must not be below its min along the face");
        }
        p.boxed = true;
    }
    p.from = dict.getScalarOr("from", p.from);
    p.until = dict.getScalarOr("until", p.until);
    if (!(p.until > p.from))
        dict.error("until", "the window [from, until) is empty: until must exceed from");
    if (p.kind == FaceKind::periodic &&
        (!whole || p.boxed || dict.has("from") || dict.has("until")))
        dict.error("type", "periodic acts on a whole face, always: write " +
                               Grid<dim>::faceName(f) +
                               ": periodic (and its opposite face "
                               "periodic too), without box or window");
    dict.checkUnknownKeys();
    return p;
}

template <int dim> void BoundaryConditions<dim>::readFace(const Dictionary& boundary, int f) {
    const std::string key = Grid<dim>::faceName(f);
    Face& face = faces_[f];
    if (!boundary.has(key)) {
        face.patches.push_back(slipPatch(key));
    } else if (!boundary.isDict(key)) {
        face.patches.push_back(wordPatch(boundary, key));
    } else {
        const Dictionary d = boundary.subDict(key);
        if (d.has("type")) {
            face.patches.push_back(readPatch(d, key, f, true));
        } else {
            const std::vector<std::string> names = d.keys();
            if (names.empty())
                boundary.error(key, "no condition: write a type (" + key +
                                        ": slip) or named patches ({wall: {type: noSlip}, …})");
            std::optional<Patch> rest;
            std::vector<Patch> boxed;
            for (const std::string& name : names) {
                Patch p = d.isDict(name) ? readPatch(d.subDict(name), name, f, false)
                                         : wordPatch(d, name);
                if (p.kind == FaceKind::periodic)
                    d.error(name, "periodic acts on a whole face, always: write " + key +
                                      ": periodic (and its opposite face periodic too)");
                if (p.boxed) {
                    boxed.push_back(std::move(p));
                } else if (rest) {
                    d.error(name, "patches '" + rest->name + "' and '" + name + "' of " + key +
                                      " both have no box: at most one patch of a face covers "
                                      "the rest of it; give the others a box");
                } else {
                    rest = std::move(p);
                }
            }
            if (!rest) rest = slipPatch(key);
            face.patches.push_back(std::move(*rest));
            for (auto& p : boxed)
                face.patches.push_back(std::move(p));
        }
    }
    for (const Patch& p : face.patches)
        hasOpen_ |= p.kind == FaceKind::open;
    if (face.patches.front().kind == FaceKind::periodic) face.partner = f ^ 1;
}

template <int dim>
typename BoundaryConditions<dim>::Patch
BoundaryConditions<dim>::slipPatch(const std::string& name) {
    Patch p;
    p.name = name;
    p.condition = BoundaryCondition<dim>::create(Dictionary::fromString("{type: slip}", ""));
    return p;
}

template <int dim> void BoundaryConditions<dim>::assignNodes(const Dictionary* faceDict, int f) {
    const int axis = f / 2;
    Face& face = faces_[f];
    const std::size_t numPatches = face.patches.size();
    const double tol = 1e-6 * grid_.h();
    std::vector<std::vector<Index>> owners(numPatches), images(numPatches);
    std::vector<bool> seen(numPatches, false);
    for (Index k : grid_.faceNodes(f)) {
        // Tangential position of the node's owner (images follow their owners).
        IVec<dim> c = grid_.nodeCoord(k);
        for (int d = 0; d < dim; ++d)
            c[d] = lattice_->ownerCoord(d, c[d]);
        const Vec<dim> x = grid_.nodePosition(c);
        std::size_t in = 0;
        for (std::size_t q = 1; q < numPatches; ++q) {
            const Patch& p = face.patches[q];
            bool inside = true;
            for (int d = 0; d < dim; ++d)
                if (d != axis && (x[d] < p.boxMin[d] - tol || x[d] > p.boxMax[d] + tol))
                    inside = false;
            if (!inside) continue;
            if (in != 0) {
                MPM_ASSERT(faceDict);
                faceDict->error(p.name, "patches '" + face.patches[in].name + "' and '" + p.name +
                                            "' of " + Grid<dim>::faceName(f) +
                                            " overlap: both boxes hold the node at " +
                                            point<dim>(x) +
                                            "; boxed patches of one face must not share a node");
            }
            in = q;
        }
        Patch& p = face.patches[in];
        if (lattice_->isOwner(k)) {
            owners[in].push_back(k);
            if (!seen[in]) p.extentMin = p.extentMax = x;
            seen[in] = true;
            p.extentMin = p.extentMin.cwiseMin(x);
            p.extentMax = p.extentMax.cwiseMax(x);
        } else {
            images[in].push_back(k);
        }
    }
    for (std::size_t q = 0; q < numPatches; ++q) {
        Patch& p = face.patches[q];
        if (q > 0 && owners[q].empty()) {
            MPM_ASSERT(faceDict);
            faceDict->error(p.name, "the box of patch '" + p.name + "' holds no node of face " +
                                        Grid<dim>::faceName(f) + " (cell size " +
                                        std::to_string(grid_.h()) +
                                        " m; the box's coordinates along the face decide)");
        }
        p.nodes = std::move(owners[q]);
        p.owners = static_cast<Index>(p.nodes.size());
        p.nodes.insert(p.nodes.end(), images[q].begin(), images[q].end());
        groupByBlock(p);
    }
}

template <int dim> void BoundaryConditions<dim>::groupByBlock(Patch& p) const {
    p.byBlock.clear(), p.blocks.clear(), p.start.clear();
    auto group = [&](Index first, Index last) {
        std::vector<std::pair<Index, Index>> keyed; // (block, node), stable by block
        for (Index k = first; k < last; ++k)
            keyed.emplace_back(p.nodes[k] / Grid<dim>::NodesPerBlock, p.nodes[k]);
        std::stable_sort(keyed.begin(), keyed.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [block, node] : keyed) {
            if (p.blocks.empty() || p.blocks.back() != block ||
                static_cast<Index>(p.blocks.size()) == p.ownerBlocks) {
                p.blocks.push_back(block);
                p.start.push_back(static_cast<Index>(p.byBlock.size()));
            }
            p.byBlock.push_back(node);
        }
    };
    p.ownerBlocks = -1;
    group(0, p.owners);
    p.ownerBlocks = static_cast<Index>(p.blocks.size());
    group(p.owners, static_cast<Index>(p.nodes.size()));
    p.start.push_back(static_cast<Index>(p.byBlock.size()));
}

template <int dim>
void BoundaryConditions<dim>::selectActive(const Grid<dim>& g,
                                           const std::function<bool(Index)>& take) {
    for (Face& face : faces_) {
        if (face.periodic()) continue;
        for (Patch& p : face.patches) {
            for (Index i : p.live) // nodes the material left keep no contact
                if (!g.isActive(i / Grid<dim>::NodesPerBlock)) contact_[i] = 0;
            p.live.clear();
            const Index nb = static_cast<Index>(p.blocks.size());
            for (Index k = 0; k < nb; ++k) {
                if (k == p.ownerBlocks) p.liveOwners = static_cast<Index>(p.live.size());
                if (take(p.blocks[k]))
                    p.live.insert(p.live.end(), p.byBlock.begin() + p.start[k],
                                  p.byBlock.begin() + p.start[k + 1]);
            }
            if (p.ownerBlocks == nb) p.liveOwners = static_cast<Index>(p.live.size());
        }
    }
}

template <int dim>
const BoundaryCondition<dim>* BoundaryConditions<dim>::governing(const Face& face, std::size_t k,
                                                                 double t) const {
    const Patch& p = face.patches[k];
    if (p.active(t)) return p.condition.get();
    if (k > 0 && face.patches.front().active(t)) return face.patches.front().condition.get();
    return slip_.get();
}

template <int dim>
void BoundaryConditions<dim>::constrain(const Grid<dim>& g, NodeArray<Vec<dim>>& v,
                                        double t) const {
    for (int f = 0; f < NumFaces; ++f) {
        const Face& face = faces_[f];
        if (face.periodic()) continue;
        const FaceNormal normal{f / 2, f % 2 == 0 ? -1.0 : 1.0};
        for (std::size_t k = 0; k < face.patches.size(); ++k) {
            const Patch& p = face.patches[k];
            const BoundaryCondition<dim>* condition = governing(face, k, t);
            if (!condition) continue; // open: no constraint
            if (!condition->unilateral()) {
                condition->apply(p.live, normal, g.mass, v, t);
                continue;
            }
            const unsigned bit = 1u << normal.axis;
            const double wn = condition->wallNormalVelocity(normal, t);
            for (Index i : p.live)
                if (g.mass[i] != 0 && (contact_[i] & bit)) v[i][normal.axis] = wn;
        }
    }
}

template <int dim> std::vector<std::pair<Index, int>> BoundaryConditions<dim>::wallContact() const {
    std::vector<std::pair<Index, int>> contact;
    for (const Face& face : faces_) // only face nodes can touch a wall
        for (const Patch& p : face.patches)
            for (Index i : p.nodes)
                if (contact_[i]) contact.emplace_back(i, contact_[i]);
    std::sort(contact.begin(), contact.end());
    contact.erase(std::unique(contact.begin(), contact.end()), contact.end());
    return contact;
}

template <int dim>
void BoundaryConditions<dim>::setWallContact(const std::vector<std::pair<Index, int>>& contact) {
    for (const Face& face : faces_)
        for (const Patch& p : face.patches)
            for (Index i : p.nodes)
                contact_[i] = 0;
    for (const auto& [node, axes] : contact) {
        MPM_ASSERT(node >= 0 && node < static_cast<Index>(contact_.size()));
        contact_[node] = static_cast<unsigned char>(axes);
    }
    // The next selectActive clears the contact of the nodes that are not active then.
    for (Face& face : faces_)
        for (Patch& p : face.patches) {
            p.live.clear();
            for (Index i : p.nodes)
                if (contact_[i]) p.live.push_back(i);
        }
}

template <int dim>
Vec<dim> BoundaryConditions<dim>::constrainAndReact(const BoundaryCondition<dim>& condition,
                                                    const Patch& p, const FaceNormal& n,
                                                    Grid<dim>& g, const Vec<dim>& gravity, double t,
                                                    double dt) {
    // v⁻ of each owner node: the undamped update for the first condition acting on the node
    // this step, the velocity the previous one left otherwise (edges and corners).
    before_.resize(static_cast<std::size_t>(p.liveOwners));
    for (Index k = 0; k < p.liveOwners; ++k) {
        const Index i = p.live[static_cast<std::size_t>(k)];
        const double m = g.mass[i];
        if (m == 0) continue;
        before_[static_cast<std::size_t>(k)] = g.v[i];
        if (!touched_[i]) {
            before_[static_cast<std::size_t>(k)] = g.vOld[i] + dt * (g.force[i] / m + gravity);
            touched_[i] = 1;
        }
    }
    condition.apply(p.live, n, g.mass, g.v, t);
    Vec<dim> reaction = Vec<dim>::Zero();
    for (Index k = 0; k < p.liveOwners; ++k) {
        const Index i = p.live[static_cast<std::size_t>(k)];
        const double m = g.mass[i];
        if (m != 0) reaction += m * (before_[static_cast<std::size_t>(k)] - g.v[i]) / dt;
    }
    return reaction;
}

template <int dim>
void BoundaryConditions<dim>::constrainUpdate(Grid<dim>& g, const Vec<dim>& gravity, double t,
                                              double dt, Reactions& reactions) {
    for (const Face& face : faces_)
        for (const Patch& p : face.patches)
            for (Index i : p.live)
                touched_[i] = 0;
    for (int f = 0; f < NumFaces; ++f) {
        Face& face = faces_[f];
        Vec<dim> reaction = Vec<dim>::Zero();
        if (!face.periodic()) {
            const FaceNormal normal{f / 2, f % 2 == 0 ? -1.0 : 1.0};
            for (std::size_t k = 0; k < face.patches.size(); ++k) {
                Patch& p = face.patches[k];
                const BoundaryCondition<dim>* condition = governing(face, k, t); // null: open
                // Contact as the rule will find it: the updated velocity enters the wall.
                const unsigned bit = 1u << normal.axis;
                const bool unilateral = condition && condition->unilateral();
                const double wn = unilateral ? condition->wallNormalVelocity(normal, t) : 0.0;
                for (Index i : p.live) {
                    const bool pressed = unilateral && g.mass[i] != 0 &&
                                         normal.sign * (g.v[i][normal.axis] - wn) > 0;
                    contact_[i] = static_cast<unsigned char>(pressed ? contact_[i] | bit
                                                                     : contact_[i] & ~bit);
                }
                // An open patch leaves its nodes untouched and takes no reaction.
                p.reaction = condition ? constrainAndReact(*condition, p, normal, g, gravity, t, dt)
                                       : Vec<dim>::Zero();
                reaction += p.reaction;
            }
        }
        reactions[f] = reaction;
    }
}

template <int dim> bool BoundaryConditions<dim>::open(int f, const Vec<dim>& x, double t) const {
    const int axis = f / 2;
    const double h = grid_.h();
    const Vec<dim> y = lattice_->wrapPosition(x);
    for (const Patch& p : faces_[f].patches) {
        if (p.kind != FaceKind::open || !p.active(t)) continue;
        if (!p.boxed) return true;
        bool inside = true;
        for (int d = 0; d < dim; ++d)
            if (d != axis && (y[d] < p.extentMin[d] - h || y[d] > p.extentMax[d] + h))
                inside = false;
        if (inside) return true;
    }
    return false;
}

template <int dim> Index BoundaryConditions<dim>::removeOutflow(Particles<dim>& p, double t) const {
    // Faces with an open patch active now, and the coordinate beyond which a point has left.
    std::array<int, NumFaces> faces{};
    std::array<double, NumFaces> limit{};
    std::size_t numOpen = 0;
    for (int f = 0; f < NumFaces; ++f)
        for (const Patch& q : faces_[f].patches)
            if (q.kind == FaceKind::open && q.active(t)) {
                faces[numOpen] = f;
                limit[numOpen++] =
                    f % 2 == 0 ? grid_.lo()[f / 2] - grid_.h() : grid_.hi()[f / 2] + grid_.h();
                break;
            }
    if (numOpen == 0) return 0;
    auto outside = [&](Index i) {
        const Vec<dim>& x = p.x[i];
        for (std::size_t k = 0; k < numOpen; ++k) {
            const int f = faces[k];
            const bool beyond = f % 2 == 0 ? x[f / 2] < limit[k] : x[f / 2] > limit[k];
            if (beyond && open(f, x, t)) return true;
        }
        return false;
    };
    const Index n = static_cast<Index>(p.size());
    Index anyOut = 0;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(+ : anyOut)
    for (Index i = 0; i < n; ++i)
        anyOut += outside(i);
    if (anyOut == 0) return 0;
    std::vector<Index> keep;
    keep.reserve(n);
    for (Index i = 0; i < n; ++i)
        if (!outside(i)) keep.push_back(i);
    if (keep.empty()) throw RunError("every particle has left the domain through open faces");
    p.permute(keep);
    return n - static_cast<Index>(keep.size());
}

template class BoundaryConditions<2>;
template class BoundaryConditions<3>;

} // namespace mpm
