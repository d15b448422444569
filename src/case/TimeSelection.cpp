// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/TimeSelection.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace mpm {

namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::string names(const TimeSelection::TimeList& times) {
    std::string out;
    for (const auto& t : times)
        out += (out.empty() ? "" : " ") + t.second;
    return out.empty() ? "none" : out;
}

} // namespace

TimeSelection::TimeSelection(const std::string& list) : list_(list) {
    const auto bad = [&](const std::string& why) {
        return InputError("", 0, "", "-time '" + list + "': " + why);
    };
    const auto number = [&](const std::string& text, double open) {
        const std::string t = trim(text);
        if (t.empty()) return open;
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (end != t.c_str() + t.size() || !std::isfinite(v))
            throw bad("'" + t + "' is not a time (a number)");
        return v;
    };
    if (trim(list).empty()) throw bad("expected a time or a range (0.1, 0.1:0.3, :0.2, 0.2:)");
    std::size_t from = 0;
    while (from <= list.size()) {
        const std::size_t comma = std::min(list.find(',', from), list.size());
        const std::string item = trim(list.substr(from, comma - from));
        from = comma + 1;
        if (item.empty()) throw bad("an empty item (two commas, or one at an end)");
        const std::size_t colon = item.find(':');
        const double inf = std::numeric_limits<double>::infinity();
        if (colon == std::string::npos) {
            const double v = number(item, 0.0);
            items_.push_back({item, v, v, true});
            continue;
        }
        if (item.find(':', colon + 1) != std::string::npos)
            throw bad("'" + item + "' has more than one ':'");
        const double lo = number(item.substr(0, colon), -inf);
        const double hi = number(item.substr(colon + 1), inf);
        if (lo > hi) throw bad("the range '" + item + "' starts after it ends");
        items_.push_back({item, lo, hi, false});
    }
}

bool TimeSelection::near(double a, double b) {
    return std::fabs(a - b) <= 1e-9 * std::max({1e-300, std::fabs(a), std::fabs(b)});
}

TimeSelection::TimeList TimeSelection::select(const TimeList& times) const {
    std::vector<char> chosen(times.size(), 0);
    for (const Item& item : items_) {
        bool any = false;
        for (std::size_t k = 0; k < times.size(); ++k) {
            const double t = times[k].first;
            const bool in = item.single ? times[k].second == item.text || near(t, item.lo)
                                        : (t >= item.lo || near(t, item.lo)) &&
                                              (t <= item.hi || near(t, item.hi));
            if (in) chosen[k] = any = 1;
        }
        if (item.single && !any)
            throw InputError("", 0, "",
                             "-time: no written time " + item.text + " (times: " + names(times) +
                                 ")");
    }
    TimeList out;
    for (std::size_t k = 0; k < times.size(); ++k)
        if (chosen[k]) out.push_back(times[k]);
    if (out.empty())
        throw InputError("", 0, "",
                         "-time '" + list_ + "' selects no written time (times: " + names(times) +
                             ")");
    return out;
}

} // namespace mpm
