// SPDX-License-Identifier: GPL-3.0-or-later
// surfaceToLevelSet: signed-distance grids (constant/levelSets/<name>.vti) of the surfaces named
// in system/surfaceToLevelSetDict, in each body's principal frame, with its mass properties.
#include "case/Case.hpp"
#include "case/CaseDirectory.hpp"
#include "core/Log.hpp"
#include "levelset/LevelSetFile.hpp"
#include "levelset/MassProperties.hpp"
#include "levelset/SignedDistance.hpp"
#include "levelset/TriangleMesh.hpp"
#include "solver/Application.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

using namespace mpm;
using namespace mpm::levelset;
namespace fs = std::filesystem;

namespace {

/// Largest grid accepted (nodes), about 1.6 GB of doubles.
constexpr double maxPoints = 2e8;

void convert(const Case& cs, const Dictionary& dict, const std::string& name, double cellSize) {
    const std::string fileName = dict.getStringOr("file", name + ".stl");
    const double scale = dict.getScalarOr("scale", 1.0, Bounds::positive());
    const bool hasSpacing = dict.has("spacing");
    double spacing = hasSpacing ? dict.getScalar("spacing", Bounds::positive()) : 0.0;
    const bool hasPadding = dict.has("padding");
    double padding = hasPadding ? dict.getScalar("padding", Bounds::nonNegative()) : 0.0;
    const std::string precision = dict.getWordOr("precision", "float", {"float", "double"});
    dict.checkUnknownKeys();

    fs::path file;
    for (const char* folder : {"constant/geometry", "constant/triSurface"}) {
        const fs::path candidate = cs.path(folder) / fileName;
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec)) {
            file = candidate;
            break;
        }
    }
    if (file.empty()) {
        dict.error(dict.has("file") ? "file" : "",
                   "'" + fileName + "' is not in constant/geometry/ or constant/triSurface/");
    }

    TriangleMesh mesh;
    try {
        mesh = readTriangleMesh(file, scale);
    } catch (const std::exception& e) {
        dict.error(dict.has("file") ? "file" : "", e.what());
    }
    log() << "Surface " << name << ": " << file.lexically_relative(cs.root()).string() << ", "
          << mesh.numTriangles() << " triangles, " << mesh.vertices.size() << " vertices\n";
    const MeshDiagnostics diag = diagnose(mesh);
    if (diag.boundaryEdges > 0) {
        warning() << name << ": open surface (" << diag.boundaryEdges
                  << " boundary edges); the sign comes from the winding number, the volume and "
                     "inertia are approximate\n";
    }
    if (diag.nonManifoldEdges > 0) {
        warning() << name << ": " << diag.nonManifoldEdges
                  << " non-manifold edges (shared by more than two triangles)\n";
    }
    if (diag.degenerateTriangles > 0) {
        warning() << name << ": " << diag.degenerateTriangles
                  << " degenerate (zero-area) triangles\n";
    }
    // The winding number does not mind the orientation; the mass properties do.
    const std::size_t flipped = orientOutward(mesh);
    if (diag.inconsistentEdges > 0) {
        warning() << name << ": inconsistent orientation (" << diag.inconsistentEdges
                  << " edges whose two triangles wind the same way); " << flipped
                  << " triangles reoriented outward for the mass properties\n";
    } else if (flipped > 0) {
        log() << "    " << flipped << " triangles wound inward: reoriented outward\n";
    }

    MassProperties mp;
    try {
        mp = computeMassProperties(mesh);
    } catch (const std::exception& e) {
        dict.error("", std::string(e.what()) + " (is it a closed surface?)");
    }
    log() << std::setprecision(6) << "    volume            " << mp.volume << '\n'
          << "    centroid          (" << mp.centroid.transpose() << ")\n"
          << "    principal moments (" << mp.principalMoments.transpose() << ")  (unit density)\n";

    if (!hasSpacing) {
        spacing = mesh.meanEdgeLength();
        if (cellSize > 0.0) spacing = std::min(spacing, cellSize);
    }
    if (!hasPadding) {
        // 3 spacings, and at least two MPM cells: coupling radius plus the kernel's support.
        padding = std::max(3.0 * spacing, 2.0 * cellSize);
    }

    mesh.toFrame(mp.centroid, mp.rotation);
    Vec3 lo, hi;
    mesh.bounds(lo, hi);
    lo.array() -= padding;
    hi.array() += padding;
    LevelSet ls;
    ls.volume = mp.volume;
    ls.centroid = mp.centroid;
    ls.principalMoments = mp.principalMoments;
    ls.rotation = mp.rotation;
    RegularGrid& grid = ls.grid;
    grid.spacing = spacing;
    double points = 1.0;
    for (int d = 0; d < 3; ++d) {
        const double n = std::ceil((hi[d] - lo[d]) / spacing) + 1.0;
        points *= n;
        if (n > 1e5 || points > maxPoints) {
            std::ostringstream os;
            os << "the level-set grid would have more than " << maxPoints << " points (spacing "
               << spacing << (hasSpacing ? "" : ", the default") << "); give a larger spacing";
            dict.error(hasSpacing ? "spacing" : "", os.str());
        }
        grid.dims[static_cast<std::size_t>(d)] = static_cast<int>(n);
        // Centre the grid on the padded bounds.
        grid.origin[d] = 0.5 * (lo[d] + hi[d]) - 0.5 * (n - 1.0) * spacing;
    }

    const auto t0 = std::chrono::steady_clock::now();
    const SignedDistance sdf(mesh);
    sdf.evaluate(grid);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const fs::path out = cs.path("constant/levelSets") / (name + ".vti");
    std::error_code ec;
    fs::create_directories(out.parent_path(), ec);
    writeVti(out, ls, precision == "double");
    log() << "    grid              " << grid.dims[0] << " x " << grid.dims[1] << " x "
          << grid.dims[2] << " = " << grid.numPoints() << " points, spacing " << spacing
          << ", padding " << padding << '\n'
          << "    signed distance   " << std::setprecision(3) << seconds << " s, "
          << std::setprecision(3) << static_cast<double>(grid.numPoints()) / seconds
          << " voxels/s on " << omp_get_max_threads() << " threads\n"
          << "    written           " << out.lexically_relative(cs.root()).string() << "\n\n";
}

} // namespace

int main(int argc, char* argv[]) {
    const Application app(argc, argv, "surfaceToLevelSet",
                          "Signed-distance grids (.vti) and mass properties of triangulated "
                          "surfaces, from system/surfaceToLevelSetDict.",
                          {});
    return app.run([&] {
        // The dictionary is what it needs; not system/controlDict, which a new case may not
        // have yet when its level sets are made (docs/userGuide.md §4).
        requireCaseDirectory(app.caseDir(), "the case directory does not exist",
                             "system/surfaceToLevelSetDict",
                             "no system/surfaceToLevelSetDict: it names the surfaces to convert "
                             "(docs/levelSets.md)");
        const Case cs(app.caseDir());
        const Dictionary dict = cs.read("system/surfaceToLevelSetDict");
        const Dictionary surfaces = dict.subDict("surfaces");
        dict.checkUnknownKeys();
        double cellSize = 0.0;
        if (cs.exists("constant/grid")) {
            const Dictionary grid = cs.read("constant/grid");
            if (grid.has("cellSize")) cellSize = grid.getScalar("cellSize", Bounds::positive());
        }
        const std::vector<std::string> names = surfaces.keys();
        if (names.empty()) surfaces.error("", "no surfaces");
        for (const std::string& name : names) {
            convert(cs, surfaces.subDict(name), name, cellSize);
        }
        log() << "End\n";
    });
}
