// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Case.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace mpm {

namespace fs = std::filesystem;

Case::Case(fs::path root) : root_(std::move(root)) {
    if (!fs::is_directory(root_))
        throw InputError(root_.string(), 0, "", "the case directory does not exist");
    if (!fs::is_directory(root_ / "system"))
        throw InputError(root_.string(), 0, "",
                         "not a case directory: it has no system/ folder (expected "
                         "system/controlDict, constant/grid, ...)");
}

bool Case::exists(const std::string& relative) const {
    return fs::is_regular_file(root_ / relative) ||
           fs::is_regular_file(root_ / (relative + ".yaml"));
}

Dictionary Case::read(const std::string& relative) const {
    fs::path p = root_ / relative;
    if (!fs::exists(p) && fs::exists(root_ / (relative + ".yaml")))
        p = root_ / (relative + ".yaml");
    if (!fs::is_regular_file(p)) throw InputError(relative, 0, "", "required file is missing");
    Dictionary d = Dictionary::fromFile(p, relative);
    d.setBaseDirectory(root_); // relative file entries (level sets, meshes) are case-relative
    return d;
}

std::vector<std::pair<double, std::string>> Case::timeDirectories() const {
    std::vector<std::pair<double, std::string>> dirs;
    for (const auto& e : fs::directory_iterator(root_)) {
        if (!e.is_directory()) continue;
        const std::string name = e.path().filename().string();
        char* end = nullptr;
        const double t = std::strtod(name.c_str(), &end);
        if (name.empty() || end != name.c_str() + name.size()) continue;
        if (!fs::exists(e.path() / "particles.vtu")) continue;
        dirs.emplace_back(t, name);
    }
    std::sort(dirs.begin(), dirs.end());
    return dirs;
}

std::string timeName(double t, int precision) {
    std::ostringstream os;
    os.precision(precision);
    os << t;
    return os.str();
}

} // namespace mpm
