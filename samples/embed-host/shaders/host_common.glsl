// The embed-host sample's push constants, shared by its scene and sky shaders (128 bytes, the
// minimum maxPushConstantsSize every Vulkan device guarantees). Mirrors HostScene::Push.
layout(push_constant) uniform Push {
  mat4 matrix;      // geometry: view_proj; sky: inverse(view_proj)
  vec4 clip_plane;  // world plane (n, d); only its positive side is drawn; (0,0,0,1) keeps all
  vec4 light_dir;   // xyz: direction the light travels (toward the scene)
  vec4 light_color; // rgb: colour * intensity
  vec4 ambient;     // rgb: ambient term
} pc;

// The sky: horizon to zenith above, horizon to a dusty ground colour below (linear RGB).
vec3 host_sky(vec3 dir) {
  const vec3 horizon = vec3(0.62, 0.74, 0.90);
  const vec3 zenith = vec3(0.16, 0.34, 0.72);
  const vec3 ground = vec3(0.30, 0.28, 0.25);
  return dir.y >= 0.0 ? mix(horizon, zenith, sqrt(dir.y)) : mix(horizon, ground, sqrt(-dir.y));
}
