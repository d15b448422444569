// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace mpm {

/// One key a model reads: its row of docs/caseFormat.md, in code. The same table feeds
/// `mpmFoam -list` and the unknown-key message of Dictionary::checkUnknownKeys (through
/// Registry::create), so the two cannot disagree.
struct KeyInfo {
    std::string name;    ///< the key as written in the file ("frictionAngle")
    std::string type;    ///< scalar, integer, bool, word, string, vector, map, list, …
    std::string unit;    ///< SI unit, "-" when it has none
    std::string deflt;   ///< the default as text; "required" when there is none
    std::string meaning; ///< one line
};
using KeyList = std::vector<KeyInfo>;

/// `a` followed by `b` (a type's keys: shared ones, then its own).
KeyList operator+(KeyList a, const KeyList& b);

/// What one registered type is and the keys it reads (besides its family's common keys).
struct TypeSchema {
    std::string summary; ///< one line
    KeyList keys;        ///< its own keys, in the order of the documentation
    std::string example; ///< a minimal valid dictionary, YAML flow style ("{type: box, …}")
    int onlyDim = 0;     ///< 2 or 3 when the type refuses the other dimension; 0: both
};

/// What every type of a family shares.
struct FamilyInfo {
    std::string where;      ///< where a type is chosen ("<material>.type in constant/materials")
    std::string docSection; ///< its heading in docs/caseFormat.md without '#' ("6. constant/…")
    KeyList common;         ///< keys every type of the family reads (`type` first)
};

/// The model families (OpenFOAM's run-time selection tables: materials, boundary conditions, …),
/// their registered types and each type's key schema. Families register with MPM_FAMILY (next
/// to the family's base class), schemas with MPM_SCHEMA (next to the type's MPM_REGISTER); the
/// type names come from the registries themselves, so a type without a schema is still listed.
class ModelCatalogue {
public:
    using Lister = std::function<std::vector<std::string>()>;
    struct Family {
        std::string name;
        FamilyInfo info;
        std::vector<std::pair<int, Lister>> listers; ///< (dimension, the registry's type names)
        std::map<std::string, TypeSchema> schemas;
    };

    /// Every family, in the order of docs/caseFormat.md.
    static std::vector<const Family*> families();
    /// The family named `name`, or nullptr.
    static const Family* find(const std::string& name);
    /// The registered types of `family` and the dimensions each is registered for.
    static std::map<std::string, std::set<int>> types(const Family& family);
    /// Every key `type` of `family` reads (the common keys, then its own), or nullopt when the
    /// type has no schema yet.
    static std::optional<KeyList> keys(const std::string& family, const std::string& type);

    /// `mpmFoam -list [family]`: every family (or one) with its types, their keys, defaults and
    /// units. An unknown family is a std::invalid_argument naming the valid ones.
    static void list(std::ostream& os, const std::string& family = "");

    struct AddFamily {
        AddFamily(const std::string& name, FamilyInfo info);
    };
    struct AddTypes {
        AddTypes(const std::string& family, int dim, Lister list);
    };
    struct AddSchema {
        AddSchema(const std::string& family, const std::string& type, TypeSchema schema);
    };

private:
    static std::map<std::string, Family>& table();
};

} // namespace mpm

#define MPM_SCHEMA_CONCAT_IMPL(a, b) a##b
#define MPM_SCHEMA_CONCAT(a, b) MPM_SCHEMA_CONCAT_IMPL(a, b)

/// Declare the keys of registered type `type` of `family`, next to its MPM_REGISTER lines:
/// MPM_SCHEMA("materials", "linearElastic", {"summary", {{"E", "scalar", "Pa", "required",
/// "Young's modulus"}, …}, "{type: linearElastic, …}"});
#define MPM_SCHEMA(family, type, ...)                                                              \
    static const ::mpm::ModelCatalogue::AddSchema MPM_SCHEMA_CONCAT(mpmSchema, __LINE__)(          \
        family, type, ::mpm::TypeSchema __VA_ARGS__)
