// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace mpm {

/// Version of mpmFoam ("0.1.0").
extern const char* const buildVersion;
/// Git revision the binary was configured from ("f2a257f-dirty").
extern const char* const buildRevision;

} // namespace mpm
