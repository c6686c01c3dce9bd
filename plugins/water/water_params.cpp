// The water effect's parameters, each declared once: the schema (defaults from WaterParams{}, so
// code and schema cannot drift), set, get and whole-struct validation come from this table.
#include "water_internal.hpp"

#include <snell/param_table.hpp>

namespace snell {
namespace {

/// The `preset` action: every parameter but height/center/size from a preset.
void apply_preset(WaterParams& p, const std::string& preset) {
  if (preset == "seed") {
    p = water_seed_preset(p);
    return;
  }
  WaterParams d;
  d.height = p.height;
  d.center = p.center;
  d.size = p.size;
  p = d;
}

const ParamTable<WaterParams>& table() {
  using W = WaterParams;
  static const ParamTable<W> t =
      ParamTable<W>("water",
                    "Planar water: reflection + refraction targets, ripples, Fresnel, absorption.")
          .action("preset", {"default", "seed"}, "default", apply_preset,
                  "Resets every parameter but height/center/size to a preset (seed = seeds "
                  "000/001); reads back the last preset applied")
          .number("height", &W::height, -1e4f, 1e4f, "m", "Height of the water plane y = height")
          .vec2("center", &W::center, -1e4f, 1e4f, "m", "Centre (x, z) of the water rectangle")
          .vec2("size", &W::size, 0.01f, 1e5f, "m", "Size (x, z) of the water rectangle")
          .number("resolution_scale", &W::resolution_scale, 0.1f, 1.0f, "",
                  "Reflection/refraction target size relative to the output (1 = seeds)")
          .enumeration("refraction_source", &W::refraction_source, {"snapshot", "pass"},
                       "Refraction from the frame's scene snapshot (no extra pass; the pass "
                       "when the host gives none) or from a pass of its own (seeds)")
          .enumeration("clip_mode", &W::clip_mode, {"oblique", "clip_distance"},
                       "Clipping of the passes: oblique near plane or gl_ClipDistance")
          .number("clip_offset", &W::clip_offset, 0.0f, 10.0f, "m",
                  "How far past the surface each pass keeps geometry (no seam at the water line)")
          .number("wave_length", &W::wave_length, 0.01f, 1000.0f, "m",
                  "World size of one ripple-map tile")
          .number("wave_height", &W::wave_height, 0.0f, 4.0f, "",
                  "Ripple strength (0 = flat water)")
          .number("distortion", &W::distortion, 0.0f, 0.5f, "",
                  "Texture offset of the reflection/refraction lookups per unit of slope")
          .vec2("wind_direction", &W::wind_direction, -1.0f, 1.0f, "",
                "Direction (x, z) the ripples scroll, normalised internally")
          .number("wind_force", &W::wind_force, 0.0f, 100.0f, "m/s", "Scroll speed of the ripples")
          .enumeration("fresnel", &W::fresnel, {"exact", "schlick", "seed", "constant"},
                       "Fresnel term: exact dielectric, Schlick, seed 001's 1 - dot(eye, normal), "
                       "or constant (reflectance)")
          .number("ior", &W::ior, 1.0f, 3.0f, "", "Index of refraction of the water (air above: 1)")
          .number("reflectance", &W::reflectance, 0.0f, 1.0f, "",
                  "Reflection weight for fresnel=constant (seed 000: 0.4)")
          .color("water_color", &W::water_color, "Colour of the water body (linear RGB)")
          .number("color_blend", &W::color_blend, 0.0f, 1.0f, "",
                  "Blend toward water_color (seed 001: 0.2)")
          .number("specular_power", &W::specular_power, 1.0f, 4096.0f, "",
                  "Exponent of the sun highlight")
          .number("specular_intensity", &W::specular_intensity, 0.0f, 100.0f, "",
                  "Strength of the highlight")
          .vec3("absorption", &W::absorption, 0.0f, 100.0f, "1/m",
                "Beer-Lambert absorption per metre along the view ray")
          .number(
              "shore_softness", &W::shore_softness, 0.0f, 100.0f, "m",
              "Water depth over which distortion, reflection and highlight fade in at the shore")
          .integer("reflection_layers", &W::reflection_layers, 0, 255, "",
                   "Objects drawn in the reflection (snell::layer bits)")
          .integer("refraction_layers", &W::refraction_layers, 0, 255, "",
                   "Objects drawn in the refraction (snell::layer bits)")
          .enumeration("debug_view", &W::debug_view,
                       {"final", "reflection", "refraction", "normals", "fresnel"},
                       "What the surface shows: final, reflection, refraction, normals, fresnel")
          .texture("normal_map", &W::normal_map,
                   "Ripple normal map file (tangent space, tileable); \"\" = built-in");
  return t;
}

} // namespace

const ParamSchema& water_schema() {
  return table().schema();
}

WaterParams water_seed_preset(const WaterParams& base) {
  WaterParams p;
  p.height = base.height;
  p.center = base.center;
  p.size = base.size;
  p.resolution_scale = 1.0f;
  p.refraction_source = WaterRefractionSource::pass; // the seeds' own refraction target
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

const ParamTable<WaterParams>& water_table() {
  return table();
}

} // namespace detail
} // namespace snell
