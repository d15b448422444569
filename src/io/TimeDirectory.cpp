// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/TimeDirectory.hpp"

#include "core/Error.hpp"
#include "io/ParticleIO.hpp"

#include <algorithm>
#include <cmath>

namespace mpm::io {

namespace fs = std::filesystem;

TimeDirectoryWriter::TimeDirectoryWriter(const Case& cs, std::vector<std::string> indices)
    : case_(cs), names_(std::move(indices)), pvd_(names_.size()) {}

std::vector<std::string>
TimeDirectoryWriter::write(Time& time, const std::function<void(const fs::path&)>& fill,
                           const std::vector<std::string>& files,
                           const std::vector<std::string>* purge) {
    const std::string name = time.name();
    const fs::path dir = case_.path(name);
    const fs::path tmp = case_.path("." + name + ".writing");
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    fill(tmp);
    time.writeTimeDict(tmp);
    fs::remove_all(dir);
    fs::rename(tmp, dir);

    for (std::size_t k = 0; k < names_.size(); ++k) {
        if (!pvd_[k])
            pvd_[k] = std::make_unique<PvdIndex>(case_.path(names_[k] + ".pvd"), time.value());
        pvd_[k]->add(time.value(), name + "/" + files[k]);
    }
    const std::vector<std::string> old = purge ? *purge : time.wrote();
    for (const std::string& o : old) {
        fs::remove_all(case_.path(o));
        for (std::size_t k = 0; k < names_.size(); ++k)
            pvd_[k]->remove(o + "/" + files[k]);
    }
    return old;
}

std::string restartDirectory(const Case& cs, const Time& time) {
    const auto dirs = cs.timeDirectories();
    std::string from;
    if (time.startFrom() == "latestTime" && !dirs.empty()) from = dirs.back().second;
    if (time.startFrom() == "firstTime" && !dirs.empty()) from = dirs.front().second;
    if (time.startFrom() == "startTime") {
        for (const auto& [t, n] : dirs)
            if (std::fabs(t - time.startTime()) <= 1e-12 * std::max(1.0, t)) from = n;
        if (from.empty() && time.startTime() != 0.0)
            time.dict().error("startTime", "no time directory " + timeName(time.startTime(), 6) +
                                               " with particles.vtu to start from");
    }
    return from;
}

template <int dim>
void readParticles(const Case& cs, const std::string& timeDir, Particles<dim>& p,
                   std::size_t numMaterials) {
    const std::string file = timeDir + "/particles.vtu";
    PointCloud cloud;
    try {
        cloud = readVtu(cs.path(file));
    } catch (const std::exception& e) {
        throw InputError(file, 0, "", e.what());
    }
    fromPointCloud(cloud, p, file);
    for (const int m : p.material)
        if (m < 0 || m >= static_cast<int>(numMaterials))
            throw InputError(file, 0, "material",
                             "material index " + std::to_string(m) +
                                 " is not defined in constant/materials");
}

template void readParticles(const Case&, const std::string&, Particles<2>&, std::size_t);
template void readParticles(const Case&, const std::string&, Particles<3>&, std::size_t);

} // namespace mpm::io
