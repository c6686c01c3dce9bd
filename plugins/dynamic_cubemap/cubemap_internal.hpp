// Internal to the dynamic cube map plugin: its parameter table.
#pragma once

#include <snell/dynamic_cubemap.hpp>
#include <snell/param_table.hpp>

namespace snell::detail {

/// The parameter table (schema, set, get, validation).
const ParamTable<DynamicCubemapParams>& cubemap_table();

} // namespace snell::detail
