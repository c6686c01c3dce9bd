// The parameter panel, generated from each effect's ParamSchema with Dear ImGui: sliders within
// the schema's range with its unit, combos for enumerations, colour pickers, vector fields,
// file fields for textures, a reset to the default, the parameter's doc as a tooltip. Every
// change goes through Effect::set_param (apply_param below), so the same validation applies as
// in `snell render --set`; a refused value shows its error under the parameter.
#pragma once

#include <snell/effect.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace snell::viewer {

/// One effect of the viewer with the panel's state for it.
struct EffectSlot {
  std::string name;     ///< Registry name ("water").
  std::uint32_t id = 0; ///< Unique in this run (ImGui ids survive removals of others).
  std::unique_ptr<Effect> effect;
  const ParamSchema* schema = nullptr;       ///< The registry's schema of `name`.
  std::map<std::string, std::string> errors; ///< Parameter key -> why its last value was refused.
  std::map<std::string, std::string> edits;  ///< Texture / string fields being typed.
  std::string frame_error; ///< Why the last frame skipped the effect ("" when it did not).
  bool remove = false;     ///< Removal requested in the panel (done between frames).
};

/// The panel's code path for every change: Effect::set_param(key, value). On success the key's
/// error is cleared; on refusal the error is kept in `slot.errors[key]` (the panel shows it
/// under the parameter) and returned. Unknown keys are refused the same way, listing the keys.
Result<void> apply_param(EffectSlot& slot, std::string_view key, const ParamValue& value);

/// Converts text to a value of `spec`'s type without checking its range or choices (those are
/// set_param's to check, as for a value typed into the panel): "0.5", "1,2,3", "true", a choice.
/// Errors: text that is not of the type at all (invalid_argument, naming the parameter).
[[nodiscard]] Result<ParamValue> text_to_value(const ParamSchema& schema, const ParamSpec& spec,
                                               std::string_view text);

/// "EFFECT" for the only instance of its name in `slots`, else "EFFECT@K" (K from 1, in the
/// order of `slots`): how --set and scripts name it.
[[nodiscard]] std::string instance_label(const std::vector<EffectSlot>& slots, std::size_t index);
/// The slots a script's or --set's "EFFECT" (every instance) or "EFFECT@K" (the K-th) names.
[[nodiscard]] std::vector<std::size_t> find_instances(const std::vector<EffectSlot>& slots,
                                                      const std::string& effect);

/// Draws one effect's section (inside an ImGui window): a collapsing header with a close button
/// (sets `slot.remove`), the effect's doc, its frame error, "reset all", and one widget per
/// parameter of its schema.
void draw_effect_section(EffectSlot& slot, const std::string& label);

/// Draws the "add effect" row: a combo of the registry's names and a button. Returns the name
/// to add, or "" when nothing was asked this frame. `selected` keeps the combo's choice.
[[nodiscard]] std::string draw_add_effect(const std::vector<std::string>& names, int& selected);

} // namespace snell::viewer
