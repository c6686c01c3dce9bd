// Internal to the water plugin: parameter plumbing shared by the effect and its schema.
#pragma once

#include <snell/water.hpp>

namespace snell::detail {

/// Validates `value` against the schema and stores it in `p` (the whole preset for "preset").
Result<void> apply_water_param(WaterParams& p, std::string_view key, const ParamValue& value);
/// The current value of `key` in `p`.
Result<ParamValue> read_water_param(const WaterParams& p, std::string_view key);
/// Validates every field of `p` against the schema (non-finite, out of range...).
Result<void> validate_water_params(const WaterParams& p);

} // namespace snell::detail
