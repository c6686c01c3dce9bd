// Snell plugin toolkit: what every plugin's creation and registration share. A plugin's typed
// creator (create_water, create_mirror, ...) checks its create info with check_create_info, and
// its register_<name> hands the registry effect_factory(create_<name>).
#pragma once

#include <snell/effect.hpp>

#include <memory>
#include <string_view>
#include <utility>

namespace snell {

/// Checks what every effect needs of `info`: a context, and frames_in_flight in [1, 16].
/// Errors (invalid_argument) name `effect` and the field: "mirror: EffectCreateInfo::context is
/// required", "...frames_in_flight = 0 is outside [1, 16]".
[[nodiscard]] Result<void> check_create_info(const EffectCreateInfo& info, std::string_view effect);

/// The registry's factory for a typed creator: `create(info)` returns
/// Result<std::unique_ptr<T>> for some Effect subclass T; the factory returns it as an Effect.
template <class Create> [[nodiscard]] EffectFactory effect_factory(Create create) {
  return [create](const EffectCreateInfo& info) -> Result<std::unique_ptr<Effect>> {
    auto made = create(info);
    if (!made) {
      return made.error();
    }
    return std::unique_ptr<Effect>(std::move(*made));
  };
}

} // namespace snell
