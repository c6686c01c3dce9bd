// The embed-host sample's chrome material: its push constants (per view) and its descriptor set
// (the probe's cube and a small uniform block, per frame slot). Mirrors HostScene's ChromePush
// and ChromeBlock.
layout(push_constant) uniform ChromePush {
  mat4 matrix;     // view_proj of the view being drawn (main, mirrored, oblique, ...)
  vec4 clip_plane; // world plane (n, d); only its positive side is drawn; (0,0,0,1) keeps all
  vec4 eye;        // xyz: the view's world-space eye (the mirrored eye in a reflection)
} pc;

// Binding 0: the probe's cube (snell::ProbeView::cube + ::sampler), SHADER_READ_ONLY_OPTIMAL.
layout(set = 0, binding = 0) uniform samplerCube probe_cube;
// Binding 1: how to look it up (snell::ProbeView) and the metal's reflectance.
layout(set = 0, binding = 1, std140) uniform ChromeBlock {
  vec4 center_levels; // xyz: where the cube was captured; w: its mip levels
  vec4 box_min;       // xyz: the probe's box; w: 1 when lookups are box-projected
  vec4 box_max;       // xyz
  vec4 f0_roughness;  // rgb: reflectance at normal incidence (linear); a: roughness [0, 1]
} chrome;
