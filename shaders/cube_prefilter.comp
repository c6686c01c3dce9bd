// GGX prefilter of a cube map (snell/toolkit/cube_prefilter.hpp): one destination level per
// dispatch, one invocation per destination texel, gl_GlobalInvocationID.z = face (Vulkan layer
// order). Split-sum radiance with N = V = R: the sum over GGX samples L around the texel's
// direction N of source(L) * NoL, divided by the sum of NoL.
//
// Everything that is the same for every texel of a level is precomputed on the CPU into the
// level's sample table (src/toolkit/cube_prefilter.cpp): per sample the tangent-space direction
// divided by its z (so the world direction is T * x + B * y + N: a cube lookup ignores the
// length), the normalised weight NoL / sum(NoL), and the source mip chosen by filtered importance
// sampling. The loop count is a specialization constant and no branch depends on the texel, so
// lavapipe compiles one straight loop per pipeline.
#version 450

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// Samples per texel (CubePrefilter builds one pipeline per count it uses).
layout(constant_id = 0) const uint kSamples = 32u;

layout(set = 0, binding = 0) uniform samplerCube source_cube;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2DArray destination;
layout(set = 0, binding = 2, std140) uniform SampleTable {
  // x, y: tangent-space direction over its z; z: weight (sums to 1); w: source lod.
  vec4 samples[kSamples];
};

// Face f's direction at face coordinates (s, t) in [-1, 1]: forward + s * right + t * down, the
// inverse of direction_to_cube (shaders/snell/cube.glsl) without a branch on the face.
const vec3 kForward[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
                                 vec3(0, 0, 1), vec3(0, 0, -1));
const vec3 kRight[6] = vec3[6](vec3(0, 0, -1), vec3(0, 0, 1), vec3(1, 0, 0), vec3(1, 0, 0),
                               vec3(1, 0, 0), vec3(-1, 0, 0));
const vec3 kDown[6] = vec3[6](vec3(0, -1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1),
                              vec3(0, -1, 0), vec3(0, -1, 0));

void main() {
  const ivec3 id = ivec3(gl_GlobalInvocationID);
  const ivec2 size = imageSize(destination).xy;
  if (id.x >= size.x || id.y >= size.y) {
    return; // only in the last groups of levels not a multiple of 8 wide
  }
  const vec2 st = (vec2(id.xy) + 0.5) / vec2(size) * 2.0 - 1.0;
  const vec3 n = normalize(kForward[id.z] + st.x * kRight[id.z] + st.y * kDown[id.z]);
  // Orthonormal basis around n without a branch (Duff et al. 2017, "Building an Orthonormal
  // Basis, Revisited").
  const float sgn = 2.0 * step(0.0, n.z) - 1.0;
  const float a = -1.0 / (sgn + n.z);
  const float b = n.x * n.y * a;
  const vec3 t = vec3(1.0 + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  const vec3 bt = vec3(b, sgn + n.y * n.y * a, -n.y);
  vec4 sum = vec4(0.0);
  for (uint i = 0u; i < kSamples; ++i) {
    const vec4 s = samples[i];
    sum += s.z * textureLod(source_cube, t * s.x + bt * s.y + n, s.w);
  }
  imageStore(destination, id, sum);
}
