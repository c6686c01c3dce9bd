#version 460
// The mirror's surface: the reflection pass looked up where this pixel is (plus the normal
// map's distortion), blurred by roughness with contact hardening (the reflected point's height
// above the plane, from the pass's depth), faded with that height, times the metal tint or
// weighted by exact dielectric Fresnel over the base colour.
#extension GL_GOOGLE_include_directive : require
#include "snell/mirror.glsl"
#include "snell/optics.glsl"
#include "mirror_common.glsl"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
  if (mirror.eye.w > 0.5) { // seen from behind: the pass was skipped
    out_color = vec4(mirror.back_color.rgb, 1.0);
    return;
  }
  vec2 uv = gl_FragCoord.xy * mirror.extent.xy;
  if (kNormalMap) {
    vec2 slope = texture(normal_map, in_uv * mirror.distortion.y).xy * 2.0 - 1.0;
    uv += slope * mirror.distortion.x;
  }
  uv = clamp(uv, vec2(0.0), vec2(1.0));
  vec3 v = normalize(in_world - mirror.eye.xyz);
  float height = 0.0;
  if (kRough || kFade) {
    float depth = texture(reflection_depth, uv).r;
    vec4 p = mirror.inv_reflection * vec4(uv * 2.0 - 1.0, depth, 1.0);
    vec3 seen = p.xyz / p.w;
    // Nothing drawn there (depth 1): the sky, infinitely far.
    height = depth >= 1.0 ? 1e6 : max(dot(mirror.plane.xyz, seen) + mirror.plane.w, 0.0);
  }
  vec3 reflected;
  if (kRough) {
    float lod = mirror_blur_lod(mirror.tint.w, height, distance(mirror.eye.xyz, in_world),
                                mirror.extent.z, mirror.extent.w);
    reflected = textureLod(reflection, uv, lod).rgb;
  } else {
    reflected = textureLod(reflection, uv, 0.0).rgb;
  }
  float weight = 1.0;
  if (kDielectric) {
    weight = fresnel_dielectric(abs(dot(mirror.plane.xyz, v)), 1.0 / mirror.base_color.w);
  }
  if (kFade) {
    weight *= clamp(1.0 - height / mirror.back_color.w, 0.0, 1.0);
  }
  out_color = vec4(mix(mirror.base_color.rgb, mirror.tint.rgb * reflected, weight), 1.0);
}
