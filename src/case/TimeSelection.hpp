// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mpm {

/// OpenFOAM's `-time` list (timeSelector): comma-separated items, each a time (`0.1`) or an
/// inclusive range (`0.1:0.3`, `:0.2` from the first time, `0.2:` to the last, `:` all), e.g.
/// `-time '0,0.1:0.2,0.5:'`.
class TimeSelection {
public:
    using TimeList = std::vector<std::pair<double, std::string>>; ///< (value, name), by value

    /// Parse `list`; an InputError (naming `-time`) for an empty list or item, a bound that is not
    /// a finite number, or a range whose start is after its end.
    explicit TimeSelection(const std::string& list);

    /// The times of `times` (sorted by value) that the list selects, in time order. A single
    /// time selects the time of that name or of that value (to 1e-9 relative, a directory's
    /// name rounds its time); ranges include their ends (to the same tolerance). An InputError
    /// (naming `-time`, listing `times`) for a single time that is not written or a list that
    /// selects none.
    TimeList select(const TimeList& times) const;

private:
    struct Item {
        std::string text; ///< as given
        double lo, hi;    ///< bounds (±inf for an open end)
        bool single;      ///< a time, not a range
    };
    static bool near(double a, double b);
    std::string list_;
    std::vector<Item> items_;
};

} // namespace mpm
