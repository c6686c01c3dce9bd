// Snell math mirrors (GLSL): cube-map faces in Vulkan layer order (include/snell/math/cube.hpp).
#ifndef SNELL_CUBE_GLSL
#define SNELL_CUBE_GLSL

// Face (0..5 = +X,-X,+Y,-Y,+Z,-Z) and uv of a direction, by the Vulkan face-selection table;
// ties go to X, then Y, then Z; the zero vector gives the centre of +X.
vec2 direction_to_cube(vec3 dir, out int face) {
  vec3 a = abs(dir);
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    ma = a.x;
    face = dir.x >= 0.0 ? 0 : 1;
    sc = dir.x >= 0.0 ? -dir.z : dir.z;
    tc = -dir.y;
  } else if (a.y >= a.z) {
    ma = a.y;
    face = dir.y >= 0.0 ? 2 : 3;
    sc = dir.x;
    tc = dir.y >= 0.0 ? dir.z : -dir.z;
  } else {
    ma = a.z;
    face = dir.z >= 0.0 ? 4 : 5;
    sc = dir.z >= 0.0 ? dir.x : -dir.x;
    tc = -dir.y;
  }
  if (!(ma > 0.0)) {
    face = 0;
    return vec2(0.5);
  }
  return vec2(0.5 * sc / ma + 0.5, 0.5 * tc / ma + 0.5);
}

// The unit direction that samples uv on face (the inverse of direction_to_cube).
vec3 cube_to_direction(int face, vec2 uv) {
  float sc = 2.0 * uv.x - 1.0;
  float tc = 2.0 * uv.y - 1.0;
  vec3 d;
  if (face == 0) {
    d = vec3(1.0, -tc, -sc);
  } else if (face == 1) {
    d = vec3(-1.0, -tc, sc);
  } else if (face == 2) {
    d = vec3(sc, 1.0, tc);
  } else if (face == 3) {
    d = vec3(sc, -1.0, -tc);
  } else if (face == 4) {
    d = vec3(sc, -tc, 1.0);
  } else {
    d = vec3(-sc, -tc, -1.0);
  }
  return normalize(d);
}

#endif
