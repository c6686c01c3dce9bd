#include "panel.hpp"

#include "cli_args.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <optional>

namespace snell::viewer {
namespace {

const ImVec4 kErrorColor{1.0f, 0.35f, 0.3f, 1.0f};

/// A printf format for values with `unit` ("%.3f m"); '%' in units is escaped.
std::string number_format(const std::string& unit, const char* base = "%.3f") {
  std::string f = base;
  if (!unit.empty()) {
    f += ' ';
    for (const char c : unit) {
      f += c;
      if (c == '%') {
        f += '%';
      }
    }
  }
  return f;
}

/// The tooltip: the doc line, then type, default, range and unit.
void tooltip(const ParamSpec& spec) {
  if (!ImGui::IsItemHovered()) {
    return;
  }
  std::string range;
  if (spec.type == ParamType::enumeration) {
    for (const std::string& c : spec.choices) {
      range.append(range.empty() ? "" : " | ").append(c);
    }
  } else if (spec.type != ParamType::boolean && spec.type != ParamType::texture &&
             spec.type != ParamType::string) {
    range.append("[").append(to_string(ParamValue{spec.min})).append(", ");
    range.append(to_string(ParamValue{spec.max})).append("]");
  }
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
  ImGui::TextUnformatted(spec.doc.c_str());
  ImGui::TextDisabled("%s %s, default %s %s%s%s", spec.name.c_str(),
                      std::string(to_string(spec.type)).c_str(),
                      to_string(spec.default_value).c_str(), range.c_str(),
                      spec.unit.empty() ? "" : " ", spec.unit.c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

/// A slider when the range is small enough to drag across, else a drag field; logarithmic for
/// positive ranges spanning three decades or more.
bool number_widget(const char* label, float* v, int n, const ParamSpec& spec) {
  const std::string format = number_format(spec.unit);
  const float span = spec.max - spec.min;
  const bool log_scale = spec.min > 0.0f && spec.max / spec.min >= 1000.0f;
  if (span <= 200.0f || log_scale) {
    const ImGuiSliderFlags flags = log_scale ? ImGuiSliderFlags_Logarithmic : 0;
    switch (n) {
    case 1:
      return ImGui::SliderFloat(label, v, spec.min, spec.max, format.c_str(), flags);
    case 2:
      return ImGui::SliderFloat2(label, v, spec.min, spec.max, format.c_str(), flags);
    case 3:
      return ImGui::SliderFloat3(label, v, spec.min, spec.max, format.c_str(), flags);
    default:
      return ImGui::SliderFloat4(label, v, spec.min, spec.max, format.c_str(), flags);
    }
  }
  // Wide ranges (positions in metres, +-10 km): drag by a hundredth of the value's size.
  float magnitude = 0.0f;
  for (int i = 0; i < n; ++i) {
    magnitude = std::max(magnitude, std::fabs(v[i]));
  }
  const float speed = 0.01f * std::max(magnitude, 1.0f);
  switch (n) {
  case 1:
    return ImGui::DragFloat(label, v, speed, spec.min, spec.max, format.c_str());
  case 2:
    return ImGui::DragFloat2(label, v, speed, spec.min, spec.max, format.c_str());
  case 3:
    return ImGui::DragFloat3(label, v, speed, spec.min, spec.max, format.c_str());
  default:
    return ImGui::DragFloat4(label, v, speed, spec.min, spec.max, format.c_str());
  }
}

/// The widget of one parameter; returns the new value when the user changed it.
std::optional<ParamValue> param_widget(EffectSlot& slot, const ParamSpec& spec,
                                       const ParamValue& current) {
  const char* label = spec.name.c_str();
  switch (spec.type) {
  case ParamType::boolean: {
    bool v = std::holds_alternative<bool>(current) && std::get<bool>(current);
    if (ImGui::Checkbox(label, &v)) {
      return ParamValue{v};
    }
    break;
  }
  case ParamType::integer: {
    int v = std::holds_alternative<int>(current) ? std::get<int>(current) : 0;
    const int lo = static_cast<int>(spec.min);
    const int hi = static_cast<int>(spec.max);
    bool changed = false;
    const std::string format = number_format(spec.unit, "%d");
    if (hi - lo <= 4096) {
      changed = ImGui::SliderInt(label, &v, lo, hi, format.c_str());
    } else {
      changed = ImGui::DragInt(label, &v, 1.0f, lo, hi, format.c_str());
    }
    tooltip(spec);
    // Layer masks (snell::layer bits): one checkbox per named layer as well.
    if (lo == 0 && hi == 255 && spec.doc.find("layer") != std::string::npos) {
      auto bits = static_cast<unsigned int>(v);
      ImGui::Indent();
      const std::pair<const char*, unsigned int> layers[] = {{"main", layer::main},
                                                             {"reflected", layer::reflected},
                                                             {"refracted", layer::refracted},
                                                             {"captured", layer::captured}};
      for (std::size_t i = 0; i < 4; ++i) {
        if (i > 0) {
          ImGui::SameLine();
        }
        changed |= ImGui::CheckboxFlags(layers[i].first, &bits, layers[i].second);
      }
      ImGui::Unindent();
      v = static_cast<int>(bits);
    }
    if (changed) {
      return ParamValue{v};
    }
    return std::nullopt;
  }
  case ParamType::number: {
    float v = std::holds_alternative<float>(current) ? std::get<float>(current) : 0.0f;
    if (number_widget(label, &v, 1, spec)) {
      return ParamValue{v};
    }
    break;
  }
  case ParamType::vec2: {
    glm::vec2 v =
        std::holds_alternative<glm::vec2>(current) ? std::get<glm::vec2>(current) : glm::vec2(0.0f);
    if (number_widget(label, &v.x, 2, spec)) {
      return ParamValue{v};
    }
    break;
  }
  case ParamType::vec3: {
    glm::vec3 v =
        std::holds_alternative<glm::vec3>(current) ? std::get<glm::vec3>(current) : glm::vec3(0.0f);
    if (number_widget(label, &v.x, 3, spec)) {
      return ParamValue{v};
    }
    break;
  }
  case ParamType::vec4: {
    glm::vec4 v =
        std::holds_alternative<glm::vec4>(current) ? std::get<glm::vec4>(current) : glm::vec4(0.0f);
    if (number_widget(label, &v.x, 4, spec)) {
      return ParamValue{v};
    }
    break;
  }
  case ParamType::color: {
    glm::vec3 v =
        std::holds_alternative<glm::vec3>(current) ? std::get<glm::vec3>(current) : glm::vec3(0.0f);
    // Linear RGB, shown and picked as the linear values (the swapchain is sRGB, so the swatch
    // shows the colour the shading will use).
    if (ImGui::ColorEdit3(label, &v.x, ImGuiColorEditFlags_Float)) {
      return ParamValue{v};
    }
    break;
  }
  case ParamType::enumeration: {
    const std::string v =
        std::holds_alternative<std::string>(current) ? std::get<std::string>(current) : "";
    std::optional<ParamValue> chosen;
    if (ImGui::BeginCombo(label, v.c_str())) {
      for (const std::string& c : spec.choices) {
        if (ImGui::Selectable(c.c_str(), c == v)) {
          chosen = ParamValue{c};
        }
      }
      ImGui::EndCombo();
    }
    tooltip(spec);
    return chosen;
  }
  case ParamType::texture:
  case ParamType::string: {
    // A file (or node name) field: typed, applied with Enter; shows the effect's value when not
    // being edited.
    const std::string v =
        std::holds_alternative<std::string>(current) ? std::get<std::string>(current) : "";
    auto it = slot.edits.find(spec.name);
    if (it == slot.edits.end()) {
      it = slot.edits.emplace(spec.name, v).first;
    }
    const bool entered = ImGui::InputTextWithHint(
        label, spec.type == ParamType::texture ? "built-in (type a PNG/JPEG path, Enter)" : "none",
        &it->second, ImGuiInputTextFlags_EnterReturnsTrue);
    if (!ImGui::IsItemActive() && !entered) {
      it->second = v; // not being typed: follow the effect (a preset may have changed it)
    }
    tooltip(spec);
    if (entered) {
      return ParamValue{it->second};
    }
    return std::nullopt;
  }
  }
  tooltip(spec);
  return std::nullopt;
}

} // namespace

Result<void> apply_param(EffectSlot& slot, std::string_view key, const ParamValue& value) {
  const std::string k(key);
  if (slot.effect == nullptr) {
    return fail(ErrorCode::invalid_argument, slot.name + ": no effect");
  }
  auto r = slot.effect->set_param(key, value);
  if (r) {
    slot.errors.erase(k);
  } else {
    slot.errors[k] = r.error().message;
  }
  return r;
}

Result<ParamValue> text_to_value(const ParamSchema& schema, const ParamSpec& spec,
                                 std::string_view text) {
  // parse_param with the range and choices opened up: only the type is checked here.
  ParamSpec loose = spec;
  loose.min = -FLT_MAX;
  loose.max = FLT_MAX;
  if (spec.type == ParamType::enumeration) {
    loose.choices = {std::string(text)};
  }
  return parse_param(schema, loose, text);
}

std::string instance_label(const std::vector<EffectSlot>& slots, std::size_t index) {
  const std::string& name = slots[index].name;
  std::size_t count = 0, k = 0;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].name == name) {
      ++count;
      if (i <= index) {
        ++k;
      }
    }
  }
  return count == 1 ? name : name + "@" + std::to_string(k);
}

std::vector<std::size_t> find_instances(const std::vector<EffectSlot>& slots,
                                        const std::string& effect) {
  const auto [name, k] = cli::split_instance(effect);
  std::vector<std::size_t> out;
  std::uint32_t seen = 0;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].name != name) {
      continue;
    }
    ++seen;
    if (effect.find('@') == std::string::npos || seen == k) {
      out.push_back(i);
    }
  }
  return out;
}

void draw_effect_section(EffectSlot& slot, const std::string& label) {
  ImGui::PushID(static_cast<int>(slot.id));
  bool visible = true;
  const bool open = ImGui::CollapsingHeader((label + "###effect").c_str(), &visible,
                                            ImGuiTreeNodeFlags_DefaultOpen);
  if (!visible) {
    slot.remove = true;
  }
  if (ImGui::IsItemHovered() && slot.schema != nullptr) {
    ImGui::SetTooltip("%s\n(the x removes it)", slot.schema->doc.c_str());
  }
  if (!open || slot.schema == nullptr || slot.effect == nullptr) {
    ImGui::PopID();
    return;
  }
  if (!slot.frame_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::TextWrapped("skipped: %s", slot.frame_error.c_str());
    ImGui::PopStyleColor();
  }
  if (ImGui::SmallButton("reset all")) {
    for (const ParamSpec& spec : slot.schema->params) {
      if (spec.name != "preset") { // a preset would overwrite the others again
        (void)apply_param(slot, spec.name, spec.default_value);
      }
    }
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Every parameter back to its default (each through set_param)");
  }
  for (const ParamSpec& spec : slot.schema->params) {
    ImGui::PushID(spec.name.c_str());
    auto current = slot.effect->get_param(spec.name);
    const ParamValue value = current ? *current : spec.default_value;
    const bool is_default = to_string(value) == to_string(spec.default_value);
    ImGui::BeginDisabled(is_default);
    if (ImGui::SmallButton("R")) {
      (void)apply_param(slot, spec.name, spec.default_value);
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip("Reset %s to its default, %s", spec.name.c_str(),
                        to_string(spec.default_value).c_str());
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    if (auto changed = param_widget(slot, spec, value)) {
      (void)apply_param(slot, spec.name, *changed);
    }
    if (auto it = slot.errors.find(spec.name); it != slot.errors.end()) {
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
      ImGui::TextWrapped("%s", it->second.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::PopID();
  }
  ImGui::PopID();
}

std::string draw_add_effect(const std::vector<std::string>& names, int& selected) {
  if (names.empty()) {
    return "";
  }
  selected = std::clamp(selected, 0, static_cast<int>(names.size()) - 1);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  if (ImGui::BeginCombo("##add", names[static_cast<std::size_t>(selected)].c_str())) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (ImGui::Selectable(names[i].c_str(), static_cast<int>(i) == selected)) {
        selected = static_cast<int>(i);
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("add effect")) {
    return names[static_cast<std::size_t>(selected)];
  }
  return "";
}

} // namespace snell::viewer
