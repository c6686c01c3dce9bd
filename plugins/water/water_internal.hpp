// Internal to the water plugin: the parameter table shared by the effect and its schema.
#pragma once

#include <snell/param_table.hpp>
#include <snell/water.hpp>

namespace snell::detail {

/// The water's parameter table (schema, set, get, validation).
const ParamTable<WaterParams>& water_table();

} // namespace snell::detail
