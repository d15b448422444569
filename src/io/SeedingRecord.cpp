// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/SeedingRecord.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

namespace mpm::io {

namespace fs = std::filesystem;

std::string fileHash(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {};
    std::uint64_t h = 14695981039346656037ULL; // FNV-1a 64
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        const std::streamsize n = in.gcount();
        for (std::streamsize i = 0; i < n; ++i) {
            h ^= static_cast<unsigned char>(buffer[i]);
            h *= 1099511628211ULL;
        }
    }
    if (in.bad()) return {};
    static constexpr char hex[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int k = 15; k >= 0; --k, h >>= 4)
        out[static_cast<std::size_t>(k)] = hex[h & 15];
    return out;
}

SeedingInputs seedingInputs(const Case& cs, bool preload) {
    const fs::path root = cs.globalRoot();
    SeedingInputs inputs;
    std::error_code ec;
    const fs::path constant = root / "constant";
    if (fs::is_directory(constant, ec)) {
        fs::recursive_directory_iterator it(constant,
                                            fs::directory_options::follow_directory_symlink, ec);
        for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            const std::string name = it->path().filename().string();
            const bool hidden = !name.empty() && name[0] == '.';
            if (hidden && it->is_directory(ec)) {
                it.disable_recursion_pending();
                continue;
            }
            if (hidden || name.empty() || name.back() == '~' || !it->is_regular_file(ec)) continue;
            inputs.emplace_back(it->path().lexically_relative(root).generic_string(),
                                fileHash(it->path()));
        }
    }
    if (preload) inputs.emplace_back("system/mpmSchemes", fileHash(root / "system/mpmSchemes"));
    std::sort(inputs.begin(), inputs.end());
    return inputs;
}

std::string seedingRecord(const SeedingInputs& inputs) {
    std::ostringstream os;
    os << "# mpmFoam seeded this time directory from these files (FNV-1a 64 hash, path from the\n"
          "# case). A restart from it seeds again when one of them has changed, is new under\n"
          "# constant/ or is gone; without this file the time directory is used as it is\n"
          "# (docs/caseFormat.md, section 9).\n";
    for (const auto& [path, hash] : inputs)
        os << (hash.empty() ? std::string(16, '-') : hash) << "  " << path << '\n';
    return os.str();
}

std::string seedingChange(const Case& cs, const std::string& timeDir) {
    std::ifstream in(cs.path(timeDir + "/uniform/seeding"));
    if (!in) return {};
    std::map<std::string, std::string> recorded;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t gap = line.find("  ");
        if (gap == std::string::npos) continue;
        recorded[line.substr(gap + 2)] = line.substr(0, gap);
    }
    std::map<std::string, std::string> now;
    for (const auto& [path, hash] : seedingInputs(cs, false))
        now[path] = hash.empty() ? std::string(16, '-') : hash;
    for (const auto& [path, hash] : recorded) // inputs outside constant/ (system/mpmSchemes)
        if (path.compare(0, 9, "constant/") != 0) {
            const std::string h = fileHash(cs.globalRoot() / path);
            if (!h.empty()) now[path] = h;
        }
    std::vector<std::string> changes;
    for (const auto& [path, hash] : recorded) {
        const auto it = now.find(path);
        if (it == now.end())
            changes.push_back(path + " is gone");
        else if (it->second != hash)
            changes.push_back(path + " has changed");
    }
    for (const auto& [path, hash] : now)
        if (!recorded.count(path)) changes.push_back(path + " is new");
    std::string out;
    for (std::size_t k = 0; k < changes.size() && k < 3; ++k)
        out += (k ? ", " : "") + changes[k];
    if (changes.size() > 3) out += " and " + std::to_string(changes.size() - 3) + " more";
    return out;
}

} // namespace mpm::io
