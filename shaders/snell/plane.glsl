// Snell math mirrors (GLSL): planes as vec4(n, d) and mirroring (plane.hpp, reflection.hpp).
#ifndef SNELL_PLANE_GLSL
#define SNELL_PLANE_GLSL

// Signed distance of p to the plane (n, d): positive on the side n points to.
float signed_distance(vec4 plane, vec3 p) { return dot(plane.xyz, p) + plane.w; }

// Mirror image of the point p across the plane (normalised here; identity if degenerate).
vec3 reflect_point(vec4 plane, vec3 p) {
  float len2 = dot(plane.xyz, plane.xyz);
  if (!(len2 > 1e-20)) {
    return p;
  }
  vec4 n = plane * inversesqrt(len2);
  return p - 2.0 * signed_distance(n, p) * n.xyz;
}

// Mirror image of the direction v across the plane (translation ignored).
vec3 reflect_direction(vec4 plane, vec3 v) {
  float len2 = dot(plane.xyz, plane.xyz);
  if (!(len2 > 1e-20)) {
    return v;
  }
  vec3 n = plane.xyz * inversesqrt(len2);
  return v - 2.0 * dot(n, v) * n;
}

#endif
