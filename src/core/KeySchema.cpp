// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/KeySchema.hpp"

#include <algorithm>
#include <stdexcept>

namespace mpm {

KeyList operator+(KeyList a, const KeyList& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

std::map<std::string, ModelCatalogue::Family>& ModelCatalogue::table() {
    static std::map<std::string, Family> t;
    return t;
}

ModelCatalogue::AddFamily::AddFamily(const std::string& name, FamilyInfo info) {
    Family& f = table()[name];
    f.name = name;
    f.info = std::move(info);
}

ModelCatalogue::AddTypes::AddTypes(const std::string& family, int dim, Lister list)
    : AddTypes(family, dim, Registered{std::move(list), {}, {}}) {}

ModelCatalogue::AddTypes::AddTypes(const std::string& family, int dim, Registered registry) {
    Family& f = table()[family];
    f.name = family;
    f.registries.emplace_back(dim, std::move(registry));
}

ModelCatalogue::AddSchema::AddSchema(const std::string& family, const std::string& type,
                                     TypeSchema schema) {
    Family& f = table()[family];
    f.name = family;
    f.schemas[type] = std::move(schema);
}

std::vector<const ModelCatalogue::Family*> ModelCatalogue::families() {
    std::vector<const Family*> all;
    for (const auto& [name, f] : table())
        all.push_back(&f);
    // The order of docs/caseFormat.md: by section ("2. system/controlDict" < "3. …"), then name.
    std::stable_sort(all.begin(), all.end(), [](const Family* a, const Family* b) {
        return a->info.docSection < b->info.docSection;
    });
    return all;
}

const ModelCatalogue::Family* ModelCatalogue::find(const std::string& name) {
    const auto it = table().find(name);
    return it == table().end() ? nullptr : &it->second;
}

std::map<std::string, std::set<int>> ModelCatalogue::types(const Family& family) {
    std::map<std::string, std::set<int>> out;
    for (const auto& [dim, r] : family.registries)
        for (const std::string& type : r.types())
            out[type].insert(dim);
    return out;
}

namespace {

/// The names `list` gives (none for an empty Lister).
std::vector<std::string> names(const ModelCatalogue::Lister& list) {
    return list ? list() : std::vector<std::string>{};
}

bool contains(const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

} // namespace

int ModelCatalogue::onlyDim(const Family& family, const std::string& type) {
    for (const auto& [dim, r] : family.registries)
        if (contains(names(r.refused), type))
            for (const auto& [other, o] : family.registries)
                if (other != dim && contains(names(o.types), type)) return other;
    return 0;
}

std::string ModelCatalogue::refusal(const std::string& family, const std::string& type,
                                    int onlyDim) {
    std::string message = "'" + type + "' is " + std::to_string(onlyDim) + "D only (this case is " +
                          std::to_string(5 - onlyDim) + "D)";
    if (const Family* f = find(family))
        if (const auto it = f->schemas.find(type);
            it != f->schemas.end() && !it->second.hint.empty())
            message += "; " + it->second.hint;
    return message;
}

std::vector<std::string> ModelCatalogue::problems(const Family& family) {
    std::vector<std::string> out;
    const std::string where = "family '" + family.name + "': ";
    for (const auto& [dim, r] : family.registries) {
        const std::string d = std::to_string(dim) + "D";
        for (const std::string& type : names(r.duplicates))
            out.push_back(where + "'" + type + "' is registered twice in " + d);
        for (const std::string& type : names(r.refused)) {
            bool built = false;
            for (const auto& [other, o] : family.registries)
                built = built || (other != dim && contains(names(o.types), type));
            if (!built)
                out.push_back(where + "'" + type + "' is refused in " + d +
                              " but no other dimension builds it");
        }
        for (const std::string& type : names(r.types))
            for (const auto& [other, o] : family.registries)
                if (other != dim && !contains(names(o.types), type) &&
                    !contains(names(o.refused), type))
                    out.push_back(where + "'" + type + "' is built in " + d + " but " +
                                  std::to_string(other) +
                                  "D neither builds nor refuses it (MPM_REGISTER_ONLY)");
    }
    for (const auto& [type, schema] : family.schemas)
        if (!schema.hint.empty() && onlyDim(family, type) == 0)
            out.push_back(where + "the schema of '" + type +
                          "' has a hint but the type has no dimension restriction");
    return out;
}

void ModelCatalogue::check() {
    std::string all;
    for (const auto& [name, f] : table())
        for (const std::string& p : problems(f))
            all += "\n    " + p;
    if (!all.empty()) throw std::logic_error("internal error in the model registrations:" + all);
}

std::optional<KeyList> ModelCatalogue::keys(const std::string& family, const std::string& type) {
    const Family* f = find(family);
    if (!f) return std::nullopt;
    const auto it = f->schemas.find(type);
    if (it == f->schemas.end()) return std::nullopt;
    return f->info.common + it->second.keys;
}

namespace {

/// Characters (UTF-8 code points) of `s`: the width it takes in a terminal column.
std::size_t width(const std::string& s) {
    return static_cast<std::size_t>(std::count_if(
        s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xc0) != 0x80; }));
}

/// `rows` as columns, each padded to its widest cell, indented by `indent`.
void printTable(std::ostream& os, const KeyList& rows, const std::string& indent) {
    std::size_t w[4] = {3, 4, 4, 7}; // the headings' widths
    for (const KeyInfo& k : rows) {
        w[0] = std::max(w[0], width(k.name));
        w[1] = std::max(w[1], width(k.type));
        w[2] = std::max(w[2], width(k.unit));
        w[3] = std::max(w[3], width(k.deflt));
    }
    const auto cell = [&os](const std::string& s, std::size_t n) {
        os << s << std::string(n - width(s) + 2, ' ');
    };
    os << indent;
    cell("key", w[0]);
    cell("type", w[1]);
    cell("unit", w[2]);
    cell("default", w[3]);
    os << "meaning\n";
    for (const KeyInfo& k : rows) {
        os << indent;
        cell(k.name, w[0]);
        cell(k.type, w[1]);
        cell(k.unit, w[2]);
        cell(k.deflt, w[3]);
        os << k.meaning << '\n';
    }
}

/// "2D, 3D", "3D only", …; a family's registry of dimension 0 serves both dimensions.
std::string dimensions(const std::set<int>& dims, int onlyDim) {
    if (onlyDim) return std::to_string(onlyDim) + "D only";
    if (dims.count(0)) return "2D, 3D";
    std::string s;
    for (const int d : dims)
        s += (s.empty() ? "" : ", ") + std::to_string(d) + "D";
    return s;
}

void listFamily(std::ostream& os, const ModelCatalogue::Family& f) {
    os << f.name << ", selected by " << f.info.where << " (docs/caseFormat.md §"
       << f.info.docSection << ")\n";
    if (!f.info.common.empty()) {
        os << "  keys of every type:\n";
        printTable(os, f.info.common, "    ");
    }
    for (const auto& [type, dims] : ModelCatalogue::types(f)) {
        const auto it = f.schemas.find(type);
        if (it == f.schemas.end()) {
            os << "  " << type << " (" << dimensions(dims, 0) << "): its keys are documented in "
               << "docs/caseFormat.md §" << f.info.docSection << '\n';
            continue;
        }
        const TypeSchema& s = it->second;
        os << "  " << type << " (" << dimensions(dims, ModelCatalogue::onlyDim(f, type))
           << "): " << s.summary << '\n';
        if (s.keys.empty())
            os << "    no keys of its own\n";
        else
            printTable(os, s.keys, "    ");
        if (!s.example.empty()) os << "    example: " << s.example << '\n';
    }
}

} // namespace

void ModelCatalogue::list(std::ostream& os, const std::string& family) {
    const std::vector<const Family*> all = families();
    if (!family.empty() && !find(family)) {
        std::string valid;
        for (const Family* f : all)
            valid += (valid.empty() ? "" : ", ") + f->name;
        throw std::invalid_argument("-list: unknown family '" + family +
                                    "'; valid families are: " + valid);
    }
    os << "Model types by family, with the keys each reads ('required': no default; units SI,\n"
          "'-' none). The reference is docs/caseFormat.md.\n";
    for (const Family* f : all) {
        if (!family.empty() && f->name != family) continue;
        os << '\n';
        listFamily(os, *f);
    }
    if (family.empty())
        os << "\nChosen by type but not model families, so only in docs/caseFormat.md: the "
              "seeding\n"
              "methods, initial velocity and initial stress (§7), rigid-body motion (§8).\n";
}

} // namespace mpm
