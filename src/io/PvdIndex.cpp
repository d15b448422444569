// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/PvdIndex.hpp"

#include "core/Format.hpp"
#include "io/ParticleFile.hpp"
#include "io/XmlFile.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

namespace mpm::io {

namespace {

std::string unescapeXml(const std::string& text) {
    static const std::pair<const char*, char> entities[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        bool replaced = false;
        if (text[i] == '&') {
            for (const auto& [entity, c] : entities) {
                const std::size_t len = std::char_traits<char>::length(entity);
                if (text.compare(i, len, entity) == 0) {
                    out += c;
                    i += len;
                    replaced = true;
                    break;
                }
            }
        }
        if (!replaced) {
            out += text[i++];
        }
    }
    return out;
}

/// Value of attribute `name` inside one element's text `tag` (between `<` and `>`).
bool attribute(const std::string& tag, const std::string& name, std::string& value) {
    std::size_t pos = 0;
    while ((pos = tag.find(name, pos)) != std::string::npos) {
        const bool startsWord = pos > 0 && (tag[pos - 1] == ' ' || tag[pos - 1] == '\t' ||
                                            tag[pos - 1] == '\n' || tag[pos - 1] == '\r');
        std::size_t p = pos + name.size();
        pos = p;
        if (!startsWord) {
            continue;
        }
        while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) {
            ++p;
        }
        if (p >= tag.size() || tag[p] != '=') {
            continue;
        }
        ++p;
        while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) {
            ++p;
        }
        if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) {
            continue;
        }
        const char quote = tag[p++];
        const std::size_t end = tag.find(quote, p);
        if (end == std::string::npos) {
            return false;
        }
        value = unescapeXml(tag.substr(p, end - p));
        return true;
    }
    return false;
}

bool parseTime(const std::string& text, double& time) {
    const char* first = text.data();
    const char* last = text.data() + text.size();
    while (first < last && std::isspace(static_cast<unsigned char>(*first))) {
        ++first;
    }
    while (last > first && std::isspace(static_cast<unsigned char>(last[-1]))) {
        --last;
    }
    if (first < last && *first == '+') {
        ++first;
    }
    const auto result = std::from_chars(first, last, time);
    return result.ec == std::errc() && result.ptr == last && std::isfinite(time);
}

/// Every well-formed `<DataSet .../>` of `text`; anything else is ignored.
std::vector<PvdIndex::Entry> parseEntries(const std::string& text) {
    std::vector<PvdIndex::Entry> entries;
    std::size_t pos = 0;
    while ((pos = text.find("<DataSet", pos)) != std::string::npos) {
        const std::size_t end = text.find('>', pos);
        if (end == std::string::npos) {
            break;
        }
        const std::string tag = text.substr(pos, end - pos);
        pos = end;
        std::string timeText;
        std::string fileText;
        double time = 0;
        if (attribute(tag, "timestep", timeText) && attribute(tag, "file", fileText) &&
            !fileText.empty() && parseTime(timeText, time)) {
            entries.push_back({time, fileText});
        }
    }
    return entries;
}

} // namespace

PvdIndex::PvdIndex(std::filesystem::path file, double keepUpTo) : file_(std::move(file)) {
    std::ifstream in(file_, std::ios::binary);
    if (!in) {
        return;
    }
    std::ostringstream text;
    text << in.rdbuf();
    bool dropped = false;
    for (Entry& e : parseEntries(text.str())) {
        if (e.time > keepUpTo) {
            dropped = true;
            continue;
        }
        auto it = std::lower_bound(entries_.begin(), entries_.end(), e.time,
                                   [](const Entry& a, double t) { return a.time < t; });
        if (it != entries_.end() && it->time == e.time) {
            dropped = true;
            *it = std::move(e);
        } else {
            entries_.insert(it, std::move(e));
        }
    }
    if (dropped) {
        write();
    }
}

void PvdIndex::add(double time, const std::string& relativeFile) {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), time,
                               [](const Entry& a, double t) { return a.time < t; });
    if (it != entries_.end() && it->time == time) {
        it->file = relativeFile;
    } else {
        entries_.insert(it, Entry{time, relativeFile});
    }
    write();
}

void PvdIndex::remove(const std::string& relativeFile) {
    std::string dir = relativeFile;
    while (!dir.empty() && dir.back() == '/') {
        dir.pop_back();
    }
    dir += '/';
    const auto matches = [&](const Entry& e) {
        return e.file == relativeFile || e.file.compare(0, dir.size(), dir) == 0;
    };
    const auto first = std::remove_if(entries_.begin(), entries_.end(), matches);
    if (first == entries_.end()) {
        return;
    }
    entries_.erase(first, entries_.end());
    write();
}

void PvdIndex::write() const {
    std::string text = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"Collection\" version=\"0.1\" "
                       "byte_order=\"LittleEndian\">\n"
                       "  <Collection>\n";
    for (const Entry& e : entries_) {
        text += "    <DataSet timestep=\"" + fullPrecision(e.time) +
                "\" group=\"\" part=\"0\" file=\"" + escapeXml(e.file) + "\"/>\n";
    }
    text += "  </Collection>\n"
            "</VTKFile>\n";
    writeTextAtomic(file_, text);
}

} // namespace mpm::io
