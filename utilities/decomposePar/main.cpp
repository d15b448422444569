// SPDX-License-Identifier: GPL-3.0-or-later
// decomposePar: split a case into the subdomains of a parallel run (OpenFOAM's decomposePar).
// The owner of each grid block, from system/decomposeParDict and the material points at the
// start time, goes to processor<r>/constant/decomposition; when the run starts from a time
// directory, processor<r>/<time>/ gets that processor's particles and a copy of the rest.
#include "boundary/BoundaryConditions.hpp"
#include "case/Case.hpp"
#include "case/Time.hpp"
#include "core/Log.hpp"
#include "forces/BodyAcceleration.hpp"
#include "grid/Grid.hpp"
#include "io/ParticleFile.hpp"
#include "io/SeedingRecord.hpp"
#include "io/TimeDirectory.hpp"
#include "materials/Material.hpp"
#include "parallel/Decomposition.hpp"
#include "particles/ParticleSeeder.hpp"
#include "particles/Particles.hpp"
#include "rigid/BodySet.hpp"
#include "solver/Application.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

using namespace mpm;
namespace fs = std::filesystem;

namespace {

/// The folders of an earlier decomposition: processor<N>, and processors<N>… (OpenFOAM's
/// collated format), sorted by name.
std::vector<fs::path> processorDirectories(const Case& cs) {
    std::vector<fs::path> dirs;
    for (const auto& e : fs::directory_iterator(cs.root())) {
        const std::string name = e.path().filename().string();
        if (!e.is_directory() || name.rfind("processor", 0) != 0) continue;
        std::size_t k = 9;
        if (k < name.size() && name[k] == 's') ++k;
        if (k < name.size() && std::isdigit(static_cast<unsigned char>(name[k])))
            dirs.push_back(e.path());
    }
    std::sort(dirs.begin(), dirs.end());
    return dirs;
}

/// "(x, y, z)".
template <int dim> std::string format(const Vec<dim>& x) {
    std::ostringstream os;
    for (int d = 0; d < dim; ++d)
        os << (d ? ", " : "(") << x[d];
    os << ')';
    return os.str();
}

/// The material points of a fresh start, seeded exactly as the solver seeds them.
template <int dim>
std::vector<Vec<dim>> seedPoints(const Case& cs, const Grid<dim>& grid,
                                 const BoundaryConditions<dim>& bc, const Time& time) {
    const auto acceleration = cs.exists("constant/g")
                                  ? BodyAcceleration<dim>::create(cs.read("constant/g"))
                                  : BodyAcceleration<dim>::constant(Vec<dim>::Zero());
    const auto materials = Material<dim>::createAll(cs.read("constant/materials"));
    Particles<dim> particles;
    for (const auto& m : materials)
        m->declareState(particles);
    const double t0 = time.startFrom() == "startTime" ? time.startTime() : 0.0;
    ParticleSeeder<dim> seeder(grid, materials, acceleration->at(t0));
    const BodySet<dim> bodies(cs, grid, &bc.lattice()); // for outsideBodies, as the solver
    if (!bodies.empty())
        seeder.setBodyDistance([&bodies](const Vec<dim>& x) { return bodies.distance(x); });
    seeder.seed(cs.read("constant/particles"), particles);
    bc.wrap(particles);
    return std::move(particles.x);
}

/// The points of `cloud` whose index is listed in `keep`, every array filtered alike.
io::PointCloud select(const io::PointCloud& cloud, const std::vector<std::size_t>& keep) {
    io::PointCloud out;
    out.points.reserve(3 * keep.size());
    for (const std::size_t i : keep)
        out.points.insert(out.points.end(), cloud.points.begin() + 3 * i,
                          cloud.points.begin() + 3 * (i + 1));
    for (const io::PointArray& a : cloud.arrays) {
        io::PointArray b;
        b.name = a.name;
        b.components = a.components;
        b.integer = a.isInteger();
        const auto c = static_cast<std::size_t>(a.components);
        for (const std::size_t i : keep) {
            if (!a.f64.empty())
                b.f64.insert(b.f64.end(), a.f64.begin() + c * i, a.f64.begin() + c * (i + 1));
            if (!a.i64.empty())
                b.i64.insert(b.i64.end(), a.i64.begin() + c * i, a.i64.begin() + c * (i + 1));
        }
        out.arrays.push_back(std::move(b));
    }
    return out;
}

template <int dim> void decompose(const Case& cs, const Dictionary& gridDict, bool force) {
    const Grid<dim> grid(gridDict);
    const BoundaryConditions<dim> bc(gridDict, grid); // checks the faces; wraps periodic seeds
    const Time time(cs);
    const Dictionary dict = cs.read("system/decomposeParDict");
    // A subdomain owns whole blocks: more subdomains than blocks leaves some without any (and
    // writes a folder for each), refused before anything is written.
    const int size = dict.getInt("numberOfSubdomains", Bounds{1, 1e6});
    if (size > grid.numBlocks()) {
        std::ostringstream os;
        os << size << " subdomains, but the grid (constant/grid) has only " << grid.numBlocks()
           << " blocks of 4^" << dim << " nodes, the unit of decomposition: a subdomain owns "
           << "whole blocks; use at most " << grid.numBlocks()
           << " (far fewer for useful subdomains)";
        dict.error("numberOfSubdomains", os.str());
    }

    const std::vector<fs::path> old = processorDirectories(cs);
    if (!old.empty() && !force) {
        std::string list;
        for (const fs::path& p : old)
            list += (list.empty() ? "" : ", ") + p.filename().string();
        throw InputError(cs.root().string(), 0, "",
                         "the case is already decomposed (" + list +
                             "); remove those folders or run decomposePar -force");
    }

    // The points at the start time.
    std::string from = io::restartDirectory(cs, time);
    // A seeded time whose inputs changed since: the run will seed again, so decompose that.
    if (const std::string change = from.empty() ? "" : io::seedingChange(cs, from);
        !change.empty()) {
        log() << "Not decomposing time " << from << ": " << change << " since it was seeded ("
              << from << "/uniform/seeding); seeding again\n";
        from.clear();
    }
    const std::string source = from.empty() ? "constant/particles" : from + "/particles.vtu";
    io::PointCloud cloud;
    std::vector<Vec<dim>> x;
    if (from.empty()) {
        x = seedPoints(cs, grid, bc, time);
    } else {
        try {
            cloud = io::readVtu(cs.path(source));
        } catch (const std::exception& e) {
            throw InputError(source, 0, "", e.what());
        }
        x.resize(cloud.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            for (int d = 0; d < dim; ++d)
                x[i][d] = cloud.points[3 * i + static_cast<std::size_t>(d)];
    }

    // Load per block.
    std::vector<Index> load(static_cast<std::size_t>(grid.numBlocks()), 0);
    std::vector<Index> block(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const Vec<dim> xh = (x[i] - grid.origin()) * grid.invH();
        if (!grid.insideArrays(xh)) {
            std::ostringstream os;
            os << "point " << i << " at " << format(x[i]) << " lies outside the grid "
               << format(grid.lo()) << " – " << format(grid.hi()) << " of constant/grid";
            throw InputError(source, 0, "", os.str());
        }
        block[i] = grid.blockOf(xh);
        ++load[static_cast<std::size_t>(block[i])];
    }

    const auto dec = Decomposition<dim>::build(dict, grid.blocks(), load);
    RebalanceSettings::read(dict); // checked here, used by the solver
    dict.checkUnknownKeys();
    const int n = dec.size();

    for (const fs::path& p : old) {
        log() << "Removing " << p.filename().string() << '\n';
        fs::remove_all(p);
    }
    std::vector<std::vector<std::size_t>> points(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < x.size(); ++i)
        points[static_cast<std::size_t>(dec.owner(block[i]))].push_back(i);
    for (int r = 0; r < n; ++r) {
        const fs::path dir = cs.path("processor" + std::to_string(r));
        fs::create_directories(dir / "constant");
        dec.write(dir / "constant/decomposition");
        if (from.empty()) continue;
        fs::create_directories(dir / from);
        io::writeVtu(dir / from / "particles.vtu", select(cloud, points[r]));
        for (const auto& e : fs::directory_iterator(cs.path(from))) {
            if (e.path().filename() == "particles.vtu") continue;
            fs::copy(e.path(), dir / from / e.path().filename(),
                     fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        }
    }

    // Report.
    std::vector<Index> occupied(static_cast<std::size_t>(n), 0);
    for (std::size_t b = 0; b < load.size(); ++b)
        if (load[b] > 0) ++occupied[static_cast<std::size_t>(dec.owner(static_cast<Index>(b)))];
    const std::vector<Index> owned = dec.blockCounts();
    log() << "Decomposed " << x.size() << " points (" << source << ") over " << grid.numBlocks()
          << " blocks of 4^" << dim << " nodes into " << n << " subdomains, method " << dec.method()
          << "\n\n"
          << std::setw(12) << "processor" << std::setw(12) << "points" << std::setw(18)
          << "occupied blocks" << std::setw(14) << "owned blocks" << '\n';
    Index most = 0;
    for (int r = 0; r < n; ++r) {
        const auto k = static_cast<std::size_t>(r);
        log() << std::setw(12) << r << std::setw(12) << points[k].size() << std::setw(18)
              << occupied[k] << std::setw(14) << owned[k] << '\n';
        most = std::max(most, static_cast<Index>(points[k].size()));
    }
    if (!x.empty())
        log() << "\nImbalance (max/mean points): " << std::setprecision(4)
              << static_cast<double>(most) * n / static_cast<double>(x.size()) << '\n';
    for (int r = 0; r < n; ++r)
        if (points[static_cast<std::size_t>(r)].empty())
            warning() << "processor" << r << " has no points"
                      << (owned[static_cast<std::size_t>(r)] == 0 ? " and owns no block" : "")
                      << '\n';
    log() << "\nWrote processor0"
          << (n > 1 ? " … processor" + std::to_string(n - 1) : std::string()) << '\n';
}

} // namespace

int main(int argc, char* argv[]) {
    const Application app(argc, argv, "decomposePar",
                          "Split the case into the subdomains of a parallel run "
                          "(system/decomposeParDict): processor<N>/ folders.",
                          {{"-force", "remove existing processor* folders first"}});
    return app.run([&] {
        const Case cs(app.caseDir());
        const Dictionary gridDict = cs.read("constant/grid");
        const int dim = gridDict.getInt("dimension", Bounds::closed(2, 3));
        if (dim == 2)
            decompose<2>(cs, gridDict, app.has("-force"));
        else
            decompose<3>(cs, gridDict, app.has("-force"));
        log() << "\nEnd\n";
    });
}
