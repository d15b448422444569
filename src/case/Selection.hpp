// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Registry.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace mpm {

/// The words registered in `Reg` (a Registry), in its order.
template <class Reg> std::vector<std::string> registeredWords() {
    std::vector<std::string> words;
    for (const auto& entry : Reg::table())
        words.push_back(entry.first);
    return words;
}

/// Run-time selection by a word: build the option of `Reg` (a Registry joined to its family by
/// MPM_FAMILY, its options registered with MPM_REGISTER…) that the word `key` of `dict` names,
/// or `deflt` where `dict` has no `key` (deflt "": the key is required). For families chosen by
/// one key of a map that holds other keys (system/mpmSchemes `stressUpdate: USL`): the option
/// reads no key of its own, so this reads `key` only and leaves `dict`'s unknown keys to its
/// caller. A word not registered is an InputError at `key` listing the registered ones
/// (Dictionary::getWord); a registry without MPM_FAMILY, a name registered twice or a default
/// not registered is an internal error.
template <class Reg, class... Args>
std::unique_ptr<typename Reg::BaseType> selectByWord(const Dictionary& dict, const std::string& key,
                                                     const std::string& deflt, Args&&... args) {
    const auto internal = [](const std::string& what) {
        return std::logic_error("internal error: the registry of " +
                                std::string(typeid(typename Reg::BaseType).name()) + " " + what);
    };
    if (Reg::family().empty()) throw internal("has no MPM_FAMILY");
    if (!Reg::duplicates().empty())
        throw internal("of family '" + Reg::family() + "' has '" + Reg::duplicates().front() +
                       "' registered twice");
    const std::string word =
        dict.has(key) || deflt.empty() ? dict.getWord(key, registeredWords<Reg>()) : deflt;
    const auto it = Reg::table().find(word);
    if (it == Reg::table().end())
        throw internal("of family '" + Reg::family() + "' lacks the default '" + deflt + "'");
    return it->second(dict, std::forward<Args>(args)...);
}

} // namespace mpm
