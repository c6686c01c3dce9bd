// Snell math mirrors (GLSL): optics. Same names, conventions and edge cases as
// include/snell/math/optics.hpp; tests/gpu compares them with the C++ functions.
#ifndef SNELL_OPTICS_GLSL
#define SNELL_OPTICS_GLSL

// Vector Snell's law with eta = n1/n2. Returns false under total internal reflection (the
// C++ std::nullopt); `transmitted` is then vec3(0). `normal` faces the incident side.
bool refract(vec3 incident, vec3 normal, float eta, out vec3 transmitted) {
  float cos_i = dot(normal, incident);
  float k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
  if (k < 0.0) {
    transmitted = vec3(0.0);
    return false;
  }
  transmitted = eta * incident - (eta * cos_i + sqrt(k)) * normal;
  return true;
}

// Exact unpolarised dielectric Fresnel reflectance; |cos_theta_i| clamped to [0,1]; 1 under TIR.
float fresnel_dielectric(float cos_theta_i, float eta) {
  float cos_i = min(abs(cos_theta_i), 1.0);
  if (eta == 1.0) {
    return 0.0;
  }
  float sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) {
    return 1.0;
  }
  float cos_t = sqrt(1.0 - sin2_t);
  float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

// Schlick's approximation f0 + (1 - f0)(1 - cos)^5.
float fresnel_schlick(float cos_theta_i, float f0) {
  float m = 1.0 - min(abs(cos_theta_i), 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}

float f0_from_ior(float n1, float n2) {
  float r = (n1 - n2) / (n1 + n2);
  return r * r;
}

// Per-channel indices of refraction for dispersion (KHR_materials_dispersion: `dispersion` =
// 20 / Abbe number): (red, green, blue) = ior -/+ half of (ior - 1) dispersion / 20.
vec3 dispersion_iors(float ior, float dispersion) {
  float half_spread = (ior - 1.0) * dispersion * 0.025;
  return vec3(ior - half_spread, ior, ior + half_spread);
}

#endif
