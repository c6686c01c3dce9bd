// The glass and ice parameters, each declared once: one table per registered name (same
// declarations, their own defaults and preset action), from which the schema, set, get and
// whole-struct validation come.
#include "glass_internal.hpp"

#include <snell/param_table.hpp>

namespace snell {
namespace {

/// Keeps the pane's placement of `from` in `to`.
GlassParams keep_placement(GlassParams to, const GlassParams& from) {
  to.pane = from.pane;
  to.center = from.center;
  to.size = from.size;
  to.normal = from.normal;
  return to;
}

ParamTable<GlassParams> make_table(const char* name, const char* doc, const GlassParams& defaults,
                                   void (*apply_preset)(GlassParams&, const std::string&)) {
  using G = GlassParams;
  return ParamTable<G>(name, doc, defaults)
      .action("preset", {"default", "seed"}, "default", apply_preset,
              "Resets every parameter but the pane's placement to a preset (seed = seed 003); "
              "reads back the last preset applied")
      .boolean("pane", &G::pane, "Draw the pane (off: only the scene's transmissive objects)")
      .vec3("center", &G::center, -1e4f, 1e4f, "m", "Centre of the pane")
      .vec2("size", &G::size, 0.01f, 1e4f, "m", "Width and height of the pane")
      .vec3("normal", &G::normal, -1.0f, 1.0f, "",
            "Direction the pane faces (normalised internally; (0,0,0): toward the eye)")
      .number("thickness", &G::thickness, 0.0f, 100.0f, "m",
              "Thickness of the pane's slab (0 = thin-walled: no lateral shift)")
      .number("ior", &G::ior, 1.0f, 3.0f, "", "Index of refraction (air outside: 1)")
      .number("dispersion", &G::dispersion, 0.0f, 20.0f, "",
              "20 / Abbe number: per-channel IOR (0 = none)")
      .number("roughness", &G::roughness, 0.0f, 1.0f, "",
              "Frosted transmission from the snapshot's blurred levels (0 = clear)")
      .color("tint", &G::tint, "Colour multiplying transmitted light (linear RGB)")
      .color("attenuation_color", &G::attenuation_color,
             "Colour of white light after attenuation_distance inside (Beer-Lambert)")
      .number("attenuation_distance", &G::attenuation_distance, 0.001f, 1e6f, "m",
              "Distance inside at which light takes attenuation_color")
      .number("refraction_scale", &G::refraction_scale, 0.0f, 1.0f, "",
              "Screen-space offset of the background per unit of normal-map slope (seed: 0.1)")
      .number("color_blend", &G::color_blend, 0.0f, 1.0f, "",
              "Blend toward the colour texture (seed: 0.5)")
      .texture("normal_map", &G::normal_map, "Normal map file (tangent space); \"\" = built-in")
      .texture("color_texture", &G::color_texture, "Colour texture file; \"\" = built-in")
      .number("texture_scale", &G::texture_scale, 0.01f, 1000.0f, "",
              "Texture tiles across the pane")
      .enumeration("fresnel", &G::fresnel, {"exact", "none"},
                   "Reflection weight: exact dielectric Fresnel, or none (seed 003)")
      .number("specular_power", &G::specular_power, 1.0f, 4096.0f, "",
              "Exponent of the sun highlight")
      .number("specular_intensity", &G::specular_intensity, 0.0f, 100.0f, "",
              "Strength of the sun highlight")
      .integer("max_layers", &G::max_layers, 1, 4, "",
               "Transmissive slabs one view ray passes through (stacked panes)")
      .enumeration("debug_view", &G::debug_view,
                   {"final", "transmission", "reflection", "fresnel", "offset"},
                   "What the surfaces show: final, transmission, reflection, fresnel, offset");
}

void glass_preset(GlassParams& p, const std::string& preset) {
  p = keep_placement(preset == "seed" ? glass_seed_preset(p) : GlassParams{}, p);
}

void ice_preset(GlassParams& p, const std::string& preset) {
  p = keep_placement(preset == "seed" ? glass_seed_preset(p) : ice_defaults(), p);
}

const ParamTable<GlassParams>& table(GlassKind kind) {
  static const ParamTable<GlassParams> glass =
      make_table("glass",
                 "Glass panes and glTF transmissive meshes: refraction from the scene snapshot, "
                 "lateral shift, Fresnel, roughness, dispersion, Beer-Lambert tint.",
                 GlassParams{}, glass_preset);
  static const ParamTable<GlassParams> ice =
      make_table("ice", "Ice: the glass effect with frost textures, IOR 1.31 and a blue tint.",
                 ice_defaults(), ice_preset);
  return kind == GlassKind::ice ? ice : glass;
}

} // namespace

GlassParams ice_defaults() {
  GlassParams p;
  p.thickness = 0.02f;
  p.ior = 1.31f;
  p.roughness = 0.15f;
  p.tint = glm::vec3(0.90f, 0.96f, 1.0f);
  p.attenuation_color = glm::vec3(0.80f, 0.92f, 1.0f);
  p.attenuation_distance = 0.5f;
  p.refraction_scale = 0.03f;
  p.color_blend = 0.3f;
  p.texture_scale = 1.5f;
  return p;
}

GlassParams glass_seed_preset(const GlassParams& base) {
  GlassParams p;
  p.thickness = 0.0f;
  p.fresnel = GlassFresnel::none;
  p.refraction_scale = 0.1f;
  p.color_blend = 0.5f;
  p.specular_intensity = 0.0f;
  return keep_placement(p, base);
}

const ParamSchema& glass_schema() {
  return table(GlassKind::glass).schema();
}

const ParamSchema& ice_schema() {
  return table(GlassKind::ice).schema();
}

namespace detail {

const ParamTable<GlassParams>& glass_table(GlassKind kind) {
  return table(kind);
}

} // namespace detail
} // namespace snell
