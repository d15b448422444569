// SPDX-License-Identifier: GPL-3.0-or-later
// mpmCloneCase: copy a case's set-up into a new case (OpenFOAM's foamCloneCase): system/,
// constant/ (level sets and meshes included), the 0/ time directory (or, with -latestTime, the
// latest one instead), *.orig folders and the files at the case's top level (Allrun, Allclean,
// makeX.py, README.md, ...). Results are not copied: other time directories, processor*/,
// postProcessing/, *.pvd, log.*, the stop file, nor files that tools generate for the case
// they were run in (mpmParaView.py, which names the original case's files). The copy is made
// in a hidden folder beside <to> and renamed into place, so <to> is either complete or absent.
#include "case/Case.hpp"
#include "case/CaseDirectory.hpp"
#include "core/Error.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
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
Usage: mpmCloneCase [OPTIONS] <from> <to>

Copy the case <from> into the new case <to> (OpenFOAM's foamCloneCase): system/,
constant/, the 0/ time directory, *.orig folders and the files at the top level
of <from> (Allrun, Allclean, scripts, README). Not copied: other time
directories, processor*/, postProcessing/, *.pvd, log.*, the stop file, the
generated mpmParaView.py (it names <from>'s files; run mpmParaView in <to>), and
other folders (listed). <to> must not exist.

options:
  -help                 print this usage and exit
  -latestTime           copy the latest time directory instead of 0/

)";

bool startsWith(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// A top-level file that a run writes: log.*, *.pvd (and *.series), the stop file, the
/// temporaries of an atomic write (*.tmp); or that a tool generates for this very case:
/// mpmParaView.py (bin/mpmParaView's script, which opens the original case's files by their
/// absolute paths).
bool isResultFile(const std::string& name) {
    return startsWith(name, "log.") || endsWith(name, ".pvd") || endsWith(name, ".series") ||
           endsWith(name, ".tmp") || name == "stop" || name == "mpmParaView.py";
}

/// A top-level folder that a run or decomposePar writes.
bool isResultDirectory(const std::string& name) {
    if (isTimeName(name) || name == "postProcessing") return true;
    if (startsWith(name, ".") && endsWith(name, ".writing")) return true; // a write in progress
    if (!startsWith(name, "processor") || name.size() == 9) return false;
    return std::all_of(name.begin() + 9, name.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == 's'; // processors<N>: collated
    });
}

/// True when `inner` is `outer` or lies inside it.
bool within(const fs::path& inner, const fs::path& outer) {
    const fs::path a = fs::weakly_canonical(inner), b = fs::weakly_canonical(outer);
    auto i = a.begin();
    for (auto j = b.begin(); j != b.end(); ++j, ++i)
        if (i == a.end() || *i != *j) return false;
    return true;
}

/// The time directory to copy: 0 (none when the case has no 0/), or with -latestTime the
/// latest one, which must hold particles.vtu (a parallel run's time needs reconstructPar).
std::string chooseTime(const fs::path& from, bool latestTime) {
    const auto times = timeDirectories(from, false);
    if (!latestTime) {
        for (const auto& t : times)
            if (t.first == 0.0) return t.second;
        return {};
    }
    if (times.empty()) return {};
    const std::string latest = times.back().second;
    if (!fs::is_regular_file(from / latest / "particles.vtu"))
        throw InputError(
            (from / latest).string(), 0, "",
            "-latestTime: the latest time directory has no particles.vtu" +
                std::string(fs::exists(from / latest / "particles.pvtu")
                                ? " (a parallel run's time: run reconstructPar -latestTime first)"
                                : " (an incomplete write?)"));
    return latest;
}

void clone(const fs::path& from, const fs::path& to, bool latestTime) {
    requireCaseDirectory(from, "the case to clone does not exist");
    if (fs::exists(fs::symlink_status(to)))
        throw InputError(to.string(), 0, "",
                         "already exists; mpmCloneCase never writes into an existing folder "
                         "(remove it or choose another name)");
    const fs::path parent = to.has_parent_path() ? to.parent_path() : fs::path(".");
    if (to.filename().empty() || to.filename() == "." || to.filename() == "..")
        throw InputError(to.string(), 0, "", "not a name for a new case folder");
    if (!fs::is_directory(parent))
        throw InputError(parent.string(), 0, "",
                         "the folder to create " + to.filename().string() + " in does not exist");

    const std::string time = chooseTime(from, latestTime);

    // What to copy, and the folders left out that are not results.
    std::vector<std::string> copied, skipped;
    for (const auto& e : fs::directory_iterator(from)) {
        const std::string name = e.path().filename().string();
        const bool directory = fs::is_directory(e.symlink_status());
        if (name == "system" || name == "constant" || name == time || endsWith(name, ".orig")) {
            copied.push_back(name);
        } else if (directory) {
            if (!isResultDirectory(name)) skipped.push_back(name + "/");
        } else if (!isResultFile(name)) {
            copied.push_back(name);
        }
    }
    std::sort(copied.begin(), copied.end());
    std::sort(skipped.begin(), skipped.end());
    for (const std::string& name : copied)
        if (fs::is_directory(fs::symlink_status(from / name)) && within(to, from / name))
            throw InputError(to.string(), 0, "",
                             "lies inside " + (from / name).string() +
                                 ", which is copied: choose a folder outside it");

    const fs::path staging =
        parent / ("." + to.filename().string() + ".cloning-" + std::to_string(getpid()));
    fs::remove_all(staging);
    try {
        fs::create_directory(staging);
        for (const std::string& name : copied)
            fs::copy(from / name, staging / name,
                     fs::copy_options::recursive | fs::copy_options::copy_symlinks);
        if (fs::exists(fs::symlink_status(to)))
            throw InputError(to.string(), 0, "", "was created while cloning; nothing written");
        fs::rename(staging, to);
    } catch (...) {
        std::error_code ec;
        fs::remove_all(staging, ec);
        throw;
    }

    std::cout << "Cloned " << from.string() << " to " << to.string() << ':';
    for (const std::string& name : copied)
        std::cout << ' ' << name << (fs::is_directory(to / name) ? "/" : "");
    std::cout << '\n';
    if (!skipped.empty()) {
        std::cout << "Not copied (folders other than system/, constant/ and the time directory):";
        for (const std::string& name : skipped)
            std::cout << ' ' << name;
        std::cout << '\n';
    }
}

} // namespace

int main(int argc, char* argv[]) {
    bool latestTime = false;
    std::vector<std::string> positional;
    std::string bad;
    for (int i = 1; i < argc && bad.empty(); ++i) {
        const std::string a = argv[i];
        if (a == "-help" || a == "--help" || a == "-h") {
            std::cout << usageText;
            return 0;
        }
        if (a == "-latestTime")
            latestTime = true;
        else if (a.size() > 1 && a[0] == '-')
            bad = "Invalid option: " + a;
        else
            positional.push_back(a);
    }
    for (std::string& p : positional) // "newCase/" names the folder newCase
        while (p.size() > 1 && p.back() == '/')
            p.pop_back();
    if (bad.empty() && positional.size() != 2)
        bad = "expected two arguments, <from> and <to>; got " + std::to_string(positional.size());
    if (!bad.empty()) {
        std::cerr << "\n--> MPMFOAM FATAL ERROR: " << escapeBytes(bad) << '\n' << usageText;
        return 1;
    }
    return reportingErrors([&] {
        clone(positional[0], positional[1], latestTime);
        return 0;
    });
}
