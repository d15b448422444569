// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/Reconstruct.hpp"

#include "case/Case.hpp"
#include "io/ParticleFile.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <system_error>

namespace mpm::io {

namespace fs = std::filesystem;

namespace {

std::string processorName(int r) {
    return "processor" + std::to_string(r);
}

/// `processor<r>/<time>/particles.vtu`, how messages name a piece.
std::string pieceName(int r, const std::string& timeName) {
    return processorName(r) + "/" + timeName + "/particles.vtu";
}

/// The processor number of a directory name `processor<digits>`, or -1 for any other name.
int processorNumber(const std::string& name) {
    const std::string prefix = "processor";
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return -1;
    const std::string digits = name.substr(prefix.size());
    if (!std::all_of(digits.begin(), digits.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
        return -1;
    if (digits.size() > 9 || (digits.size() > 1 && digits[0] == '0'))
        throw std::runtime_error("unexpected directory " + name +
                                 ": processor directories are processor0, processor1, ... "
                                 "(no leading zeros)");
    return std::atoi(digits.c_str());
}

/// Point-array `a` of `piece` must match `expected` (name, components, type).
void checkArray(const PointArray& expected, const PointArray* a, const std::string& piece,
                const std::string& first) {
    if (a == nullptr)
        throw std::runtime_error(piece + ": no array '" + expected.name + "' (" + first +
                                 " has it)");
    if (a->components != expected.components || a->isInteger() != expected.isInteger()) {
        const auto describe = [](const PointArray& x) {
            return std::string(x.isInteger() ? "Int64" : "Float64") + " × " +
                   std::to_string(x.components);
        };
        throw std::runtime_error(piece + ": array '" + a->name + "' is " + describe(*a) + ", but " +
                                 describe(expected) + " in " + first);
    }
}

/// Append the points and arrays of `piece` to `total`, in the order of `total`'s arrays.
void append(PointCloud& total, PointCloud&& piece) {
    total.points.insert(total.points.end(), piece.points.begin(), piece.points.end());
    for (PointArray& a : total.arrays) {
        PointArray& b = *std::find_if(piece.arrays.begin(), piece.arrays.end(),
                                      [&](const PointArray& x) { return x.name == a.name; });
        a.f64.insert(a.f64.end(), b.f64.begin(), b.f64.end());
        a.i64.insert(a.i64.end(), b.i64.begin(), b.i64.end());
    }
}

/// `values` (tuples of `components`) reordered: tuple k of the result is tuple order[k].
template <class T>
void permute(std::vector<T>& values, int components, const std::vector<std::size_t>& order) {
    if (values.empty()) return;
    const auto c = static_cast<std::size_t>(components);
    std::vector<T> out(values.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(order[k] * c), c,
                    out.begin() + static_cast<std::ptrdiff_t>(k * c));
    values = std::move(out);
}

} // namespace

int countProcessors(const fs::path& caseRoot) {
    std::error_code ec;
    fs::directory_iterator it(caseRoot, ec);
    if (ec) throw std::runtime_error("cannot list " + caseRoot.string() + ": " + ec.message());
    std::vector<int> found;
    for (const fs::directory_entry& e : it) {
        const int r = processorNumber(e.path().filename().string());
        if (r >= 0 && e.is_directory(ec)) found.push_back(r);
    }
    std::sort(found.begin(), found.end());
    for (std::size_t k = 0; k < found.size(); ++k) {
        if (found[k] != static_cast<int>(k))
            throw std::runtime_error(caseRoot.string() + ": " + processorName(static_cast<int>(k)) +
                                     " is missing (found " + std::to_string(found.size()) +
                                     " processor directories up to " + processorName(found.back()) +
                                     "; they must be processor0 ... processor<N-1>)");
    }
    return static_cast<int>(found.size());
}

std::vector<std::pair<double, std::string>> processorTimes(const fs::path& caseRoot,
                                                           int numProcessors) {
    if (numProcessors < 1)
        throw std::runtime_error(caseRoot.string() + ": no processor directories");
    const auto times = timeDirectories(caseRoot / processorName(0), true);
    std::error_code ec;
    for (int r = 1; r < numProcessors; ++r) {
        for (const auto& time : times) {
            const std::string piece = pieceName(r, time.second);
            if (!fs::is_regular_file(caseRoot / piece, ec))
                throw std::runtime_error(caseRoot.string() + ": " + piece + " is missing (" +
                                         pieceName(0, time.second) + " exists)");
        }
    }
    return times;
}

std::size_t reconstructTime(const fs::path& caseRoot, int numProcessors,
                            const std::string& timeName) {
    if (numProcessors < 1)
        throw std::runtime_error(caseRoot.string() + ": no processor directories");
    const std::string first = pieceName(0, timeName);
    PointCloud total = readVtu(caseRoot / first);
    std::vector<std::size_t> starts{0}; // first point of each piece in `total`
    for (int r = 1; r < numProcessors; ++r) {
        const std::string piece = pieceName(r, timeName);
        PointCloud cloud = readVtu(caseRoot / piece);
        for (const PointArray& a : total.arrays)
            checkArray(a, cloud.find(a.name), caseRoot.string() + ": " + piece, first);
        for (const PointArray& a : cloud.arrays) {
            if (total.find(a.name) == nullptr)
                throw std::runtime_error(caseRoot.string() + ": " + piece + ": array '" + a.name +
                                         "' is not in " + first);
        }
        starts.push_back(total.size());
        append(total, std::move(cloud));
    }

    const PointArray* id = total.find("id");
    if (id == nullptr)
        throw std::runtime_error(caseRoot.string() + ": " + first +
                                 " has no 'id' array: the particles cannot be ordered");
    if (!id->isInteger() || id->components != 1)
        throw std::runtime_error(caseRoot.string() + ": " + first +
                                 ": the 'id' array is not one integer per point");
    const std::vector<std::int64_t>& ids = id->i64;
    std::vector<std::size_t> order(total.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
    const auto pieceOf = [&](std::size_t point) {
        return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), point) -
                                starts.begin()) -
               1;
    };
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (ids[order[k]] == ids[order[k - 1]])
            throw std::runtime_error(caseRoot.string() + ": duplicate particle id " +
                                     std::to_string(ids[order[k]]) + " in " +
                                     pieceName(pieceOf(order[k - 1]), timeName) + " and " +
                                     pieceName(pieceOf(order[k]), timeName));
    }
    permute(total.points, 3, order);
    for (PointArray& a : total.arrays) {
        permute(a.f64, a.components, order);
        permute(a.i64, a.components, order);
    }

    const fs::path target = caseRoot / timeName;
    fs::create_directories(target);
    writeVtu(target / "particles.vtu", total);

    const fs::path source = caseRoot / processorName(0) / timeName;
    for (const fs::directory_entry& e : fs::directory_iterator(source)) {
        const fs::path name = e.path().filename();
        if (name == "particles.vtu") continue;
        std::error_code ec;
        fs::copy(e.path(), target / name,
                 fs::copy_options::recursive | fs::copy_options::overwrite_existing, ec);
        if (ec)
            throw std::runtime_error("cannot copy " + e.path().string() + " to " +
                                     (target / name).string() + ": " + ec.message());
    }
    return total.size();
}

} // namespace mpm::io
