// SPDX-License-Identifier: GPL-3.0-or-later
// mpmListTimes: the written time directories of a case in time order (OpenFOAM's foamListTimes).
// A time directory is a folder whose name is a number (0.05, 1e-05: the names mpmFoam writes,
// the names bin/tools/CleanFunctions removes); the staging folders of a write in progress
// (`.0.004.writing`) are not numbers and are never listed. -rm removes the listed directories,
// never 0/, constant/ or system/, and drops them from particles.pvd and rigidBodies.pvd.
#include "case/Case.hpp"
#include "case/CaseDirectory.hpp"
#include "core/Error.hpp"
#include "io/PvdIndex.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace mpm;
namespace fs = std::filesystem;

namespace {

const char* const usageText =
    R"(
Usage: mpmListTimes [OPTIONS]

List the time directories of a case in time order, one name a line (OpenFOAM's
foamListTimes). 0 is left out unless -withZero; folders of a write in progress
(.<time>.writing) are never listed.

options:
  -case <dir>           case directory (default: the current directory)
  -help                 print this usage and exit
  -latestTime           only the latest time
  -processor            the times of processor0/ (a decomposed case); with -rm,
                        remove them from every processor<N>/
  -rm                   remove the listed time directories (never 0/, constant/,
                        system/) and their entries in particles.pvd, rigidBodies.pvd
  -withZero             list 0 too (not with -rm)

)";

struct Options {
    std::string caseDir = ".";
    bool latestTime = false, processor = false, rm = false, withZero = false;
};

using TimeList = std::vector<std::pair<double, std::string>>;

/// processor0, processor1, … of a decomposed case, in rank order.
std::vector<fs::path> processorDirectories(const fs::path& root) {
    std::vector<std::pair<long, fs::path>> dirs;
    for (const auto& e : fs::directory_iterator(root)) {
        const std::string name = e.path().filename().string();
        if (!e.is_directory() || name.size() <= 9 || name.compare(0, 9, "processor") != 0) continue;
        const std::string rank = name.substr(9);
        if (!std::all_of(rank.begin(), rank.end(),
                         [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
            continue;
        dirs.emplace_back(std::strtol(rank.c_str(), nullptr, 10), e.path());
    }
    std::sort(dirs.begin(), dirs.end());
    std::vector<fs::path> out;
    for (auto& d : dirs)
        out.push_back(std::move(d.second));
    return out;
}

void run(const Options& opt) {
    const fs::path root = opt.caseDir;
    requireCaseDirectory(root, "the case directory does not exist");

    std::vector<fs::path> processors;
    fs::path listed = root;
    if (opt.processor) {
        processors = processorDirectories(root);
        if (processors.empty())
            throw InputError(root.string(), 0, "",
                             "-processor: the case has no processor<N> directories (decomposePar "
                             "or a parallel run writes them)");
        listed = processors.front();
    }

    TimeList times = timeDirectories(listed, false);
    if (!opt.withZero)
        times.erase(std::remove_if(times.begin(), times.end(),
                                   [](const auto& t) { return t.first == 0.0; }),
                    times.end());
    if (opt.latestTime && !times.empty()) times.erase(times.begin(), times.end() - 1);

    if (!opt.rm) {
        for (const auto& t : times)
            std::cout << t.second << '\n';
        return;
    }

    std::vector<std::string> removed;
    for (const auto& t : times) {
        if (t.first == 0.0) continue; // never 0 (-withZero is refused with -rm anyway)
        const std::string& name = t.second;
        if (opt.processor) {
            for (const fs::path& p : processors)
                if (fs::is_directory(p / name)) fs::remove_all(p / name);
            std::cout << "Removed processor*/" << name << '\n';
        } else {
            fs::remove_all(root / name);
            std::cout << "Removed " << name << '\n';
        }
        removed.push_back(name);
    }
    // The ParaView indices of the root case list its own time directories only.
    if (!opt.processor && !removed.empty())
        for (const char* series : {"particles.pvd", "rigidBodies.pvd"}) {
            if (!fs::is_regular_file(root / series)) continue;
            io::PvdIndex pvd(root / series);
            for (const std::string& name : removed)
                pvd.remove(name);
        }
}

} // namespace

int main(int argc, char* argv[]) {
    Options opt;
    std::string bad;
    for (int i = 1; i < argc && bad.empty(); ++i) {
        const std::string a = argv[i];
        if (a == "-help" || a == "--help" || a == "-h") {
            std::cout << usageText;
            return 0;
        }
        if (a == "-case") {
            if (i + 1 >= argc)
                bad = "-case needs a directory";
            else
                opt.caseDir = argv[++i];
        } else if (a == "-latestTime") {
            opt.latestTime = true;
        } else if (a == "-processor") {
            opt.processor = true;
        } else if (a == "-rm") {
            opt.rm = true;
        } else if (a == "-withZero") {
            opt.withZero = true;
        } else {
            bad = "Invalid option: " + a;
        }
    }
    if (bad.empty() && opt.rm && opt.withZero) bad = "-rm never removes 0/: leave out -withZero";
    if (!bad.empty()) {
        std::cerr << "\n--> MPMFOAM FATAL ERROR: " << escapeBytes(bad) << '\n' << usageText;
        return 1;
    }
    return reportingErrors([&] {
        run(opt);
        return 0;
    });
}
