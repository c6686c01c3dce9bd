// Snell's gradient sky (snell::Sky): horizon to zenith above, horizon to ground below. Shared by
// the scene renderer and the effects that reflect the sky (glass), so both show the same sky.
#ifndef SNELL_SKY_GLSL
#define SNELL_SKY_GLSL

// The sky's linear colour in the unit direction `dir` (world, +Y up).
vec3 sky_gradient(vec3 dir, vec3 zenith, vec3 horizon, vec3 ground) {
  float y = dir.y;
  if (y >= 0.0) {
    return mix(horizon, zenith, pow(y, 0.6));
  }
  return mix(horizon, ground, pow(-y, 0.4));
}

#endif
