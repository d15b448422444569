// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Error.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace mpm {

/// Allowed interval of a scalar entry; an entry outside it is an InputError naming the bounds.
struct Bounds {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool loInclusive = true;
    bool hiInclusive = true;

    static Bounds positive() { return {0.0, std::numeric_limits<double>::infinity(), false, true}; }
    static Bounds nonNegative() {
        return {0.0, std::numeric_limits<double>::infinity(), true, true};
    }
    static Bounds closed(double lo, double hi) { return {lo, hi, true, true}; }
    static Bounds halfOpen(double lo, double hi) { return {lo, hi, true, false}; }
};

/// A YAML map read from a case file, with typed lookup and errors that name file, line and key.
///
/// Every lookup (`has`, `get*`, `subDict`) records the key as valid. After a model has read its
/// entries, `checkUnknownKeys()` reports any key present in the file but never looked up, naming
/// the nearest valid key (OpenFOAM-style: a misspelt key is an error, not silently ignored).
/// Copies share the record, so sub-dictionaries are checked by their own `checkUnknownKeys()`.
class Dictionary {
public:
    /// Parse `file`; `displayName` is how messages name it (e.g. "constant/materials").
    /// YAML syntax errors, a missing file or a top level that is not a map are InputErrors.
    static Dictionary fromFile(const std::filesystem::path& file, const std::string& displayName);
    /// Parse a YAML string (tests and in-code defaults).
    static Dictionary fromString(const std::string& text, const std::string& displayName);

    bool has(const std::string& key) const;

    /// Required entries: a missing key or a wrong type is an InputError.
    double getScalar(const std::string& key, Bounds bounds = {}) const;
    int getInt(const std::string& key, Bounds bounds = {}) const;
    bool getBool(const std::string& key) const; ///< yes|no|true|false|on|off
    std::string getString(const std::string& key) const;
    /// A sequence of exactly `size` numbers (size < 0: any length).
    std::vector<double> getVector(const std::string& key, int size = -1) const;
    /// A sequence of strings (e.g. `fields: [pressure, velocity]`); an item that is not a plain
    /// string is an InputError located at the item (`key[i]`).
    std::vector<std::string> getStringList(const std::string& key) const;
    /// One of `choices`; anything else is an InputError listing the choices.
    std::string getWord(const std::string& key, const std::vector<std::string>& choices) const;

    /// Optional entries with a documented default.
    double getScalarOr(const std::string& key, double def, Bounds bounds = {}) const;
    int getIntOr(const std::string& key, int def, Bounds bounds = {}) const;
    bool getBoolOr(const std::string& key, bool def) const;
    std::string getStringOr(const std::string& key, const std::string& def) const;
    std::vector<double> getVectorOr(const std::string& key, const std::vector<double>& def,
                                    int size = -1) const;
    std::string getWordOr(const std::string& key, const std::string& def,
                          const std::vector<std::string>& choices) const;

    /// A nested map (required; an entry that is not a map is an InputError).
    Dictionary subDict(const std::string& key) const;
    /// True if the entry exists and is a map.
    bool isDict(const std::string& key) const;
    /// A sequence of maps (e.g. polygon vertices are vectors, regions a list of maps).
    std::vector<Dictionary> dictList(const std::string& key) const;
    /// A sequence of numeric sequences (e.g. polygon vertices, tabulated motion).
    std::vector<std::vector<double>> vectorList(const std::string& key, int size = -1) const;

    /// Keys of this map in file order (marks none of them as read).
    std::vector<std::string> keys() const;

    /// Error on every key never looked up, e.g.
    /// `constant/grid:7: key 'grid.cellSzie': unknown key; did you mean 'cellSize'?`; with a
    /// KeyHelp the message also lists the model's keys.
    void checkUnknownKeys() const;

    /// What checkUnknownKeys says about the model that reads this map: Registry::create sets it
    /// from the type's key schema (core/KeySchema.hpp), the table `mpmFoam -list` prints.
    /// Shared by copies, like the record of read keys.
    struct KeyHelp {
        std::string model;             ///< the type, e.g. "linearElastic"
        std::vector<std::string> keys; ///< every key it reads; empty: the type has no schema
        std::string more;              ///< where its keys are described ("mpmFoam -list …")
    };
    void setKeyHelp(KeyHelp help) const { *help_ = std::move(help); }
    /// Every key looked up so far (read or tested with has), for the schema tests.
    const std::set<std::string>& readKeys() const { return *read_; }

    /// Throw an InputError located at `key` (or at this map if the key is absent).
    [[noreturn]] void error(const std::string& key, const std::string& message) const;
    /// Line (1-based) of `key`'s value, or of this map if absent.
    int line(const std::string& key) const;

    const std::string& fileName() const { return file_; }

    /// A path entry: relative values are taken from the base directory (the case directory
    /// for dictionaries read through Case; the working directory otherwise).
    std::filesystem::path getPath(const std::string& key) const;
    /// Set the directory relative paths are resolved against (inherited by sub-dictionaries).
    void setBaseDirectory(const std::filesystem::path& dir) { base_ = dir; }
    /// Dotted path of this map inside its file ("" for the top level).
    const std::string& path() const { return path_; }

private:
    Dictionary(YAML::Node node, std::string file, std::string path);
    YAML::Node node_;
    std::string file_;
    std::string path_;
    std::shared_ptr<std::set<std::string>> read_;
    std::shared_ptr<KeyHelp> help_;
    std::filesystem::path base_;
};

/// Levenshtein distance, for "did you mean" suggestions.
int editDistance(const std::string& a, const std::string& b);

} // namespace mpm
