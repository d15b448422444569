// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/KeySchema.hpp"

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

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

/// Run-time selection of models by their `type:` key (OpenFOAM's runTimeSelectionTable), one
/// registry per family and dimension.
///
/// Each model registers itself from its own .cpp: MPM_REGISTER_DIMS (2D and 3D), MPM_REGISTER_ONLY
/// (one dimension; the other refuses the type with a generated message) or MPM_REGISTER (one
/// registry), and its keys with MPM_SCHEMA. A registry joins the ModelCatalogue's family with
/// MPM_FAMILY, which every registry needs. `create` builds the model a dictionary names and
/// checks that it read every key; an unknown type is an InputError listing the valid ones. A
/// name registered twice is an internal error (create, ModelCatalogue::check). The library is an
/// OBJECT library so that no registrar is dropped by the linker.
template <class Base, class... Args> class Registry {
public:
    using BaseType = Base;
    using Factory = std::function<std::unique_ptr<Base>(const Dictionary&, Args...)>;

    static std::map<std::string, Factory>& table() {
        static std::map<std::string, Factory> t;
        return t;
    }

    /// Types this dimension refuses (MPM_REGISTER_ONLY): name → the only dimension they have.
    static std::map<std::string, int>& refused() {
        static std::map<std::string, int> r;
        return r;
    }

    /// Names registered (or refused) more than once: the first registration stands.
    static std::vector<std::string>& duplicates() {
        static std::vector<std::string> d;
        return d;
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
            static const ModelCatalogue::AddTypes types(
                name, dim, {names(table()), names(refused()), [] { return duplicates(); }});
        }
    };

    struct Add {
        Add(const std::string& name, Factory f) {
            if (taken(name))
                duplicates().push_back(name);
            else
                table().emplace(name, std::move(f));
        }
    };

    /// Refuse `name` in this registry: it is registered for dimension `onlyDim` only.
    struct Refuse {
        Refuse(const std::string& name, int onlyDim) {
            if (taken(name))
                duplicates().push_back(name);
            else
                refused().emplace(name, onlyDim);
        }
    };

    /// Build the model named by `dict`'s `type:` entry; a key of `dict` it did not read is an
    /// InputError listing the type's keys.
    static std::unique_ptr<Base> create(const Dictionary& dict, Args... args) {
        std::unique_ptr<Base> model = createReadingMore(dict, args...);
        dict.checkUnknownKeys();
        return model;
    }

    /// As create, for a caller that reads more keys of `dict` (its family's common keys) and
    /// then calls dict.checkUnknownKeys() itself.
    static std::unique_ptr<Base> createReadingMore(const Dictionary& dict, Args... args) {
        if (family().empty() || !duplicates().empty())
            throw std::logic_error(
                std::string("internal error: the registry of ") + typeid(Base).name() +
                (family().empty() ? " has no MPM_FAMILY"
                                  : " of family '" + family() + "' has '" + duplicates().front() +
                                        "' registered twice"));
        const std::string type = dict.getString("type");
        if (const auto r = refused().find(type); r != refused().end())
            dict.error("type", ModelCatalogue::refusal(family(), type, r->second));
        const auto it = table().find(type);
        if (it == table().end()) {
            std::string valid;
            for (const auto& [name, f] : table())
                valid += (valid.empty() ? "" : ", ") + name;
            dict.error("type", "unknown type '" + type + "'; valid types are: " + valid +
                                   " (mpmFoam -list " + family() + " shows their keys)");
        }
        setKeyHelp(dict, family(), type);
        return it->second(dict, args...);
    }

private:
    static bool taken(const std::string& name) {
        return table().count(name) != 0 || refused().count(name) != 0;
    }
    template <class Map> static ModelCatalogue::Lister names(const Map& map) {
        return [&map] {
            std::vector<std::string> out;
            for (const auto& entry : map)
                out.push_back(entry.first);
            return out;
        };
    }
};

} // namespace mpm

#define MPM_CONCAT_IMPL(a, b) a##b
#define MPM_CONCAT(a, b) MPM_CONCAT_IMPL(a, b)

/// Join `RegistryType` (of dimension `dim`) to the ModelCatalogue's family `name`; once per
/// registry, in the family's .cpp, next to an MPM_FAMILY_INFO.
#define MPM_FAMILY(RegistryType, dim, name)                                                        \
    static const RegistryType::Join MPM_CONCAT(mpmFamily, __COUNTER__)(name, dim)

/// Join both registries of an alias template `Family<dim>` (Family<2>, Family<3>) to the family
/// `name`: MPM_FAMILY_DIMS(MaterialRegistry, "materials").
#define MPM_FAMILY_DIMS(Family, name)                                                              \
    MPM_FAMILY(Family<2>, 2, name);                                                                \
    MPM_FAMILY(Family<3>, 3, name)

/// Describe the family `name` (where it is selected, its docs/caseFormat.md section, the keys
/// every type reads): MPM_FAMILY_INFO("materials", {"constant/materials: …", "6. …", {…}}).
#define MPM_FAMILY_INFO(name, ...)                                                                 \
    static const ::mpm::ModelCatalogue::AddFamily MPM_CONCAT(mpmFamilyInfo, __COUNTER__)(          \
        name, ::mpm::FamilyInfo __VA_ARGS__)

/// Register `Derived` under `name` in the one registry `RegistryType`; Derived must be
/// constructible from the registry's (const Dictionary&, Args...).
#define MPM_REGISTER(RegistryType, Derived, name)                                                  \
    static const RegistryType::Add MPM_CONCAT(mpmRegistrar, __COUNTER__)(                          \
        name, [](const ::mpm::Dictionary& d, auto&&... a) {                                        \
            return std::unique_ptr<RegistryType::BaseType>(new Derived(d, a...));                  \
        })

/// Register `Derived<2>` and `Derived<3>` under `name` in `Family<2>` and `Family<3>` (a family
/// is an alias template such as MaterialRegistry):
/// MPM_REGISTER_DIMS(MaterialRegistry, HenckyElastic, "henckyElastic").
#define MPM_REGISTER_DIMS(Family, Derived, name)                                                   \
    MPM_REGISTER(Family<2>, Derived<2>, name);                                                     \
    MPM_REGISTER(Family<3>, Derived<3>, name)

/// Register `Derived` (the model of dimension `dim`, 2 or 3) under `name` in `Family<dim>`; the
/// other dimension refuses the type: "'levelSet' is 3D only (this case is 2D)" and the hint of
/// its schema. MPM_REGISTER_ONLY(3, ShapeRegistry, LevelSetShape, "levelSet").
#define MPM_REGISTER_ONLY(dim, Family, Derived, name)                                              \
    MPM_REGISTER(Family<dim>, Derived, name);                                                      \
    static const Family<5 - (dim)>::Refuse MPM_CONCAT(mpmRefusal, __COUNTER__)(name, dim)
