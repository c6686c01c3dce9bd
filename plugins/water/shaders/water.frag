#version 460
// Water surface: projective reflection and refraction lookups perturbed by scrolled normal-map
// ripples, depth-aware refraction (Beer-Lambert absorption along the view ray, soft shoreline,
// no leaking of geometry in front of the water), Fresnel blend and the sun's specular.
#extension GL_GOOGLE_include_directive : require
#include "snell/optics.glsl"
#include "snell/plane.glsl"
#include "water_common.glsl"

layout(location = 0) in vec3 in_world;
layout(location = 0) out vec4 out_color;

// World position of what the refraction pass saw at `uv`, and whether anything was there.
vec3 underwater_point(vec2 uv, out bool hit) {
  float d = textureLod(refraction_depth, uv, 0.0).r;
  hit = d < 1.0;
  vec4 p = water.refraction_inv_vp * vec4(uv * 2.0 - 1.0, d, 1.0);
  return p.xyz / p.w;
}

// The nearest of the four depth texels the bilinear colour lookup at `uv` blends: along one
// ray the projected depth grows with distance (also for an oblique projection), so the
// smallest depth is the nearest point any of the four texels shows.
vec3 nearest_point_in_footprint(vec2 uv, out bool hit) {
  vec4 d4 = textureGather(refraction_depth, uv, 0);
  float d = min(min(d4.x, d4.y), min(d4.z, d4.w));
  hit = d < 1.0;
  vec4 p = water.refraction_inv_vp * vec4(uv * 2.0 - 1.0, d, 1.0);
  return p.xyz / p.w;
}

void main() {
  vec3 p = in_world;
  float height = -water.plane.w;
  vec2 uv = gl_FragCoord.xy * water.extent.zw; // == project_to_uv(view_proj * p, vulkan)
  // Seen from below, the refraction pass holds the world above the water and the reflection
  // pass the underwater scene (total internal reflection beyond the critical angle).
  bool below = water.side.x < 0.0;

  // Soft shoreline: 0 where the water meets geometry, 1 from shore_softness metres of depth on.
  bool hit0;
  vec3 q0 = underwater_point(uv, hit0);
  float depth_below = hit0 ? max(height - q0.y, 0.0) : 1e4;
  float shore = water.absorption.a > 0.0 && !below
                    ? smoothstep(0.0, water.absorption.a, depth_below)
                    : 1.0;

  // Two normal-map layers scrolled along the wind at different scales hide the tiling. A
  // pattern moves with velocity w when its texture coordinate is (x - w t) / wave_length; the
  // second layer is scaled by 0.43, so its offset is scaled alike to keep its world speed.
  vec2 base = p.xz * water.wave.x;
  float t = water.wave.w * water.wave.x;
  vec3 n1 = texture(normal_map, base - water.wind.xy * t).xyz * 2.0 - 1.0;
  vec3 n2 = texture(normal_map, (base - water.wind.zw * t) * 0.43 + vec2(0.37, 0.11)).xyz * 2.0 - 1.0;
  vec2 slope = (n1.xy + n2.xy) * water.wave.y;
  // Tangent space: x = +x world, y (green, toward the image top = decreasing v) = -z world.
  vec3 n = normalize(vec3(slope.x, 1.0, -slope.y));
  // Near the shore the distortion fades out, so the refracted ground meets the real ground
  // without a seam.
  vec2 offset = slope * water.wave.z * shore;

  vec3 reflection = textureLod(reflection_tex, uv + offset, 0.0).rgb;

  // Refraction: a distorted sample that lands on something in front of the water (nearer the
  // eye than this surface point) falls back to the undistorted one. The test covers all four
  // texels the bilinear lookup blends, so an edge texel cannot bleed in either.
  float surface_distance = distance(water.eye.xyz, p);
  vec2 uv_r = uv + offset;
  bool near_hit;
  vec3 near_q = nearest_point_in_footprint(uv_r, near_hit);
  bool wrong_side = below ? near_q.y < height : near_q.y > height;
  if (near_hit && (distance(water.eye.xyz, near_q) < surface_distance || wrong_side)) {
    uv_r = uv;
  }
  bool hit;
  vec3 q = underwater_point(uv_r, hit);
  // Level 0: the snapshot has mips, and ripple offsets must not pick a blurred level.
  vec3 refraction = textureLod(refraction_tex, uv_r, 0.0).rgb;
  // Water along the view ray: below the surface point from above, between eye and surface
  // from below (there it also dims the reflection, applied after the blend).
  float thickness = below ? 0.0 : (hit ? distance(p, q) : 1e4);
  vec3 transmittance = exp(-water.absorption.rgb * thickness);
  vec3 refracted = refraction * transmittance + water.water_color.rgb * (1.0 - transmittance);

  vec3 v = normalize(water.eye.xyz - p);
  // The normal facing the eye, and eta = n(eye side) / n(other side).
  vec3 n_eye = below ? -n : n;
  float eta = below ? water.side.y : water.fresnel.y;
  float cos_v = max(dot(n_eye, v), 0.0);
  int mode = int(water.fresnel.x + 0.5);
  float f;
  if (mode == 0) {
    f = fresnel_dielectric(cos_v, eta); // 1 beyond the critical angle from below (Snell's window)
  } else if (mode == 1) {
    // Schlick takes the angle in the less dense medium: the transmitted one from below.
    float sin2_t = eta * eta * (1.0 - cos_v * cos_v);
    f = sin2_t >= 1.0 ? 1.0 : fresnel_schlick(below ? sqrt(1.0 - sin2_t) : cos_v, water.fresnel.z);
  } else if (mode == 2) {
    f = 1.0 - cos_v; // seed 001: lerp(reflection, refraction, dot(eye, normal))
  } else {
    f = water.side.z; // seed 000: lerp(reflection, refraction, 0.6), i.e. a constant 0.4
  }
  // A thin film over uneven ground does not mirror: reflection and highlight fade in with the
  // water depth too. The surface stays opaque, so the water never "disappears".
  f *= shore;
  vec3 color = mix(refracted, reflection, f);
  if (below) {
    vec3 t_eye = exp(-water.absorption.rgb * surface_distance);
    color = color * t_eye + water.water_color.rgb * (1.0 - t_eye);
  }
  color = mix(color, water.water_color.rgb, water.water_color.a);
  vec3 r = reflect(normalize(water.light_dir.xyz), n);
  float spec = below ? 0.0 : pow(max(dot(r, v), 0.0), water.light_color.a) * water.light_dir.w * shore;
  color += water.light_color.rgb * spec;

  int view = int(water.fresnel.w + 0.5);
  if (view == 1) {
    color = reflection;
  } else if (view == 2) {
    color = refraction;
  } else if (view == 3) {
    color = n * 0.5 + 0.5;
  } else if (view == 4) {
    color = vec3(f);
  }
  out_color = vec4(color, 1.0);
}
