#version 460
// GPU test kernel: evaluates every GLSL math mirror on one input record per invocation, so
// tests/gpu can compare the results with the C++ functions.
#extension GL_GOOGLE_include_directive : require
#include "snell/cube.glsl"
#include "snell/optics.glsl"
#include "snell/plane.glsl"
#include "snell/projective.glsl"

layout(local_size_x = 64) in;

struct Input {
  vec4 incident; // xyz incident direction
  vec4 normal;   // xyz normal, w = eta
  vec4 plane;    // plane (n, d)
  vec4 point;    // xyz point, w = cos_theta for Fresnel
  vec4 clip;     // clip position for project_to_uv
  vec4 misc;     // x = f0, y = face (as float), zw = uv for cube_to_direction
};
struct Output {
  vec4 refracted;   // xyz transmitted, w = 1 if refracted else 0
  vec4 fresnel;     // x exact, y schlick, z f0_from_ior(1, 1/eta), w signed_distance
  vec4 reflected;   // xyz reflect_point, w unused
  vec4 uv;          // xy vulkan, zw d3d
  vec4 uv_gl_cube;  // xy opengl, zw direction_to_cube(point.xyz) uv
  vec4 cube;        // x face of direction_to_cube, yzw cube_to_direction(face, uv)
  vec4 reflected_dir; // xyz reflect_direction(plane, incident)
};

layout(std430, set = 0, binding = 0) readonly buffer Inputs { Input inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Outputs { Output outputs[]; };
layout(push_constant) uniform Push { uint count; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) {
    return;
  }
  Input v = inputs[i];
  Output o;
  vec3 t;
  bool ok = refract(v.incident.xyz, v.normal.xyz, v.normal.w, t);
  o.refracted = vec4(t, ok ? 1.0 : 0.0);
  o.fresnel = vec4(fresnel_dielectric(v.point.w, v.normal.w), fresnel_schlick(v.point.w, v.misc.x),
                   f0_from_ior(1.0, 1.0 / v.normal.w), signed_distance(v.plane, v.point.xyz));
  o.reflected = vec4(reflect_point(v.plane, v.point.xyz), 0.0);
  o.uv = vec4(project_to_uv(v.clip, SNELL_CLIP_VULKAN), project_to_uv(v.clip, SNELL_CLIP_D3D));
  int face;
  vec2 cube_uv = direction_to_cube(v.point.xyz, face);
  o.uv_gl_cube = vec4(project_to_uv(v.clip, SNELL_CLIP_OPENGL), cube_uv);
  o.cube = vec4(float(face), cube_to_direction(int(v.misc.y), v.misc.zw));
  o.reflected_dir = vec4(reflect_direction(v.plane, v.incident.xyz), 0.0);
  outputs[i] = o;
}
