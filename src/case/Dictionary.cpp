// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Dictionary.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <locale>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>

namespace mpm {

namespace {

/// Deepest nesting accepted when validating a document (guards against recursive aliases).
constexpr int maxDepth = 64;

/// 1-based line of a YAML mark, 0 if the node has no position (e.g. a map built in code).
int lineOf(const YAML::Mark& mark) {
    return mark.line >= 0 ? mark.line + 1 : 0;
}

/// Shortest text that reads back as `v` ("0.001", "1e-06", "inf").
std::string formatNumber(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (std::isnan(v)) return "nan";
    std::string text;
    for (int precision = 1; precision <= 17; ++precision) {
        std::ostringstream os;
        os.imbue(std::locale::classic());
        os.precision(precision);
        os << v;
        text = os.str();
        double back = 0.0;
        std::from_chars(text.data(), text.data() + text.size(), back);
        if (back == v) break;
    }
    return text;
}

/// "(0, inf]", "[1, 10)", ...
std::string formatBounds(const Bounds& b) {
    return std::string(b.loInclusive ? "[" : "(") + formatNumber(b.lo) + ", " + formatNumber(b.hi) +
           (b.hiInclusive ? "]" : ")");
}

bool inBounds(double v, const Bounds& b) {
    const bool loOk = b.loInclusive ? v >= b.lo : v > b.lo;
    const bool hiOk = b.hiInclusive ? v <= b.hi : v < b.hi;
    return loOk && hiOk;
}

/// How an entry that has the wrong type is shown in a message.
std::string describe(const YAML::Node& node) {
    switch (node.Type()) {
    case YAML::NodeType::Map:
        return "a map";
    case YAML::NodeType::Sequence:
        return "a sequence";
    case YAML::NodeType::Null:
        return "an empty value";
    case YAML::NodeType::Scalar:
        return "'" + node.Scalar() + "'";
    default:
        return "nothing";
    }
}

/// Parse a finite decimal number; false for anything else (words, hex, nan, inf, overflow).
bool parseNumber(const std::string& text, double& value) {
    if (text.empty()) return false;
    const bool allowed = std::all_of(text.begin(), text.end(), [](char c) {
        return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
    });
    if (!allowed) return false;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    // from_chars does not take a leading '+'; YAML does.
    if (*first == '+') {
        ++first;
        if (first == last || *first == '+' || *first == '-') return false;
    }
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(first, last, v, std::chars_format::general);
    if (ec != std::errc() || ptr != last || !std::isfinite(v)) return false;
    value = v;
    return true;
}

/// Check a loaded document: keys are plain non-empty strings and no map repeats a key.
void validate(const YAML::Node& node, const std::string& file, const std::string& path, int depth) {
    if (depth > maxDepth) {
        throw InputError(file, lineOf(node.Mark()), path, "nesting too deep (recursive alias?)");
    }
    if (node.IsMap()) {
        std::set<std::string> seen;
        for (auto it = node.begin(); it != node.end(); ++it) {
            const YAML::Node k = it->first;
            if (!k.IsScalar() || k.Scalar().empty()) {
                throw InputError(file, lineOf(k.Mark()), path,
                                 "expected a plain name as key, got " + describe(k));
            }
            const std::string key = path.empty() ? k.Scalar() : path + "." + k.Scalar();
            if (!seen.insert(k.Scalar()).second) {
                throw InputError(file, lineOf(k.Mark()), key, "duplicate key");
            }
            validate(it->second, file, key, depth + 1);
        }
    } else if (node.IsSequence()) {
        for (std::size_t i = 0; i < node.size(); ++i) {
            validate(node[i], file, path + "[" + std::to_string(i) + "]", depth + 1);
        }
    }
}

/// The first entry of a file written in OpenFOAM's dictionary syntax, for the message that says
/// the case files are YAML.
struct FoamEntry {
    int line = 0;       ///< 1-based line of the entry (of the header when there is no entry)
    std::string key;    ///< its keyword ("" when the file has only a FoamFile header)
    std::string value;  ///< its value as written, without the ';' ("" for a sub-dictionary)
    bool block = false; ///< `key { … }`: a sub-dictionary
};

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

bool isKeyword(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
    });
}

/// Detect OpenFOAM's dictionary form (OpenFOAM's own files: a `FoamFile { … }` header,
/// `keyword value;` entries, `keyword { … }` sub-dictionaries, C and C++ comments): the header, or
/// at least one `keyword value;` line at the top level. Returns the first entry after the header.
std::optional<FoamEntry> openFoamSyntax(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    int lineNo = 0, depth = 0, headerLine = 0, headerDepth = -1;
    bool inComment = false, header = false, semicolonEntry = false;
    std::optional<FoamEntry> first;
    std::string pendingWord; // a keyword alone on its line: a sub-dictionary if '{' follows
    int pendingLine = 0;
    while (std::getline(in, raw)) {
        ++lineNo;
        // Remove /* … */ (across lines) and // comments.
        std::string line;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (inComment) {
                if (raw.compare(i, 2, "*/") == 0) {
                    inComment = false;
                    ++i;
                }
            } else if (raw.compare(i, 2, "/*") == 0) {
                inComment = true;
                ++i;
            } else if (raw.compare(i, 2, "//") == 0) {
                break;
            } else {
                line += raw[i];
            }
        }
        line = trim(line);
        if (line.empty() || line[0] == '#') continue; // #include, #inputMode, YAML comments
        const bool atTop = depth == 0 && headerDepth < 0;
        // The keyword that starts the line, and what follows it.
        std::size_t w = 0;
        while (w < line.size() && !std::isspace(static_cast<unsigned char>(line[w])) &&
               line[w] != '{' && line[w] != ';')
            ++w;
        const std::string word = line.substr(0, w);
        const std::string rest = trim(line.substr(w));
        if (!pendingWord.empty() && line[0] == '{' && !first) {
            first = FoamEntry{pendingLine, pendingWord, "", true};
        }
        pendingWord.clear();
        if (atTop && word == "FoamFile" && (rest.empty() || rest[0] == '{')) {
            header = true;
            headerLine = lineNo;
            headerDepth = depth;
        } else if (atTop && isKeyword(word) && !first) {
            if (!rest.empty() && rest.back() == ';' && rest.find(':') == std::string::npos &&
                rest.size() > 1) {
                first = FoamEntry{lineNo, word, trim(rest.substr(0, rest.size() - 1)), false};
            } else if (!rest.empty() && rest[0] == '{') {
                first = FoamEntry{lineNo, word, "", true};
            } else if (rest.empty()) {
                pendingWord = word;
                pendingLine = lineNo;
            }
        }
        if (isKeyword(word) && rest.size() > 1 && rest.back() == ';' &&
            rest.find(':') == std::string::npos)
            semicolonEntry = true;
        for (const char c : line) {
            if (c == '{') ++depth;
            if (c == '}') {
                depth = std::max(depth - 1, 0);
                if (depth == headerDepth) headerDepth = -1; // the header's block closed
            }
        }
    }
    if (!header && !semicolonEntry) return std::nullopt;
    if (first) return first;
    return FoamEntry{headerLine, "", "", false};
}

/// An OpenFOAM value in YAML: `(0 0 -9.81)` → `[0, 0, -9.81]`; anything else as written.
std::string yamlValue(const std::string& value) {
    if (value.size() >= 2 && value.front() == '(' && value.back() == ')' &&
        value.find_first_of("()", 1) == value.size() - 1) {
        std::istringstream items(value.substr(1, value.size() - 2));
        std::string item, out;
        while (items >> item)
            out += (out.empty() ? "" : ", ") + item;
        return "[" + out + "]";
    }
    return value;
}

/// The error for a file in OpenFOAM syntax: it names the first entry and its YAML form.
[[noreturn]] void openFoamSyntaxError(const FoamEntry& e, const std::string& file) {
    const std::string yaml =
        "the case files are YAML, not OpenFOAM dictionaries (docs/caseFormat.md): ";
    const std::string rest = "; leave out the FoamFile header and the ';' after each value";
    if (e.key.empty()) {
        throw InputError(file, e.line, "",
                         yaml + "write each entry as 'key: value' (e.g. 'endTime: 0.5')" + rest);
    }
    if (e.block) {
        throw InputError(file, e.line, e.key,
                         yaml + "write the sub-dictionary '" + e.key + " { … }' as '" + e.key +
                             ":' with its entries indented below it, each as 'key: value'" + rest);
    }
    throw InputError(file, e.line, e.key,
                     yaml + "write '" + e.key + " " + e.value + ";' as '" + e.key + ": " +
                         yamlValue(e.value) + "'" + rest);
}
} // namespace

// YAML::Node is a cheap shared handle without a move constructor.
// NOLINTNEXTLINE(performance-unnecessary-value-param)
Dictionary::Dictionary(YAML::Node node, std::string file, std::string path)
    : node_(node), file_(std::move(file)), path_(std::move(path)),
      read_(std::make_shared<std::set<std::string>>()), help_(std::make_shared<KeyHelp>()) {}

Dictionary Dictionary::fromFile(const std::filesystem::path& file, const std::string& displayName) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        throw InputError(displayName, 0, "", "cannot open file");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(displayName, 0, "", "cannot open file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(displayName, 0, "", "cannot open file");
    return fromString(text.str(), displayName);
}

Dictionary Dictionary::fromString(const std::string& text, const std::string& displayName) {
    std::vector<YAML::Node> docs;
    try {
        docs = YAML::LoadAll(text);
    } catch (const YAML::ParserException& e) {
        if (const auto foam = openFoamSyntax(text)) openFoamSyntaxError(*foam, displayName);
        throw InputError(displayName, lineOf(e.mark), "", "YAML syntax error: " + e.msg);
    } catch (const YAML::Exception& e) {
        if (const auto foam = openFoamSyntax(text)) openFoamSyntaxError(*foam, displayName);
        throw InputError(displayName, lineOf(e.mark), "", "YAML error: " + e.msg);
    }
    if (docs.size() > 1) {
        throw InputError(displayName, lineOf(docs[1].Mark()), "",
                         "expected a single YAML document, found " + std::to_string(docs.size()));
    }
    YAML::Node root = docs.empty() ? YAML::Node(YAML::NodeType::Map) : docs.front();
    if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
    if (!root.IsMap()) {
        if (const auto foam = openFoamSyntax(text)) openFoamSyntaxError(*foam, displayName);
        throw InputError(displayName, lineOf(root.Mark()), "",
                         "expected a map of 'key: value' entries at the top level, got " +
                             describe(root));
    }
    validate(root, displayName, "", 0);
    return Dictionary(root, displayName, "");
}

namespace {

/// The value stored under `key` in `map`, or an undefined node; also its key node for positions.
std::pair<YAML::Node, YAML::Node> findEntry(const YAML::Node& map, const std::string& key) {
    for (auto it = map.begin(); it != map.end(); ++it) {
        if (it->first.IsScalar() && it->first.Scalar() == key) return {it->first, it->second};
    }
    return {YAML::Node(YAML::NodeType::Undefined), YAML::Node(YAML::NodeType::Undefined)};
}

} // namespace

bool Dictionary::has(const std::string& key) const {
    read_->insert(key);
    return findEntry(node_, key).second.IsDefined();
}

int Dictionary::line(const std::string& key) const {
    const auto [k, v] = findEntry(node_, key);
    if (!v.IsDefined()) return lineOf(node_.Mark());
    // An empty value is positioned where the parser found the next token; use its key instead.
    if (v.IsNull()) return lineOf(k.Mark());
    return lineOf(v.Mark());
}

void Dictionary::error(const std::string& key, const std::string& message) const {
    throw InputError(file_, line(key), path_.empty() ? key : path_ + "." + key, message);
}

namespace {

std::string lowerCase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// Shared lookup of a required entry: marks it read, errors if absent. A missing key is most
/// often a misspelt one: when the map holds a key not (yet) looked up and not in the model's
/// schema that is close to it (equal but for case, or at most 2 edits away on a key long enough
/// that 2 edits leave most of it), the error is located at that key and names both, e.g.
/// `constant/materials:9: key 'sand.frictionAngel': unknown key; did you mean
/// 'frictionAngle'? (required, missing)`, rather than at the map's first line. This is the one
/// place every required lookup goes through; unknown keys in general are reported by
/// checkUnknownKeys once the model has read what it reads.
YAML::Node required(const Dictionary& dict, const YAML::Node& map, std::set<std::string>& read,
                    const Dictionary::KeyHelp& help, const std::string& key) {
    read.insert(key);
    YAML::Node v = findEntry(map, key).second;
    if (v.IsDefined()) return v;
    const std::string lower = lowerCase(key);
    std::string typo;
    int typoLine = 0;
    int best = std::numeric_limits<int>::max();
    for (auto it = map.begin(); it != map.end(); ++it) {
        const std::string k = it->first.Scalar();
        if (read.count(k) || std::find(help.keys.begin(), help.keys.end(), k) != help.keys.end())
            continue; // a valid key of the model, not a misspelling
        const int d = lowerCase(k) == lower ? 0 : editDistance(k, key);
        const bool close = d == 0 || (d <= 2 && static_cast<int>(key.size()) > 2 * d);
        if (close && d < best) {
            best = d;
            typo = k;
            typoLine = lineOf(it->first.Mark());
        }
    }
    if (!typo.empty()) {
        const std::string& path = dict.path();
        throw InputError(dict.fileName(), typoLine, path.empty() ? typo : path + "." + typo,
                         "unknown key; did you mean '" + key + "'? (required, missing)");
    }
    dict.error(key, "missing required key");
}

double toNumber(const Dictionary& dict, const std::string& key, const YAML::Node& v,
                const std::string& where = "") {
    double value = 0.0;
    if (!v.IsScalar() || !parseNumber(v.Scalar(), value)) {
        dict.error(key, "expected a number" + where + ", got " + describe(v));
    }
    return value;
}

} // namespace

double Dictionary::getScalar(const std::string& key, Bounds bounds) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    const double value = toNumber(*this, key, v);
    if (!inBounds(value, bounds)) {
        error(key, "expected a number in " + formatBounds(bounds) + ", got " + v.Scalar());
    }
    return value;
}

int Dictionary::getInt(const std::string& key, Bounds bounds) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    double value = 0.0;
    if (!v.IsScalar() || !parseNumber(v.Scalar(), value)) {
        error(key, "expected an integer, got " + describe(v));
    }
    if (value != std::floor(value)) error(key, "expected an integer, got " + describe(v));
    if (value < static_cast<double>(std::numeric_limits<int>::min()) ||
        value > static_cast<double>(std::numeric_limits<int>::max())) {
        error(key, "integer out of range, got " + v.Scalar());
    }
    if (!inBounds(value, bounds)) {
        error(key, "expected an integer in " + formatBounds(bounds) + ", got " + v.Scalar());
    }
    return static_cast<int>(value);
}

bool Dictionary::getBool(const std::string& key) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (v.IsScalar()) {
        std::string s = v.Scalar();
        std::transform(s.begin(), s.end(), s.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (s == "yes" || s == "true" || s == "on") return true;
        if (s == "no" || s == "false" || s == "off") return false;
    }
    error(key, "expected yes/no/true/false/on/off, got " + describe(v));
}

std::string Dictionary::getString(const std::string& key) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (!v.IsScalar()) error(key, "expected a string, got " + describe(v));
    return v.Scalar();
}

std::vector<double> Dictionary::getVector(const std::string& key, int size) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    const std::string expected = size >= 0
                                     ? "expected a sequence of " + std::to_string(size) + " numbers"
                                     : std::string("expected a sequence of numbers");
    if (!v.IsSequence()) error(key, expected + ", got " + describe(v));
    if (size >= 0 && v.size() != static_cast<std::size_t>(size)) {
        error(key, expected + ", got " + std::to_string(v.size()));
    }
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        out.push_back(toNumber(*this, key, v[i], " at index " + std::to_string(i)));
    }
    return out;
}

std::vector<std::string> Dictionary::getStringList(const std::string& key) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (!v.IsSequence()) error(key, "expected a sequence of strings, got " + describe(v));
    const std::string base = path_.empty() ? key : path_ + "." + key;
    std::vector<std::string> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!v[i].IsScalar()) {
            throw InputError(file_, lineOf(v[i].Mark()), base + "[" + std::to_string(i) + "]",
                             "expected a string, got " + describe(v[i]));
        }
        out.push_back(v[i].Scalar());
    }
    return out;
}

std::string Dictionary::getWord(const std::string& key,
                                const std::vector<std::string>& choices) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (v.IsScalar() && std::find(choices.begin(), choices.end(), v.Scalar()) != choices.end()) {
        return v.Scalar();
    }
    std::string list;
    for (const auto& c : choices)
        list += (list.empty() ? "" : ", ") + c;
    error(key, "expected one of " + list + "; got " + describe(v));
}

double Dictionary::getScalarOr(const std::string& key, double def, Bounds bounds) const {
    return has(key) ? getScalar(key, bounds) : def;
}

int Dictionary::getIntOr(const std::string& key, int def, Bounds bounds) const {
    return has(key) ? getInt(key, bounds) : def;
}

bool Dictionary::getBoolOr(const std::string& key, bool def) const {
    return has(key) ? getBool(key) : def;
}

std::string Dictionary::getStringOr(const std::string& key, const std::string& def) const {
    return has(key) ? getString(key) : def;
}

std::vector<double> Dictionary::getVectorOr(const std::string& key, const std::vector<double>& def,
                                            int size) const {
    return has(key) ? getVector(key, size) : def;
}

std::string Dictionary::getWordOr(const std::string& key, const std::string& def,
                                  const std::vector<std::string>& choices) const {
    return has(key) ? getWord(key, choices) : def;
}

Dictionary Dictionary::subDict(const std::string& key) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (!v.IsMap()) error(key, "expected a map of 'key: value' entries, got " + describe(v));
    Dictionary d(v, file_, path_.empty() ? key : path_ + "." + key);
    d.base_ = base_;
    return d;
}

std::filesystem::path Dictionary::getPath(const std::string& key) const {
    const std::filesystem::path p(getString(key));
    return p.is_relative() && !base_.empty() ? base_ / p : p;
}

bool Dictionary::isDict(const std::string& key) const {
    read_->insert(key);
    return findEntry(node_, key).second.IsMap();
}

std::vector<Dictionary> Dictionary::dictList(const std::string& key) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (!v.IsSequence()) error(key, "expected a sequence of maps, got " + describe(v));
    const std::string base = path_.empty() ? key : path_ + "." + key;
    std::vector<Dictionary> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string itemPath = base + "[" + std::to_string(i) + "]";
        if (!v[i].IsMap()) {
            throw InputError(file_, lineOf(v[i].Mark()), itemPath,
                             "expected a map of 'key: value' entries, got " + describe(v[i]));
        }
        out.push_back(Dictionary(v[i], file_, itemPath));
        out.back().base_ = base_;
    }
    return out;
}

std::vector<std::vector<double>> Dictionary::vectorList(const std::string& key, int size) const {
    const YAML::Node v = required(*this, node_, *read_, *help_, key);
    if (!v.IsSequence()) error(key, "expected a sequence of sequences, got " + describe(v));
    const std::string base = path_.empty() ? key : path_ + "." + key;
    const std::string expected = size >= 0
                                     ? "expected a sequence of " + std::to_string(size) + " numbers"
                                     : std::string("expected a sequence of numbers");
    std::vector<std::vector<double>> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        const YAML::Node item = v[i];
        const std::string itemPath = base + "[" + std::to_string(i) + "]";
        const int itemLine = lineOf(item.Mark());
        if (!item.IsSequence()) {
            throw InputError(file_, itemLine, itemPath, expected + ", got " + describe(item));
        }
        if (size >= 0 && item.size() != static_cast<std::size_t>(size)) {
            throw InputError(file_, itemLine, itemPath,
                             expected + ", got " + std::to_string(item.size()));
        }
        std::vector<double> row;
        row.reserve(item.size());
        for (std::size_t j = 0; j < item.size(); ++j) {
            double value = 0.0;
            if (!item[j].IsScalar() || !parseNumber(item[j].Scalar(), value)) {
                throw InputError(file_, lineOf(item[j].Mark()), itemPath,
                                 "expected a number at index " + std::to_string(j) + ", got " +
                                     describe(item[j]));
            }
            row.push_back(value);
        }
        out.push_back(std::move(row));
    }
    return out;
}

std::vector<std::string> Dictionary::keys() const {
    std::vector<std::string> out;
    for (auto it = node_.begin(); it != node_.end(); ++it)
        out.push_back(it->first.Scalar());
    return out;
}

void Dictionary::checkUnknownKeys() const {
    for (auto it = node_.begin(); it != node_.end(); ++it) {
        const std::string key = it->first.Scalar();
        if (read_->count(key)) continue;
        const std::string fullKey = path_.empty() ? key : path_ + "." + key;
        const int keyLine = lineOf(it->first.Mark());
        // The model's keys, from its schema: what the message lists.
        std::string help;
        if (!help_->keys.empty()) {
            std::string list;
            for (const auto& k : help_->keys)
                list += (list.empty() ? "" : ", ") + k;
            help = " The keys of " + help_->model + " are: " + list + " (" + help_->more + ")";
        } else if (!help_->model.empty()) {
            help = " The keys of " + help_->model + " are described in " + help_->more + ".";
        }
        std::set<std::string> valid = *read_;
        valid.insert(help_->keys.begin(), help_->keys.end());
        if (valid.empty()) {
            throw InputError(file_, keyLine, fullKey,
                             "unknown key; this dictionary takes no entries." + help);
        }
        const std::string* nearest = nullptr;
        int best = std::numeric_limits<int>::max();
        for (const auto& v : valid) {
            const int d = editDistance(key, v);
            if (d < best) {
                best = d;
                nearest = &v;
            }
        }
        throw InputError(file_, keyLine, fullKey,
                         "unknown key; did you mean '" + *nearest + "'?" + help);
    }
}

int editDistance(const std::string& a, const std::string& b) {
    std::vector<int> prev(b.size() + 1);
    std::vector<int> cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        prev[j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = static_cast<int>(i);
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const int substitution = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, substitution});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

} // namespace mpm
