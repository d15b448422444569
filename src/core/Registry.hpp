// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/KeySchema.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace mpm {

/// Tell `dict` (for its unknown-key message) the keys of `type` of `family`, from the type's
/// schema in the ModelCatalogue (core/KeySchema.hpp).
inline void setKeyHelp(const Dictionary& dict, const std::string& family, const std::string& type) {
    const std::string more = "mpmFoam -list " + family;
    if (const auto keys = ModelCatalogue::keys(family, type)) {
        std::vector<std::string> names;
        for (const KeyInfo& k : *keys)
            names.push_back(k.name);
        dict.setKeyHelp({type, names, more});
    } else if (const auto* f = ModelCatalogue::find(family)) {
        dict.setKeyHelp({type, {}, "docs/caseFormat.md §" + f->info.docSection});
    }
}

/// Run-time selection of models by their `type:` key (OpenFOAM's runTimeSelectionTable).
///
/// Each model registers itself from its own .cpp with MPM_REGISTER (and its keys with
/// MPM_SCHEMA); `create` builds the one a dictionary names, and an unknown type is an InputError
/// listing the valid ones. A registry joins the ModelCatalogue's family with MPM_FAMILY; the
/// dictionary then lists the type's keys when it has an unknown one. The library is an OBJECT
/// library so that no registrar is dropped by the linker.
template <class Base, class... Args> class Registry {
public:
    using BaseType = Base;
    using Factory = std::function<std::unique_ptr<Base>(const Dictionary&, Args...)>;

    static std::map<std::string, Factory>& table() {
        static std::map<std::string, Factory> t;
        return t;
    }

    /// The registry's family in the ModelCatalogue ("" before MPM_FAMILY names it).
    static std::string& family() {
        static std::string f;
        return f;
    }

    /// Joins the registry of dimension `dim` to `family` (MPM_FAMILY).
    struct Join {
        Join(const std::string& name, int dim) {
            family() = name;
            static const ModelCatalogue::AddTypes types(name, dim, [] {
                std::vector<std::string> names;
                for (const auto& entry : table())
                    names.push_back(entry.first);
                return names;
            });
        }
    };

    struct Add {
        Add(const std::string& name, Factory f) { table()[name] = std::move(f); }
    };

    /// Build the model named by `dict`'s `type:` entry.
    static std::unique_ptr<Base> create(const Dictionary& dict, Args... args) {
        const std::string type = dict.getString("type");
        const auto it = table().find(type);
        if (it == table().end()) {
            std::string valid;
            for (const auto& [name, f] : table())
                valid += (valid.empty() ? "" : ", ") + name;
            dict.error("type", "unknown type '" + type + "'; valid types are: " + valid +
                                   (family().empty()
                                        ? std::string()
                                        : " (mpmFoam -list " + family() + " shows their keys)"));
        }
        if (!family().empty()) setKeyHelp(dict, family(), type);
        return it->second(dict, args...);
    }
};

} // namespace mpm

#define MPM_CONCAT_IMPL(a, b) a##b
#define MPM_CONCAT(a, b) MPM_CONCAT_IMPL(a, b)

/// Join `RegistryType` (of dimension `dim`) to the ModelCatalogue's family `name`; once per
/// registry, in the family's .cpp, next to an MPM_FAMILY_INFO.
#define MPM_FAMILY(RegistryType, dim, name)                                                        \
    static const RegistryType::Join MPM_CONCAT(mpmFamily, __LINE__)(name, dim)

/// Describe the family `name` (where it is selected, its docs/caseFormat.md section, the keys
/// every type reads): MPM_FAMILY_INFO("materials", {"constant/materials: …", "6. …", {…}}).
#define MPM_FAMILY_INFO(name, ...)                                                                 \
    static const ::mpm::ModelCatalogue::AddFamily MPM_CONCAT(mpmFamilyInfo, __LINE__)(             \
        name, ::mpm::FamilyInfo __VA_ARGS__)

/// Register `Derived` under `name` in `RegistryType`; Derived must be constructible from the
/// registry's (const Dictionary&, Args...).
#define MPM_REGISTER(RegistryType, Derived, name)                                                  \
    static const RegistryType::Add MPM_CONCAT(mpmRegistrar, __LINE__)(                             \
        name, [](const ::mpm::Dictionary& d, auto&&... a) {                                        \
            return std::unique_ptr<RegistryType::BaseType>(new Derived(d, a...));                  \
        })
