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
    /// What to use instead where the type is refused (a type of one dimension, registered with
    /// MPM_REGISTER_ONLY); it follows the generated "'x' is 3D only (this case is 2D)".
    std::string hint = {};
};

/// What every type of a family shares.
struct FamilyInfo {
    std::string where;      ///< where a type is chosen ("<material>.type in constant/materials")
    std::string docSection; ///< its heading in docs/caseFormat.md without '#' ("6. constant/…")
    KeyList common;         ///< keys every type of the family reads (`type` first)
};

/// The model families (OpenFOAM's run-time selection tables: materials, boundary conditions, …),
/// their registered types and each type's key schema. Families register with MPM_FAMILY (next
/// to the family's base class, case/Registry.hpp), schemas with MPM_SCHEMA (next to the type's
/// registration); the type names come from the registries themselves, so a type without a
/// schema is still listed.
class ModelCatalogue {
public:
    using Lister = std::function<std::vector<std::string>()>;
    /// What the registry of one dimension holds (an empty Lister: none).
    struct Registered {
        Lister types;      ///< the names it builds
        Lister refused;    ///< the names it refuses: types of the other dimension only
        Lister duplicates; ///< names registered twice (an internal error)
    };
    struct Family {
        std::string name;
        FamilyInfo info;
        std::vector<std::pair<int, Registered>> registries; ///< (dimension, its registry)
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
    /// The only dimension of `type` (2 or 3) when the family's other registry refuses it; 0
    /// when it has no such restriction.
    static int onlyDim(const Family& family, const std::string& type);
    /// What creating `type`, registered for dimension `onlyDim` only, in the other one says:
    /// "'levelSet' is 3D only (this case is 2D)", then the schema's hint.
    static std::string refusal(const std::string& family, const std::string& type, int onlyDim);

    /// The programming errors in `family`'s registrations: a name registered twice, a type of
    /// one dimension that the other neither builds nor refuses, a refusal of a type that the
    /// other dimension does not build, a schema hint of a type without a restriction.
    static std::vector<std::string> problems(const Family& family);
    /// Throws std::logic_error (an internal error) listing the problems of every family; called
    /// at start-up.
    static void check();

    /// `mpmFoam -list [family]`: every family (or one) with its types, their keys, defaults and
    /// units. An unknown family is a std::invalid_argument naming the valid ones.
    static void list(std::ostream& os, const std::string& family = "");

    struct AddFamily {
        AddFamily(const std::string& name, FamilyInfo info);
    };
    struct AddTypes {
        AddTypes(const std::string& family, int dim, Lister list);
        AddTypes(const std::string& family, int dim, Registered registry);
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

/// Declare the keys of registered type `type` of `family`, next to its registration:
/// MPM_SCHEMA("materials", "linearElastic", {"summary", {{"E", "scalar", "Pa", "required",
/// "Young's modulus"}, …}, "{type: linearElastic, …}"});
#define MPM_SCHEMA(family, type, ...)                                                              \
    static const ::mpm::ModelCatalogue::AddSchema MPM_SCHEMA_CONCAT(mpmSchema, __LINE__)(          \
        family, type, ::mpm::TypeSchema __VA_ARGS__)
