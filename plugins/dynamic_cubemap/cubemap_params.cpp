// The dynamic cube map's parameters, each declared once (schema, set, get, validation).
#include "cubemap_internal.hpp"

namespace snell {

const ParamSchema& dynamic_cubemap_schema() {
  return detail::cubemap_table().schema();
}

namespace detail {

const ParamTable<DynamicCubemapParams>& cubemap_table() {
  using C = DynamicCubemapParams;
  static const ParamTable<C> t =
      ParamTable<C>("dynamic_cubemap",
                    "A probe capturing the scene into a cube map; a mirror or glass sphere.")
          .vec3("center", &C::center, -1e4f, 1e4f, "m", "Where the capture is taken")
          .string("node", &C::node,
                  "Scene object the probe is attached to (\"\": its own sphere at center)")
          .number("radius", &C::radius, 0.01f, 1e4f, "m",
                  "Radius of the effect's own sphere (node \"\")")
          .integer("face_size", &C::face_size, 16, 2048, "px", "Width and height of a cube face")
          .number("z_near", &C::z_near, 0.001f, 100.0f, "m", "Near distance of the capture")
          .number("z_far", &C::z_far, 0.01f, 1e5f, "m", "Far distance of the capture")
          .enumeration("capture", &C::capture, {"multiview", "six_pass"},
                       "One multiview pass for the six faces, or six passes (seed 002)")
          .enumeration("refresh", &C::refresh,
                       {"every_frame", "every_n", "on_demand", "faces_per_frame"},
                       "When the capture is refreshed (a sliced cube is published whole)")
          .integer("refresh_n", &C::refresh_n, 1, 1000, "", "Frames between refreshes (every_n)")
          .integer("faces_per_frame", &C::faces_per_frame, 1, 6, "",
                   "Faces captured a frame (faces_per_frame)")
          .integer("capture_layers", &C::capture_layers, 0, 255, "",
                   "Objects drawn into the capture (snell::layer bits)")
          .enumeration("surface", &C::surface, {"reflect", "refract", "glass"},
                       "Mirror, refraction through a solid sphere, or both by Fresnel")
          .number("ior", &C::ior, 1.0f, 3.0f, "", "Index of refraction of the sphere")
          .number("dispersion", &C::dispersion, 0.0f, 2.0f, "",
                  "Per-channel IOR spread, 20 / Abbe number (refract, glass)")
          .enumeration("prefilter", &C::prefilter, {"none", "mips", "ggx"},
                       "Filtering for roughness: none, box mips, or GGX convolution (compute)")
          .number("roughness", &C::roughness, 0.0f, 1.0f, "",
                  "Roughness: reads level roughness x (levels - 1) of the filtered cube")
          .boolean("box_projection", &C::box_projection,
                   "Parallax-correct lookups inside the box box_min..box_max (a room)")
          .vec3("box_min", &C::box_min, -1e4f, 1e4f, "m", "Smallest corner of the room")
          .vec3("box_max", &C::box_max, -1e4f, 1e4f, "m", "Largest corner of the room")
          .color("tint", &C::tint, "Colour multiplying what the surface shows");
  return t;
}

} // namespace detail
} // namespace snell
