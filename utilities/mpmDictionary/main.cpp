// SPDX-License-Identifier: GPL-3.0-or-later
// mpmDictionary: query and edit the entries of a case's YAML files (OpenFOAM's foamDictionary).
//
// Reading goes through yaml-cpp. Editing is line-based on block-style YAML, so that comments and
// the layout of every untouched line stay as they were: -set rewrites the value of the entry's
// lines (keeping the comment at the end of its key line), adds missing entries after their
// siblings, -remove deletes the entry's lines. Inside a flow map (`{min: [0, 0], max: [1, 2]}`)
// the flow value is rewritten as a whole. The edited text must parse as a case dictionary
// (Dictionary::fromString: single document, no duplicate keys) and must hold exactly the
// document that the same edit makes on the parsed tree; otherwise the file is not touched. The
// new file replaces the old one by rename (temporary file in the same folder).
#include "case/Dictionary.hpp"
#include "core/Error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace mpm;
namespace fs = std::filesystem;

namespace {

const char* const usageText =
    R"(
Usage: mpmDictionary [OPTIONS] <file>

Print or edit the entries of a YAML case file (OpenFOAM's foamDictionary).
Entries are named by their keys joined with dots: functions.energy.writeInterval.
Edits keep the file's comments and the layout of the lines they do not change;
an edit whose result does not parse is refused and the file left as it was.

options:
  -entry <a.b.c>        the entry to print or edit (without it: the whole file)
  -help                 print this usage and exit
  -keywords             print the keys of the entry (a map), one a line
  -remove               remove the entry
  -set <value>          set the entry to a YAML value (0.2, [0, 0, -9.81],
                        '{type: energy}'), adding it and missing parent maps if absent;
                        a map cannot be set to a scalar or a list
  -value                print the entry's value only

Examples:
  mpmDictionary system/controlDict -entry endTime -value
  mpmDictionary system/controlDict -entry endTime -set 0.2
  mpmDictionary constant/grid -entry bounds.max -set '[1, 1, 0.5]'
  mpmDictionary system/controlDict -entry functions -keywords
  mpmDictionary system/controlDict -entry functions.energy -remove

)";

using Path = std::vector<std::string>;

std::string join(const Path& path, std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n && i < path.size(); ++i)
        s += (i ? "." : "") + path[i];
    return s;
}

std::string describe(const YAML::Node& n) {
    switch (n.Type()) {
    case YAML::NodeType::Map:
        return "a map";
    case YAML::NodeType::Sequence:
        return "a list";
    case YAML::NodeType::Scalar:
        return "a scalar ('" + n.Scalar() + "')";
    default:
        return "empty";
    }
}

int lineOf(const YAML::Mark& m) {
    return m.is_null() ? 0 : m.line + 1;
}

/// The value of `key` in `map` (a map), or an undefined node.
YAML::Node findKey(const YAML::Node& map, const std::string& key) {
    for (auto it = map.begin(); it != map.end(); ++it)
        if (it->first.IsScalar() && it->first.Scalar() == key) return it->second;
    return YAML::Node(YAML::NodeType::Undefined);
}

std::vector<std::string> keysOf(const YAML::Node& map) {
    std::vector<std::string> keys;
    for (auto it = map.begin(); it != map.end(); ++it)
        keys.push_back(it->first.Scalar());
    return keys;
}

/// Deep equality of two documents: scalars by text, maps by key (in any order), lists by item.
bool same(const YAML::Node& a, const YAML::Node& b) {
    if (a.Type() != b.Type()) return false;
    if (a.IsScalar()) return a.Scalar() == b.Scalar();
    if (a.IsSequence()) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!same(a[i], b[i])) return false;
        return true;
    }
    if (a.IsMap()) {
        if (a.size() != b.size()) return false;
        for (auto it = a.begin(); it != a.end(); ++it) {
            const YAML::Node other = findKey(b, it->first.Scalar());
            if (!other.IsDefined() || !same(it->second, other)) return false;
        }
    }
    return true;
}

void setFlowStyle(YAML::Node n) {
    if (n.IsMap()) {
        n.SetStyle(YAML::EmitterStyle::Flow);
        for (auto it = n.begin(); it != n.end(); ++it)
            setFlowStyle(it->second);
    } else if (n.IsSequence()) {
        n.SetStyle(YAML::EmitterStyle::Flow);
        for (auto it = n.begin(); it != n.end(); ++it)
            setFlowStyle(*it);
    }
}

/// `n` on one line in flow style: `{min: [0, 0], max: [1, 2]}`.
std::string flowText(const YAML::Node& n) {
    YAML::Node copy = YAML::Clone(n);
    setFlowStyle(copy);
    YAML::Emitter out;
    out << copy;
    return out.c_str();
}

/// Set (value defined) or remove (value undefined) `path` below `root`, making missing parent
/// maps; `root` is changed in place.
void applyEdit(YAML::Node root, const Path& path, const YAML::Node& value) {
    YAML::Node cur;
    cur.reset(root);
    for (std::size_t d = 0; d + 1 < path.size(); ++d) {
        YAML::Node next = findKey(cur, path[d]);
        if (!next.IsDefined()) {
            cur[path[d]] = YAML::Node(YAML::NodeType::Map);
            next.reset(findKey(cur, path[d]));
        } else if (!next.IsMap()) {
            next = YAML::Node(YAML::NodeType::Map); // null → empty map (assigned in place)
        }
        cur.reset(next);
    }
    if (value.IsDefined())
        cur[path.back()] = YAML::Clone(value);
    else
        cur.remove(path.back());
}

// ------------------------------------------------------------------------------------------
// The file as lines, and the block structure of its maps.

struct Text {
    std::vector<std::string> lines; ///< without line ends
    std::string eol = "\n";
    bool finalEol = true;

    static Text split(const std::string& s) {
        Text t;
        std::size_t pos = 0;
        while (pos < s.size()) {
            const std::size_t nl = s.find('\n', pos);
            if (nl == std::string::npos) {
                t.lines.push_back(s.substr(pos));
                t.finalEol = false;
                break;
            }
            t.lines.push_back(s.substr(pos, nl - pos));
            pos = nl + 1;
        }
        if (!t.lines.empty() && !t.lines.front().empty() && t.lines.front().back() == '\r')
            t.eol = "\r\n";
        if (t.eol == "\r\n")
            for (std::string& l : t.lines)
                if (!l.empty() && l.back() == '\r') l.pop_back();
        return t;
    }
    std::string str() const {
        std::string s;
        for (std::size_t i = 0; i < lines.size(); ++i)
            s += lines[i] + (i + 1 < lines.size() || finalEol ? eol : "");
        return s;
    }
};

std::size_t indentOf(const std::string& line) {
    std::size_t i = 0;
    while (i < line.size() && line[i] == ' ')
        ++i;
    return i;
}

/// A line that carries YAML content: not blank, not only a comment, not a document marker.
bool isContent(const std::string& line) {
    const std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] == '#') return false;
    if (i == 0 && (line.compare(0, 3, "---") == 0 || line.compare(0, 3, "...") == 0) &&
        (line.size() == 3 || line[3] == ' ' || line[3] == '\t'))
        return false;
    return !(i == 0 && line[0] == '%');
}

bool isSequenceItem(const std::string& line) {
    const std::size_t i = indentOf(line);
    return i < line.size() && line[i] == '-' &&
           (i + 1 == line.size() || line[i + 1] == ' ' || line[i + 1] == '\t');
}

/// A `key: value  # comment` line of a block map, split into its parts (columns).
struct KeyLine {
    bool isKey = false;
    std::size_t indent = 0;
    std::string key;
    std::size_t colon = 0;                    ///< column of the ':'
    std::size_t valueBegin = 0, valueEnd = 0; ///< the value on this line (may be empty)
    std::size_t comment = std::string::npos;  ///< column of the comment's '#'
    std::string value(const std::string& line) const {
        return line.substr(valueBegin, valueEnd - valueBegin);
    }
};

KeyLine scanKey(const std::string& line) {
    KeyLine k;
    k.indent = indentOf(line);
    std::size_t i = k.indent;
    if (!isContent(line) || isSequenceItem(line)) return k;
    const char first = line[i];
    if (first == '"' || first == '\'') {
        std::string key;
        std::size_t j = i + 1;
        for (; j < line.size(); ++j) {
            if (line[j] == first) {
                if (first == '\'' && j + 1 < line.size() && line[j + 1] == '\'') {
                    key += '\'';
                    ++j;
                    continue;
                }
                break;
            }
            if (first == '"' && line[j] == '\\' && j + 1 < line.size()) ++j;
            key += line[j];
        }
        if (j >= line.size()) return k;
        j = line.find_first_not_of(" \t", j + 1);
        if (j == std::string::npos || line[j] != ':') return k;
        k.key = key;
        k.colon = j;
    } else {
        if (std::string("[]{},?&*!|>%@`#").find(first) != std::string::npos) return k;
        std::size_t j = i;
        for (; j < line.size(); ++j) {
            if (line[j] == '#' && (line[j - 1] == ' ' || line[j - 1] == '\t')) return k;
            if (line[j] == ':' &&
                (j + 1 == line.size() || line[j + 1] == ' ' || line[j + 1] == '\t'))
                break;
        }
        if (j >= line.size()) return k;
        std::size_t e = j;
        while (e > i && (line[e - 1] == ' ' || line[e - 1] == '\t'))
            --e;
        k.key = line.substr(i, e - i);
        k.colon = j;
    }
    k.isKey = true;
    // The value: to the first '#' that follows a blank outside quotes.
    std::size_t v = line.find_first_not_of(" \t", k.colon + 1);
    if (v == std::string::npos) {
        k.valueBegin = k.valueEnd = line.size();
        return k;
    }
    k.valueBegin = v;
    char quote = 0;
    char previous = ' '; // the last character outside quotes that is not a blank
    for (std::size_t j = v; j < line.size(); ++j) {
        const char c = line[j];
        if (quote) {
            if (quote == '"' && c == '\\') {
                ++j;
            } else if (c == quote) {
                if (quote == '\'' && j + 1 < line.size() && line[j + 1] == '\'')
                    ++j;
                else
                    quote = 0;
            }
            continue;
        }
        if (c == '#' && (j == v || line[j - 1] == ' ' || line[j - 1] == '\t')) {
            k.comment = j;
            break;
        }
        if ((c == '"' || c == '\'') && std::string(" [{,:").find(previous) != std::string::npos &&
            (j == v || line[j - 1] == ' ' || line[j - 1] == '\t' || line[j - 1] == '[' ||
             line[j - 1] == '{' || line[j - 1] == ','))
            quote = c;
        if (c != ' ' && c != '\t') previous = c;
    }
    std::size_t e = k.comment == std::string::npos ? line.size() : k.comment;
    while (e > v && (line[e - 1] == ' ' || line[e - 1] == '\t'))
        --e;
    k.valueEnd = e;
    return k;
}

/// True when the value on a key line is only a header of what follows on the next lines:
/// nothing, an anchor (&a) or a tag (!t).
bool valueOnNextLines(const std::string& value) {
    std::istringstream words(value);
    std::string w;
    while (words >> w)
        if (w[0] != '&' && w[0] != '!') return false;
    return true;
}

/// One entry of a block map: its key line and the last content line of its value.
struct Entry {
    std::size_t line = 0, last = 0;
    KeyLine key;
};

Entry entryAt(const Text& t, std::size_t k) {
    Entry e;
    e.line = e.last = k;
    e.key = scanKey(t.lines[k]);
    const bool emptyValue = e.key.valueBegin == e.key.valueEnd;
    for (std::size_t j = k + 1; j < t.lines.size(); ++j) {
        const std::string& l = t.lines[j];
        if (!isContent(l)) continue;
        const std::size_t ind = indentOf(l);
        if (ind > e.key.indent || (ind == e.key.indent && emptyValue && isSequenceItem(l)))
            e.last = j;
        else
            break;
    }
    return e;
}

/// Thrown when the layout is beyond a line edit; the file is left alone.
struct Unsupported : std::runtime_error {
    int line;
    Unsupported(int l, const std::string& what) : std::runtime_error(what), line(l) {}
};

/// The entries of the block map whose lines are [begin, end): those at the indentation of its
/// first content line. `indent` gets that indentation (unchanged when the range is empty).
std::vector<Entry> children(const Text& t, std::size_t begin, std::size_t end,
                            std::size_t& indent) {
    std::vector<Entry> out;
    std::size_t j = begin;
    while (j < end && !isContent(t.lines[j]))
        ++j;
    if (j >= end) return out;
    indent = indentOf(t.lines[j]);
    while (j < end) {
        const std::string& l = t.lines[j];
        if (!isContent(l)) {
            ++j;
            continue;
        }
        const KeyLine k = scanKey(l);
        if (indentOf(l) != indent || !k.isKey)
            throw Unsupported(static_cast<int>(j + 1),
                              "this line is not a 'key: value' line of a block map");
        out.push_back(entryAt(t, j));
        j = out.back().last + 1;
    }
    return out;
}

/// The indentation step of the file's nested maps (2 if it has none).
std::size_t indentStep(const Text& t) {
    for (std::size_t k = 0; k < t.lines.size(); ++k) {
        const KeyLine key = scanKey(t.lines[k]);
        if (!key.isKey || key.valueBegin != key.valueEnd) continue;
        for (std::size_t j = k + 1; j < t.lines.size(); ++j) {
            if (!isContent(t.lines[j])) continue;
            const std::size_t ind = indentOf(t.lines[j]);
            if (ind > key.indent) return ind - key.indent;
            break;
        }
    }
    return 2;
}

/// `line` with its value (columns [valueBegin, valueEnd)) replaced by `value`; a comment at
/// the end of the line keeps its column where there is room.
std::string replaceValue(const std::string& line, const KeyLine& k, const std::string& value) {
    std::string out = line.substr(0, k.colon + 1);
    if (!value.empty())
        out = (k.valueBegin < k.valueEnd ? line.substr(0, k.valueBegin) : out + " ") + value;
    if (k.comment != std::string::npos) {
        const std::size_t pad = k.comment > out.size() ? k.comment - out.size() : 1;
        out += std::string(std::max<std::size_t>(pad, 1), ' ') + line.substr(k.comment);
    }
    return out;
}

/// The lines of a multi-line block value, re-indented to `indent`.
std::vector<std::string> blockLines(const std::string& text, std::size_t indent) {
    std::vector<std::string> lines = Text::split(text).lines;
    while (!lines.empty() && lines.back().find_first_not_of(" \t\r") == std::string::npos)
        lines.pop_back();
    std::size_t common = std::string::npos;
    for (const std::string& l : lines)
        if (l.find_first_not_of(" \t\r") != std::string::npos)
            common = std::min(common, indentOf(l));
    for (std::string& l : lines) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        l = l.find_first_not_of(" \t") == std::string::npos
                ? std::string()
                : std::string(indent, ' ') + l.substr(common);
    }
    return lines;
}

struct Request {
    std::string file;
    Path entry;
    bool set = false, remove = false;
    std::string valueText; ///< -set's argument
    YAML::Node value;      ///< its parsed value
};

/// The edited text: `doc` is the parsed file (for flow values), `request` the edit.
std::string editText(const Text& original, const YAML::Node& doc, const Request& r) {
    Text t = original;
    const Path& p = r.entry;
    const std::size_t step = indentStep(t);

    // How the new value goes onto a line, or under its key as a block.
    const bool multiLine = r.set && r.valueText.find('\n') != std::string::npos;
    const bool blockValue = multiLine && (r.value.IsMap() || r.value.IsSequence()) &&
                            r.value.Style() != YAML::EmitterStyle::Flow;
    std::string inlineValue;
    if (r.set && !blockValue) {
        const bool blockCollection = (r.value.IsMap() || r.value.IsSequence()) &&
                                     r.value.Style() != YAML::EmitterStyle::Flow;
        if (!multiLine && !blockCollection) {
            inlineValue = r.valueText;
            const std::size_t a = inlineValue.find_first_not_of(" \t");
            const std::size_t b = inlineValue.find_last_not_of(" \t\r");
            inlineValue = a == std::string::npos ? "" : inlineValue.substr(a, b - a + 1);
        } else {
            inlineValue = r.value.IsNull() ? "" : flowText(r.value);
        }
        if (inlineValue.find('\n') != std::string::npos)
            throw Unsupported(0, "the value cannot be written on one line");
    }

    std::size_t begin = 0, end = t.lines.size(); // the lines of the current block map
    std::size_t childIndent = 0;
    std::optional<Entry> parent; // the entry whose value is [begin, end), none at the top
    YAML::Node node = doc;       // the parsed value of the current map
    for (std::size_t d = 0; d < p.size(); ++d) {
        std::size_t indent = parent ? parent->key.indent + step : 0;
        const std::vector<Entry> entries = children(t, begin, end, indent);
        childIndent = indent;
        const Entry* found = nullptr;
        for (const Entry& e : entries) {
            if (e.key.key != p[d]) continue;
            if (found)
                throw Unsupported(static_cast<int>(e.line + 1),
                                  "duplicate key '" + p[d] + "' (also on line " +
                                      std::to_string(found->line + 1) + ")");
            found = &e;
        }

        if (!found) { // absent: only -set gets here; add it and its missing parents
            std::vector<std::string> added;
            std::size_t ind = childIndent;
            for (std::size_t k = d; k < p.size(); ++k, ind += step) {
                const std::string pad(ind, ' ');
                if (k + 1 < p.size())
                    added.push_back(pad + p[k] + ":");
                else if (blockValue) {
                    added.push_back(pad + p[k] + ":");
                    for (std::string& l : blockLines(r.valueText, ind + step))
                        added.push_back(std::move(l));
                } else {
                    added.push_back(pad + p[k] + ":" + (inlineValue.empty() ? "" : " ") +
                                    inlineValue);
                }
            }
            std::size_t at = parent ? parent->line + 1 : 0;
            for (const Entry& e : entries)
                at = std::max(at, e.last + 1);
            if (entries.empty() && !parent) // an empty file: after its comments
                at = t.lines.size();
            for (std::string& l : added)
                l = l.substr(0, l.find_last_not_of(' ') + 1);
            t.lines.insert(t.lines.begin() + static_cast<std::ptrdiff_t>(at), added.begin(),
                           added.end());
            return t.str();
        }

        const Entry e = *found;
        const std::string& keyLine = t.lines[e.line];
        const std::string inlineText = e.key.value(keyLine);
        const YAML::Node value = findKey(node, p[d]);
        const auto erase = [&](std::size_t from, std::size_t to) { // [from, to]
            if (from <= to)
                t.lines.erase(t.lines.begin() + static_cast<std::ptrdiff_t>(from),
                              t.lines.begin() + static_cast<std::ptrdiff_t>(to) + 1);
        };

        if (d + 1 == p.size()) { // the entry itself
            if (r.remove) {
                erase(e.line, e.last);
                if (parent && entries.size() == 1) // the map is now empty: {}
                    t.lines[parent->line] = replaceValue(t.lines[parent->line], parent->key, "{}");
                return t.str();
            }
            if (blockValue) {
                const std::vector<std::string> body = blockLines(r.valueText, e.key.indent + step);
                std::string head = replaceValue(keyLine, e.key, "");
                erase(e.line + 1, e.last);
                t.lines[e.line] = head;
                t.lines.insert(t.lines.begin() + static_cast<std::ptrdiff_t>(e.line) + 1,
                               body.begin(), body.end());
            } else {
                std::string line = replaceValue(keyLine, e.key, inlineValue);
                erase(e.line + 1, e.last);
                t.lines[e.line] = line;
            }
            return t.str();
        }

        if (!valueOnNextLines(inlineText) || value.IsSequence()) {
            // A flow value (or a scalar) on the key line: rewrite it as a whole.
            for (std::size_t j = e.line + 1; j <= e.last; ++j) // the value goes on one line
                if (t.lines[j].find('#') != std::string::npos)
                    throw Unsupported(static_cast<int>(j + 1),
                                      "the flow value of '" + join(p, d + 1) +
                                          "' spans several lines and has comments in them");
            YAML::Node edited =
                value.IsMap() ? YAML::Clone(value) : YAML::Node(YAML::NodeType::Map);
            const Path rest(p.begin() + static_cast<std::ptrdiff_t>(d) + 1, p.end());
            applyEdit(edited, rest, r.set ? r.value : YAML::Node(YAML::NodeType::Undefined));
            t.lines[e.line] = replaceValue(keyLine, e.key, flowText(edited));
            erase(e.line + 1, e.last);
            return t.str();
        }
        // A block map below the key line (or nothing yet): go down.
        parent = e;
        begin = e.line + 1;
        end = e.last + 1;
        node.reset(value);
    }
    return t.str();
}

// ------------------------------------------------------------------------------------------

std::string readFile(const std::string& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw InputError(file, 0, "", "no such file");
    if (!fs::is_regular_file(file, ec)) throw InputError(file, 0, "", "not a regular file");
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw InputError(file, 0, "", "cannot read the file");
    return text.str();
}

/// Replace `file` by `text`: a temporary file beside it (its permissions), then rename.
void writeAtomic(const std::string& file, const std::string& text) {
    const fs::path target = fs::canonical(file); // through a link: edit the file it names
    struct stat st {};
    if (::stat(target.c_str(), &st) != 0)
        throw InputError(file, 0, "", std::string("cannot stat: ") + std::strerror(errno));
    std::string tmp =
        (target.parent_path() / ("." + target.filename().string() + ".mpmDictionary-XXXXXX"))
            .string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0)
        throw InputError(file, 0, "",
                         std::string("cannot write a temporary file beside it: ") +
                             std::strerror(errno));
    bool ok = ::fchmod(fd, st.st_mode & 07777) == 0;
    std::size_t done = 0;
    while (ok && done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        ok = n > 0;
        if (ok) done += static_cast<std::size_t>(n);
    }
    ok = ok && ::fsync(fd) == 0;
    const int error = errno;
    ok = ::close(fd) == 0 && ok;
    if (!ok || ::rename(tmp.c_str(), target.c_str()) != 0) {
        const int e = ok ? errno : error;
        ::unlink(tmp.c_str());
        throw InputError(file, 0, "",
                         std::string("cannot write: ") + std::strerror(e) +
                             " (the file is unchanged)");
    }
}

Path splitEntry(const std::string& text) {
    Path p;
    std::size_t pos = 0;
    while (true) {
        const std::size_t dot = text.find('.', pos);
        p.push_back(text.substr(pos, dot == std::string::npos ? std::string::npos : dot - pos));
        if (p.back().empty())
            throw std::runtime_error("-entry '" + text +
                                     "': empty key (keys are joined by single dots: a.b.c)");
        if (dot == std::string::npos) break;
        pos = dot + 1;
    }
    return p;
}

YAML::Node parsed(const std::string& text, const std::string& file) {
    Dictionary::fromString(text, file); // the rules of a case file (one map, no duplicates, ...)
    const YAML::Node doc = YAML::Load(text);
    return doc.IsNull() ? YAML::Node(YAML::NodeType::Map) : doc;
}

int run(int argc, char* argv[]) {
    Request r;
    std::string entryText;
    bool printValue = false, keywords = false, haveEntry = false;
    std::vector<std::string> positional;
    std::string bad;
    int actions = 0;
    for (int i = 1; i < argc && bad.empty(); ++i) {
        const std::string a = argv[i];
        if (a == "-help" || a == "--help" || a == "-h") {
            std::cout << usageText;
            return 0;
        }
        if (a == "-entry" || a == "-set") {
            if (i + 1 >= argc) {
                bad = a + " needs a value";
                break;
            }
            if (a == "-entry") {
                entryText = argv[++i];
                haveEntry = true;
            } else {
                r.valueText = argv[++i];
                r.set = true;
                ++actions;
            }
        } else if (a == "-value") {
            printValue = true;
            ++actions;
        } else if (a == "-remove") {
            r.remove = true;
            ++actions;
        } else if (a == "-keywords") {
            keywords = true;
            ++actions;
        } else if (a.size() > 1 && a[0] == '-') {
            bad = "Invalid option: " + a;
        } else {
            positional.push_back(a);
        }
    }
    if (bad.empty() && positional.size() != 1)
        bad = "expected one file, got " + std::to_string(positional.size());
    if (bad.empty() && actions > 1) bad = "-value, -set, -remove and -keywords exclude each other";
    if (bad.empty() && !haveEntry && (r.set || r.remove || printValue))
        bad = std::string(r.set ? "-set" : r.remove ? "-remove" : "-value") + " needs -entry";
    if (!bad.empty()) {
        std::cerr << "\n--> MPMFOAM FATAL ERROR: " << escapeBytes(bad) << '\n' << usageText;
        return 1;
    }
    r.file = positional.front();
    if (haveEntry) r.entry = splitEntry(entryText);

    const std::string original = readFile(r.file);
    const YAML::Node doc = parsed(original, r.file);

    // Walk to the entry on the parsed tree: its value, or how much of the path exists.
    YAML::Node node = doc;
    std::size_t depth = 0;
    for (; depth < r.entry.size(); ++depth) {
        const std::string& key = r.entry[depth];
        if (node.IsSequence() && !r.set && !r.remove &&
            key.find_first_not_of("0123456789") == std::string::npos &&
            std::strtoul(key.c_str(), nullptr, 10) < node.size()) {
            node.reset(node[std::strtoul(key.c_str(), nullptr, 10)]);
            continue;
        }
        if (!node.IsMap()) {
            if (r.set && node.IsNull()) break; // an empty value becomes a map
            throw InputError(
                r.file, lineOf(node.Mark()), entryText,
                "'" + join(r.entry, depth) + "' is " + describe(node) +
                    ", not a map: it has no entry '" + key + "'" +
                    (node.IsSequence() ? " (a list is set or printed as a whole)" : ""));
        }
        const YAML::Node next = findKey(node, key);
        if (!next.IsDefined()) {
            if (r.set) break;
            std::string message =
                "no such entry: " +
                (depth ? "'" + join(r.entry, depth) + "'" : std::string("the file")) +
                " has no key '" + key + "'";
            const std::vector<std::string> keys = keysOf(node);
            const std::string* nearest = nullptr;
            int best = 3;
            for (const std::string& k : keys) {
                const int dist = editDistance(key, k);
                if (dist < best) {
                    best = dist;
                    nearest = &k;
                }
            }
            if (nearest) message += "; did you mean '" + *nearest + "'?";
            std::string list;
            for (const std::string& k : keys)
                list += (list.empty() ? "" : ", ") + k;
            message += " (keys: " + (list.empty() ? std::string("none") : list) + ")";
            throw InputError(r.file, depth ? lineOf(node.Mark()) : 0, entryText, message);
        }
        node.reset(next);
    }

    if (!r.set && !r.remove) { // print
        if (keywords) {
            if (!node.IsMap())
                throw InputError(r.file, lineOf(node.Mark()), entryText,
                                 "-keywords: the entry is " + describe(node) + ", not a map");
            for (const std::string& k : keysOf(node))
                std::cout << k << '\n';
        } else if (printValue) {
            if (node.IsScalar()) {
                std::cout << node.Scalar() << '\n';
            } else {
                YAML::Emitter out;
                out << node;
                std::cout << out.c_str() << '\n';
            }
        } else {
            YAML::Emitter out;
            if (r.entry.empty())
                out << node;
            else
                out << YAML::BeginMap << YAML::Key << r.entry.back() << YAML::Value << node
                    << YAML::EndMap;
            std::cout << out.c_str() << '\n';
        }
        return 0;
    }

    if (r.set) {
        try {
            r.value = YAML::Load(r.valueText);
        } catch (const YAML::Exception& e) {
            throw InputError(r.file, 0, entryText,
                             "-set: the value '" + r.valueText + "' is not YAML: " + e.msg +
                                 "; the file is unchanged");
        }
        if (depth == r.entry.size() && node.IsMap() && !r.value.IsMap())
            throw InputError(r.file, lineOf(node.Mark()), entryText,
                             "the entry is a map; setting it to " + describe(r.value) +
                                 " would change its type (remove it first if that is meant); "
                                 "the file is unchanged");
    }

    // The document the edit must give, and the edited text.
    YAML::Node expected = YAML::Clone(doc);
    applyEdit(expected, r.entry, r.set ? r.value : YAML::Node(YAML::NodeType::Undefined));
    std::string edited;
    try {
        edited = editText(Text::split(original), doc, r);
    } catch (const Unsupported& e) {
        throw InputError(r.file, e.line, entryText,
                         std::string(e.what()) +
                             ": mpmDictionary edits block-style maps line by line and cannot "
                             "make this edit; the file is unchanged (edit it by hand)");
    }
    YAML::Node result;
    try {
        result = parsed(edited, r.file + " (as edited)");
    } catch (const InputError& e) {
        throw InputError(r.file, 0, entryText,
                         std::string("the edit would leave the file unreadable (") + e.what() +
                             "); the file is unchanged");
    }
    if (!same(result, expected))
        throw InputError(r.file, 0, entryText,
                         "the line edit would not give the intended document (an unusual layout?); "
                         "the file is unchanged (edit it by hand)");
    if (edited != original) writeAtomic(r.file, edited);
    return 0;
}

} // namespace

int main(int argc, char* argv[]) {
    return mpm::reportingErrors([&] { return run(argc, argv); });
}
