// Shared by the glass shaders: the per-frame uniform block (std140 mirror of GlassBlock in
// glass.cpp), the per-draw push constants and the images.
#ifndef GLASS_COMMON_GLSL
#define GLASS_COMMON_GLSL

const int kMaxSurfaces = 64;

// One transmissive surface. Optics are per surface (the pane's from the parameters, a scene
// object's from its material). A "traced" surface is also a slab other surfaces can see
// through: a rectangle centre +- axis_u +- axis_v, thickness along the normal.
struct GlassSurface {
  vec4 center;      // xyz slab centre (world); w thickness in world units (0 = thin-walled)
  vec4 axis_u;      // xyz half-extent vector along the slab's width; w 1 = traced
  vec4 axis_v;      // xyz half-extent vector along its height; w ior
  vec4 normal;      // xyz unit normal of the slab; w roughness
  vec4 tint;        // rgb transmission tint (base colour); a transmission factor
  vec4 attenuation; // rgb attenuation colour; a attenuation distance (world units)
  vec4 params;      // x dispersion, y refraction_scale, z color_blend, w texture tiles (0 = none)
};

layout(set = 0, binding = 0, std140) uniform GlassBlock {
  mat4 view_proj;     // the main view
  mat4 inv_view_proj; // of the background images (snapshot or the effect's own pass)
  vec4 eye;           // xyz world eye
  vec4 extent;        // main view: width, height, 1/width, 1/height (pixels)
  vec4 light_dir;     // xyz direction the light travels; w specular intensity
  vec4 light_color;   // rgb light colour x intensity; w specular power
  vec4 ambient;       // rgb ambient light; w highest background mip level
  vec4 sky_zenith;    // rgb
  vec4 sky_horizon;   // rgb
  vec4 sky_ground;    // rgb
  vec4 mode;          // w log2 of the background's larger side (xyz unused)
  vec4 probe_center;  // the probe reflected (kProbe): xyz capture centre; w mip levels
  vec4 probe_box_min; // xyz room corner; w 1 = box projection
  vec4 probe_box_max; // xyz room corner
  GlassSurface surfaces[kMaxSurfaces];
} glass;

// Per draw: a second dynamic uniform block, not push constants. Mesa's lavapipe turns push
// constants into uniform block 0 and specialises (recompiles) a shader for the values of block-0
// data that steer its branches and loops, whenever they change: with the loop bounds and
// switches below as push constants a glass frame cost ~60 ms more at 1280x720 (measured).
// Pipeline variants: the effect builds one pipeline per combination of these it draws, and the
// branches on them are removed at pipeline creation. On lavapipe every branch of a shader costs
// whether it is taken or not (SIMD lanes under masks), so a clear thin pane must not pay for
// slabs, layers, textures, blur and dispersion it does not use. The defaults enable everything.
layout(constant_id = 0) const uint kFeatures = 0x1Fu;
layout(constant_id = 1) const uint kDebugView = 0u;    // GlassDebugView
layout(constant_id = 2) const uint kFresnelExact = 1u; // 0: fresnel = none
const uint kShift = 1u;      // some surface has a volume (thickness > 0)
const uint kLayers = 2u;     // rays may cross other surfaces (more than one, max_layers > 1)
const uint kTextured = 4u;   // a normal-map offset or colour texture
const uint kRough = 8u;      // blurred background levels
const uint kDispersion = 16u; // per-channel IOR
const uint kProbe = 32u;      // reflections from a probe's cube (ProbeDirectory), not the sky

bool has(uint feature) {
  return (kFeatures & feature) != 0u;
}

layout(set = 0, binding = 5, std140) uniform GlassDraw {
  mat4 model;   // object to world
  uvec4 index;  // x index into glass.surfaces, y number of surfaces, z layers (max_layers; 1
                // when the surface is alone), w unused
  // This draw's own surface, a copy of glass.surfaces[index.x]: read at constant offsets, which
  // llvmpipe loads once per draw instead of gathering per pixel as it does for a dynamic index.
  GlassSurface self;
} draw;

layout(set = 0, binding = 1) uniform sampler2D background;       // opaque colour (mips)
layout(set = 0, binding = 2) uniform sampler2D background_depth; // its depth (nearest)
layout(set = 0, binding = 3) uniform sampler2D normal_map;       // pane: tangent-space normals
layout(set = 0, binding = 4) uniform sampler2D color_map;        // pane: colour texture (sRGB)
layout(set = 0, binding = 6) uniform samplerCube probe_cube;     // kProbe: the nearest probe

#endif
