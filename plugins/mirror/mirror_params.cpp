// The mirror's parameters, each declared once (schema, set, get, validation).
#include "mirror_internal.hpp"

namespace snell {

const ParamSchema& mirror_schema() {
  return detail::mirror_table().schema();
}

namespace detail {

const ParamTable<MirrorParams>& mirror_table() {
  using M = MirrorParams;
  static const ParamTable<M> t =
      ParamTable<M>("mirror", "A planar mirror: the scene from the mirrored camera, clipped at "
                              "the plane; tint or Fresnel, contact-hardening roughness.")
          .string("node", &M::node, "Scene object whose mesh is the mirror (\"\": a rectangle)")
          .vec3("center", &M::center, -1e4f, 1e4f, "m", "Centre of the rectangle")
          .vec3("normal", &M::normal, -1.0f, 1.0f, "",
                "Side the rectangle reflects ((0,0,0): toward the eye)")
          .vec3("up", &M::up, -1.0f, 1.0f, "", "The rectangle's up, projected onto its plane")
          .vec2("size", &M::size, 0.01f, 1e4f, "m", "Width and height of the rectangle")
          .number("resolution_scale", &M::resolution_scale, 0.1f, 2.0f, "",
                  "Reflection target size relative to the output")
          .enumeration("clip", &M::clip, {"oblique", "clip_distance"},
                       "How the pass keeps what is in front of the plane")
          .integer("reflection_layers", &M::reflection_layers, 0, 255, "",
                   "Objects drawn in the reflection (snell::layer bits)")
          .color("tint", &M::tint, "Reflectance per channel (a metal's colour)")
          .enumeration("fresnel", &M::fresnel, {"none", "dielectric"},
                       "Metal (none) or exact dielectric Fresnel with ior over base_color")
          .number("ior", &M::ior, 1.0f, 3.0f, "", "Index of refraction (fresnel = dielectric)")
          .color("base_color", &M::base_color, "Colour under the reflection, and faded to")
          .number("roughness", &M::roughness, 0.0f, 1.0f, "",
                  "Blur growing with roughness^2 and the height above the mirror")
          .number("fade_distance", &M::fade_distance, 0.0f, 1e4f, "m",
                  "Height above the mirror where the reflection has faded out (0: never)")
          .texture("normal_map", &M::normal_map,
                   "Normal map distorting the reflection (\"\": none)")
          .number("distortion", &M::distortion, 0.0f, 0.2f, "",
                  "Lookup offset (uv) per unit of normal-map slope")
          .number("normal_tiles", &M::normal_tiles, 0.01f, 1000.0f, "",
                  "Normal-map tiles per unit of the mesh's uv (a rectangle: across it)")
          .color("back_color", &M::back_color, "Colour of the mirror's back");
  return t;
}

} // namespace detail
} // namespace snell
