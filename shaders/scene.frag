#version 460
// Scene fragment shader: ambient + Lambert diffuse + Blinn-Phong specular, one directional
// light, base colour / normal / emissive textures, alpha mask. Outputs linear colour.
#extension GL_GOOGLE_include_directive : require
#include "scene_common.glsl"

layout(set = 1, binding = 0) uniform sampler2D base_color_tex;
layout(set = 1, binding = 1) uniform sampler2D normal_tex;
layout(set = 1, binding = 2) uniform sampler2D emissive_tex;

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_tangent;
layout(location = 3) in vec2 in_uv;

layout(location = 0) out vec4 out_color;

void main() {
  vec4 albedo = draw.base_color;
  if (draw.emissive.a > 0.5) {
    albedo *= texture(base_color_tex, in_uv);
  }
  if (draw.params.w >= 0.0 && albedo.a < draw.params.w) {
    discard;
  }
  vec3 n = normalize(in_normal);
  if (!gl_FrontFacing) {
    n = -n; // double-sided materials light their back faces
  }
  if (draw.flags.x > 0.5) {
    vec3 t = normalize(in_tangent.xyz - n * dot(n, in_tangent.xyz));
    vec3 b = cross(n, t) * in_tangent.w;
    vec3 m = texture(normal_tex, in_uv).xyz * 2.0 - 1.0;
    m.xy *= draw.params.z;
    n = normalize(mat3(t, b, n) * m);
  }
  vec3 l = normalize(-view_block.light_dir.xyz);
  vec3 v = normalize(view_block.eye.xyz - in_world);
  vec3 h = normalize(l + v);
  float roughness = clamp(draw.params.x, 0.02, 1.0);
  float shininess = max(2.0 / (roughness * roughness * roughness * roughness) - 2.0, 1.0);
  float ndl = max(dot(n, l), 0.0);
  // Normalised Blinn-Phong so that rough surfaces do not look brighter than smooth ones.
  float spec = draw.params.y * (shininess + 8.0) / 25.13274 * pow(max(dot(n, h), 0.0), shininess);
  vec3 light = view_block.light_color.rgb * view_block.light_dir.w;
  vec3 color = albedo.rgb * (view_block.ambient.rgb + light * ndl) + light * spec * ndl;
  color += draw.emissive.rgb * texture(emissive_tex, in_uv).rgb;
  out_color = vec4(color, albedo.a);
}
