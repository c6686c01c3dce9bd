// The water effect's schema: built from WaterParams{} so code and schema cannot drift, and the
// conversion between the typed struct and data-driven (key, value) parameters.
#include "water_internal.hpp"

#include <array>

namespace snell {
namespace {

constexpr std::array<const char*, 2> kClipModes = {"oblique", "clip_distance"};
constexpr std::array<const char*, 4> kFresnel = {"exact", "schlick", "seed", "constant"};
constexpr std::array<const char*, 5> kDebugViews = {"final", "reflection", "refraction", "normals",
                                                    "fresnel"};

template <std::size_t N> std::vector<std::string> choices(const std::array<const char*, N>& a) {
  return std::vector<std::string>(a.begin(), a.end());
}

template <std::size_t N> int index_of(const std::array<const char*, N>& a, const std::string& s) {
  for (std::size_t i = 0; i < N; ++i) {
    if (s == a[i]) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

ParamSchema build_schema() {
  const WaterParams d;
  ParamSchema s;
  s.effect = "water";
  s.doc = "Planar water: reflection + refraction targets, ripples, Fresnel, absorption.";
  auto num = [&](const char* name, float def, float lo, float hi, const char* unit,
                 const char* doc) {
    s.params.push_back(ParamSpec{name, ParamType::number, def, lo, hi, {}, unit, doc});
  };
  auto vec2 = [&](const char* name, glm::vec2 def, float lo, float hi, const char* unit,
                  const char* doc) {
    s.params.push_back(ParamSpec{name, ParamType::vec2, def, lo, hi, {}, unit, doc});
  };
  auto color = [&](const char* name, glm::vec3 def, const char* doc) {
    s.params.push_back(ParamSpec{name, ParamType::color, def, 0.0f, 1.0f, {}, "", doc});
  };
  auto enumeration = [&](const char* name, std::string def, std::vector<std::string> c,
                         const char* doc) {
    s.params.push_back(ParamSpec{name, ParamType::enumeration, def, 0, 0, std::move(c), "", doc});
  };
  auto integer = [&](const char* name, int def, int lo, int hi, const char* doc) {
    s.params.push_back(ParamSpec{name, ParamType::integer, def, float(lo), float(hi), {}, "", doc});
  };
  enumeration("preset", "default", {"default", "seed"},
              "Resets every parameter but height/center/size to a preset (seed = seeds 000/001); "
              "reads back the last preset applied");
  num("height", d.height, -1e4f, 1e4f, "m", "Height of the water plane y = height");
  vec2("center", d.center, -1e4f, 1e4f, "m", "Centre (x, z) of the water rectangle");
  vec2("size", d.size, 0.01f, 1e5f, "m", "Size (x, z) of the water rectangle");
  num("resolution_scale", d.resolution_scale, 0.1f, 1.0f, "",
      "Reflection/refraction target size relative to the output (1 = seeds)");
  enumeration("clip_mode", kClipModes[static_cast<int>(d.clip_mode)], choices(kClipModes),
              "Clipping of the passes: oblique near plane or gl_ClipDistance");
  num("clip_offset", d.clip_offset, 0.0f, 10.0f, "m",
      "How far past the surface each pass keeps geometry (no seam at the water line)");
  num("wave_length", d.wave_length, 0.01f, 1000.0f, "m", "World size of one ripple-map tile");
  num("wave_height", d.wave_height, 0.0f, 4.0f, "", "Ripple strength (0 = flat water)");
  num("distortion", d.distortion, 0.0f, 0.5f, "",
      "Texture offset of the reflection/refraction lookups per unit of slope");
  vec2("wind_direction", d.wind_direction, -1.0f, 1.0f, "",
       "Direction (x, z) the ripples scroll, normalised internally");
  num("wind_force", d.wind_force, 0.0f, 100.0f, "m/s", "Scroll speed of the ripples");
  enumeration("fresnel", kFresnel[static_cast<int>(d.fresnel)], choices(kFresnel),
              "Fresnel term: exact dielectric, Schlick, seed 001's 1 - dot(eye, normal), or "
              "constant (reflectance)");
  num("ior", d.ior, 1.0f, 3.0f, "", "Index of refraction of the water (air above: 1)");
  num("reflectance", d.reflectance, 0.0f, 1.0f, "",
      "Reflection weight for fresnel=constant (seed 000: 0.4)");
  color("water_color", d.water_color, "Colour of the water body (linear RGB)");
  num("color_blend", d.color_blend, 0.0f, 1.0f, "", "Blend toward water_color (seed 001: 0.2)");
  num("specular_power", d.specular_power, 1.0f, 4096.0f, "", "Exponent of the sun highlight");
  num("specular_intensity", d.specular_intensity, 0.0f, 100.0f, "", "Strength of the highlight");
  s.params.push_back(ParamSpec{"absorption",
                               ParamType::vec3,
                               d.absorption,
                               0.0f,
                               100.0f,
                               {},
                               "1/m",
                               "Beer-Lambert absorption per metre along the view ray"});
  num("shore_softness", d.shore_softness, 0.0f, 100.0f, "m",
      "Water depth over which distortion, reflection and highlight fade in at the shore");
  integer("reflection_layers", d.reflection_layers, 0, 255,
          "Objects drawn in the reflection (snell::layer bits)");
  integer("refraction_layers", d.refraction_layers, 0, 255,
          "Objects drawn in the refraction (snell::layer bits)");
  enumeration("debug_view", kDebugViews[static_cast<int>(d.debug_view)], choices(kDebugViews),
              "What the surface shows: final, reflection, refraction, normals, fresnel");
  s.params.push_back(
      ParamSpec{"normal_map",
                ParamType::texture,
                d.normal_map,
                0,
                0,
                {},
                "",
                "Ripple normal map file (tangent space, tileable); \"\" = built-in"});
  return s;
}

} // namespace

const ParamSchema& water_schema() {
  static const ParamSchema schema = build_schema();
  return schema;
}

WaterParams water_seed_preset(const WaterParams& base) {
  WaterParams p;
  p.height = base.height;
  p.center = base.center;
  p.size = base.size;
  p.resolution_scale = 1.0f;
  p.clip_offset = 0.1f;
  p.distortion = 0.01f;
  p.fresnel = WaterFresnel::constant;
  p.reflectance = 0.4f;
  p.water_color = glm::vec3(0.3f, 0.3f, 0.5f);
  p.color_blend = 0.2f;
  p.specular_power = 256.0f;
  p.absorption = glm::vec3(0.0f);
  p.shore_softness = 0.0f;
  return p;
}

namespace detail {

Result<void> apply_water_param(WaterParams& p, std::string_view key, const ParamValue& value) {
  const ParamSchema& schema = water_schema();
  const ParamSpec* spec = schema.find(key);
  if (spec == nullptr) {
    return fail(ErrorCode::unknown_name,
                "water: unknown parameter '" + std::string(key) + "'; valid: " + schema.key_list());
  }
  if (auto r = validate_param(schema, *spec, value); !r) {
    return r;
  }
  const auto f = [&] { return std::get<float>(value); };
  const auto v2 = [&] { return std::get<glm::vec2>(value); };
  const auto v3 = [&] { return std::get<glm::vec3>(value); };
  const auto s = [&] { return std::get<std::string>(value); };
  if (key == "preset") {
    p = s() == "seed" ? water_seed_preset(p) : [&] {
      WaterParams d;
      d.height = p.height;
      d.center = p.center;
      d.size = p.size;
      return d;
    }();
  } else if (key == "height") {
    p.height = f();
  } else if (key == "center") {
    p.center = v2();
  } else if (key == "size") {
    p.size = v2();
  } else if (key == "resolution_scale") {
    p.resolution_scale = f();
  } else if (key == "clip_mode") {
    p.clip_mode = static_cast<WaterClipMode>(index_of(kClipModes, s()));
  } else if (key == "clip_offset") {
    p.clip_offset = f();
  } else if (key == "wave_length") {
    p.wave_length = f();
  } else if (key == "wave_height") {
    p.wave_height = f();
  } else if (key == "distortion") {
    p.distortion = f();
  } else if (key == "wind_direction") {
    p.wind_direction = v2();
  } else if (key == "wind_force") {
    p.wind_force = f();
  } else if (key == "fresnel") {
    p.fresnel = static_cast<WaterFresnel>(index_of(kFresnel, s()));
  } else if (key == "ior") {
    p.ior = f();
  } else if (key == "reflectance") {
    p.reflectance = f();
  } else if (key == "water_color") {
    p.water_color = v3();
  } else if (key == "color_blend") {
    p.color_blend = f();
  } else if (key == "specular_power") {
    p.specular_power = f();
  } else if (key == "specular_intensity") {
    p.specular_intensity = f();
  } else if (key == "absorption") {
    p.absorption = v3();
  } else if (key == "shore_softness") {
    p.shore_softness = f();
  } else if (key == "reflection_layers") {
    p.reflection_layers = std::get<int>(value);
  } else if (key == "refraction_layers") {
    p.refraction_layers = std::get<int>(value);
  } else if (key == "debug_view") {
    p.debug_view = static_cast<WaterDebugView>(index_of(kDebugViews, s()));
  } else if (key == "normal_map") {
    p.normal_map = s();
  }
  return {};
}

Result<ParamValue> read_water_param(const WaterParams& p, std::string_view key) {
  const ParamSchema& schema = water_schema();
  if (schema.find(key) == nullptr) {
    return fail(ErrorCode::unknown_name,
                "water: unknown parameter '" + std::string(key) + "'; valid: " + schema.key_list());
  }
  if (key == "preset") {
    return ParamValue{std::string("default")};
  }
  if (key == "height")
    return ParamValue{p.height};
  if (key == "center")
    return ParamValue{p.center};
  if (key == "size")
    return ParamValue{p.size};
  if (key == "resolution_scale")
    return ParamValue{p.resolution_scale};
  if (key == "clip_mode")
    return ParamValue{std::string(kClipModes[static_cast<int>(p.clip_mode)])};
  if (key == "clip_offset")
    return ParamValue{p.clip_offset};
  if (key == "wave_length")
    return ParamValue{p.wave_length};
  if (key == "wave_height")
    return ParamValue{p.wave_height};
  if (key == "distortion")
    return ParamValue{p.distortion};
  if (key == "wind_direction")
    return ParamValue{p.wind_direction};
  if (key == "wind_force")
    return ParamValue{p.wind_force};
  if (key == "fresnel")
    return ParamValue{std::string(kFresnel[static_cast<int>(p.fresnel)])};
  if (key == "ior")
    return ParamValue{p.ior};
  if (key == "reflectance")
    return ParamValue{p.reflectance};
  if (key == "water_color")
    return ParamValue{p.water_color};
  if (key == "color_blend")
    return ParamValue{p.color_blend};
  if (key == "specular_power")
    return ParamValue{p.specular_power};
  if (key == "specular_intensity")
    return ParamValue{p.specular_intensity};
  if (key == "absorption")
    return ParamValue{p.absorption};
  if (key == "shore_softness")
    return ParamValue{p.shore_softness};
  if (key == "reflection_layers")
    return ParamValue{p.reflection_layers};
  if (key == "refraction_layers")
    return ParamValue{p.refraction_layers};
  if (key == "normal_map")
    return ParamValue{p.normal_map};
  return ParamValue{std::string(kDebugViews[static_cast<int>(p.debug_view)])};
}

Result<void> validate_water_params(const WaterParams& p) {
  // Enumerations first: a cast integer out of range must not index the name tables.
  if (static_cast<std::size_t>(p.clip_mode) >= kClipModes.size() ||
      static_cast<std::size_t>(p.fresnel) >= kFresnel.size() ||
      static_cast<std::size_t>(p.debug_view) >= kDebugViews.size()) {
    return fail(ErrorCode::invalid_argument,
                "water: WaterParams has an out-of-range enumeration value (clip_mode, fresnel "
                "or debug_view)");
  }
  WaterParams scratch;
  for (const ParamSpec& spec : water_schema().params) {
    if (spec.name == "preset") {
      continue;
    }
    auto value = read_water_param(p, spec.name);
    if (!value) {
      return value.error();
    }
    if (auto r = apply_water_param(scratch, spec.name, *value); !r) {
      return r;
    }
  }
  return {};
}

} // namespace detail
} // namespace snell
