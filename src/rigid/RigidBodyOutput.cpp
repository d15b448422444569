// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/RigidBodyOutput.hpp"

#include "io/ParticleFile.hpp"
#include "io/PolyDataFile.hpp"

#include <sstream>
#include <string>
#include <system_error>

namespace mpm {

namespace {

/// A YAML double-quoted key.
std::string quoted(const std::string& name) {
    std::string s = "\"";
    for (const char c : name) {
        if (c == '"' || c == '\\') s += '\\';
        s += c;
    }
    return s + "\"";
}

} // namespace

template <int dim>
void writeRigidBodies(const std::filesystem::path& vtpFile,
                      const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies) {
    std::vector<Vec3> points;
    std::vector<std::vector<int>> cells;
    io::DataArray body{"body", 1, {}};
    io::DataArray velocity{"velocity", 3, {}};

    std::vector<Vec3> local;
    std::vector<std::vector<int>> localCells;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const RigidBody<dim>& rb = *bodies[b];
        rb.shape().surface(local, localCells);
        const int first = static_cast<int>(points.size());
        for (const Vec3& p : local) {
            const Vec<dim> x = rb.position() + rb.rotation() * p.template head<dim>();
            const Vec<dim> v = rb.velocityAt(x);
            Vec3 x3 = Vec3::Zero();
            Vec3 v3 = Vec3::Zero();
            x3.template head<dim>() = x;
            v3.template head<dim>() = v;
            points.push_back(x3);
            velocity.values.insert(velocity.values.end(), v3.data(), v3.data() + 3);
        }
        for (std::vector<int> cell : localCells) {
            for (int& i : cell)
                i += first;
            cells.push_back(std::move(cell));
            body.values.push_back(static_cast<double>(b));
        }
    }
    io::writeVtp(vtpFile, points, cells, dim == 2, {velocity}, {body});
}

template <int dim>
void writeRigidBodyState(const std::filesystem::path& file,
                         const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies) {
    std::ostringstream text;
    for (const auto& b : bodies) {
        std::ostringstream state;
        b->writeState(state);
        text << quoted(b->name()) << ":\n";
        std::istringstream lines(state.str());
        for (std::string line; std::getline(lines, line);)
            text << "    " << line << "\n";
    }
    if (bodies.empty()) text << "{}\n";
    if (file.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(file.parent_path(), ec);
    }
    io::writeTextAtomic(file, text.str());
}

template <int dim>
void readRigidBodyState(const Dictionary& dict,
                        const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies) {
    for (const auto& b : bodies) {
        if (!dict.has(b->name())) {
            dict.error(b->name(), "no state for rigid body '" + b->name() + "'");
        }
        b->readState(dict.subDict(b->name()));
    }
    dict.checkUnknownKeys();
}

template void writeRigidBodies<2>(const std::filesystem::path&,
                                  const std::vector<std::unique_ptr<RigidBody<2>>>&);
template void writeRigidBodies<3>(const std::filesystem::path&,
                                  const std::vector<std::unique_ptr<RigidBody<3>>>&);
template void writeRigidBodyState<2>(const std::filesystem::path&,
                                     const std::vector<std::unique_ptr<RigidBody<2>>>&);
template void writeRigidBodyState<3>(const std::filesystem::path&,
                                     const std::vector<std::unique_ptr<RigidBody<3>>>&);
template void readRigidBodyState<2>(const Dictionary&,
                                    const std::vector<std::unique_ptr<RigidBody<2>>>&);
template void readRigidBodyState<3>(const Dictionary&,
                                    const std::vector<std::unique_ptr<RigidBody<3>>>&);

} // namespace mpm
