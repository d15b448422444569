// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace mpm {

/// Run-time selection of models by their `type:` key (OpenFOAM's runTimeSelectionTable).
///
/// Each model registers itself from its own .cpp with MPM_REGISTER; `create` builds the one a
/// dictionary names, and an unknown type is an InputError listing the valid ones. The library is
/// an OBJECT library so that no registrar is dropped by the linker.
template <class Base, class... Args> class Registry {
public:
    using BaseType = Base;
    using Factory = std::function<std::unique_ptr<Base>(const Dictionary&, Args...)>;

    static std::map<std::string, Factory>& table() {
        static std::map<std::string, Factory> t;
        return t;
    }

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
            dict.error("type", "unknown type '" + type + "'; valid types are: " + valid);
        }
        return it->second(dict, args...);
    }
};

} // namespace mpm

#define MPM_CONCAT_IMPL(a, b) a##b
#define MPM_CONCAT(a, b) MPM_CONCAT_IMPL(a, b)

/// Register `Derived` under `name` in `RegistryType`; Derived must be constructible from the
/// registry's (const Dictionary&, Args...).
#define MPM_REGISTER(RegistryType, Derived, name)                                                  \
    static const RegistryType::Add MPM_CONCAT(mpmRegistrar, __LINE__)(                             \
        name, [](const ::mpm::Dictionary& d, auto&&... a) {                                        \
            return std::unique_ptr<RegistryType::BaseType>(new Derived(d, a...));                  \
        })
