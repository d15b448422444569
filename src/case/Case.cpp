// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Case.hpp"

#include <algorithm>
#include <cctype>
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

Case Case::processor(int rank) const {
    Case c;
    c.global_ = globalRoot();
    c.root_ = c.global_ / ("processor" + std::to_string(rank));
    if (!fs::is_directory(c.root_))
        throw InputError(c.root_.string(), 0, "",
                         "no such processor directory: run decomposePar first (with "
                         "numberOfSubdomains equal to mpirun's -np)");
    return c;
}

namespace {
/// A file of system/ or constant/: a processor case shares the root case's.
bool shared(const std::string& relative) {
    return relative.rfind("system/", 0) == 0 || relative.rfind("constant/", 0) == 0;
}
} // namespace

fs::path Case::locate(const std::string& relative) const {
    for (const fs::path& dir : {root_, global_}) {
        if (dir.empty() || (dir == global_ && !shared(relative))) continue;
        if (fs::is_regular_file(dir / relative)) return dir / relative;
        if (fs::is_regular_file(dir / (relative + ".yaml"))) return dir / (relative + ".yaml");
    }
    return root_ / relative;
}

bool Case::exists(const std::string& relative) const {
    return fs::is_regular_file(locate(relative));
}

std::string Case::displayName(const std::string& relative) const {
    if (global_.empty()) return relative;
    // The processor's own file, or one it should have (a time directory's); a shared file that
    // is missing belongs in the root case.
    const bool own = !shared(relative) || fs::is_regular_file(root_ / relative) ||
                     fs::is_regular_file(root_ / (relative + ".yaml"));
    return own ? (root_.filename() / relative).generic_string() : relative;
}

Dictionary Case::read(const std::string& relative) const {
    const fs::path p = locate(relative);
    const std::string name = displayName(relative);
    if (!fs::is_regular_file(p)) throw InputError(name, 0, "", "required file is missing");
    Dictionary d = Dictionary::fromFile(p, name);
    // Relative file entries (level sets, meshes) are relative to the (root) case.
    d.setBaseDirectory(globalRoot());
    return d;
}

std::vector<std::pair<double, std::string>> Case::timeDirectories() const {
    return mpm::timeDirectories(root_, true);
}

bool isTimeName(const std::string& s) {
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t start = i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
            ++i;
        return i - start;
    };
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t mantissa = digits();
    if (i < s.size() && s[i] == '.') {
        ++i;
        mantissa += digits();
    }
    if (mantissa == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        if (digits() == 0) return false;
    }
    return i == s.size();
}

std::vector<std::pair<double, std::string>> timeDirectories(const fs::path& dir,
                                                            bool withParticles) {
    std::vector<std::pair<double, std::string>> dirs;
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec) throw std::runtime_error("cannot list " + dir.string() + ": " + ec.message());
    for (const fs::directory_entry& e : it) {
        const std::string name = e.path().filename().string();
        if (!isTimeName(name) || !e.is_directory(ec)) continue;
        if (withParticles && !fs::is_regular_file(e.path() / "particles.vtu", ec)) continue;
        dirs.emplace_back(std::strtod(name.c_str(), nullptr), name);
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
