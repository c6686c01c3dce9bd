#version 460
// A transmissive surface: what is behind it from the background images (the scene snapshot),
// displaced by the lateral shift of its slab (exact for a slab: the ray leaves parallel to where
// it came from) and by the normal map (seed 003), blurred by roughness, tinted (Beer-Lambert),
// per-channel IOR for dispersion, exact dielectric Fresnel against the reflected sky and sun.
// Slabs behind it (the effect's other flat surfaces) are traced analytically, so a pane seen
// through a pane stays visible although the snapshot holds neither.
#extension GL_GOOGLE_include_directive : require
#include "snell/optics.glsl"
#include "snell/probe.glsl"
#include "snell/sky.glsl"
#include "glass_common.glsl"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

const int kDebugFinal = 0, kDebugTransmission = 1, kDebugReflection = 2, kDebugFresnel = 3,
          kDebugOffset = 4;

// The world point the background images show at `uv`; `sky`: nothing there (depth 1).
vec3 background_point(vec2 uv, out bool sky) {
  float d = textureLod(background_depth, uv, 0.0).r;
  sky = d >= 1.0;
  vec4 p = glass.inv_view_proj * vec4(uv * 2.0 - 1.0, d, 1.0);
  return p.xyz / p.w;
}

// Texture coordinate of the main view (and of the background images) where `p` projects.
vec2 screen_uv(vec3 p) {
  vec4 c = glass.view_proj * vec4(p, 1.0);
  return c.xy / max(c.w, 1e-6) * 0.5 + 0.5;
}

// Where the line o + s d (s >= 0) meets the opaque scene of the background images: the fixed
// point of s <- (distance along d of the point shown where o + s d projects), from `s`. For a
// surface not seen edge-on it converges in a few steps to the exact intersection. `s_hit` < 0:
// the point found is in front of `o` (an occluder), so the caller must not use it. The sky is at
// infinity: its direction alone decides where it shows.
vec2 trace_background(vec3 o, vec3 d, float s, out float s_hit) {
  vec2 uv = screen_uv(o + d * s);
  for (int k = 0; k < 4; ++k) {
    bool sky;
    vec3 w = background_point(clamp(uv, 0.0, 1.0), sky);
    if (sky) {
      s_hit = 1e6;
      return screen_uv(o + d * 1e6);
    }
    s = dot(w - o, d);
    uv = screen_uv(o + d * max(s, 0.0));
  }
  s_hit = s;
  return uv;
}

// What one transmissive surface does to a ray crossing it: out = add + mul * (light behind).
struct Crossing {
  vec3 add;       // reflection, highlight, diffuse remainder, colour texture
  vec3 mul;       // transmitted fraction (1 - F, transmission, tint, absorption, texture blend)
  vec3 exit;      // where the ray leaves the surface's volume
  vec3 dir;       // the direction it leaves in (a slab: the incident direction)
  float fresnel;  // F
  vec3 reflected; // sky + sun along the mirror direction (not weighted)
  vec3 transmit;  // tint x absorption (not weighted)
};

// Crossing of surface `s` at `p` with unit normal `n` facing the ray `v`, refractive index
// `ior`, colour texture `tex` (a = 0: none).
Crossing cross_surface(GlassSurface s, vec3 p, vec3 n, vec3 v, float ior, vec4 tex) {
  Crossing c;
  float eta = 1.0 / ior;
  float cos_i = clamp(-dot(n, v), 0.0, 1.0);
  vec3 t;
  refract(v, n, eta, t); // from air into a denser medium: never total internal reflection
  float thickness = s.center.w;
  vec3 absorb = vec3(1.0);
  c.exit = p;
  c.dir = v;
  if (has(kShift) && thickness > 0.0) {
    float cos_t = max(-dot(n, t), 1e-4);
    float path;
    if (s.axis_u.w > 0.5) {
      // A slab: the far face is parallel, so the ray leaves parallel to v, shifted sideways by
      // thickness * sin(ti - tt) / cos(tt).
      path = thickness / cos_t;
      c.exit = p + t * path;
    } else {
      // A curved solid: a sphere of diameter `thickness` touching the surface at p. The chord
      // along t is thickness * cos(tt); the ray leaves through the sphere's far side, refracted
      // back into air there (never totally reflected: the chord meets both sides at tt).
      path = thickness * cos_t;
      c.exit = p + t * path;
      vec3 out_n = normalize(c.exit - (p - n * (0.5 * thickness)));
      vec3 d;
      c.dir = refract(t, -out_n, ior, d) ? d : t;
    }
    absorb = pow(s.attenuation.rgb, vec3(path / s.attenuation.a));
  }
  c.fresnel = kFresnelExact != 0u ? fresnel_dielectric(cos_i, eta) : 0.0;
  vec3 r = reflect(v, n);
  float highlight = pow(max(dot(r, -glass.light_dir.xyz), 0.0), glass.light_color.w);
  vec3 environment;
  if (has(kProbe)) { // the scene around, as the nearest probe captured it
    vec3 dir = r;
    if (glass.probe_box_min.w > 0.5) {
      dir = probe_box_direction(p, r, glass.probe_center.xyz, glass.probe_box_min.xyz,
                                glass.probe_box_max.xyz);
    }
    environment = probe_lookup(probe_cube, dir, s.normal.w, glass.probe_center.w);
  } else {
    environment = sky_gradient(r, glass.sky_zenith.rgb, glass.sky_horizon.rgb, glass.sky_ground.rgb);
  }
  c.reflected = environment + highlight * glass.light_dir.w * glass.light_color.rgb;
  c.transmit = s.tint.rgb * absorb;
  // KHR_materials_transmission: the untransmitted part is the base colour, lit diffusely.
  float transmission = s.tint.a;
  vec3 diffuse = s.tint.rgb * (glass.ambient.rgb +
                               glass.light_color.rgb * max(dot(n, -glass.light_dir.xyz), 0.0));
  float f = c.fresnel;
  c.add = f * c.reflected + (1.0 - f) * (1.0 - transmission) * diffuse;
  c.mul = (1.0 - f) * transmission * c.transmit;
  if ((has(kTextured) || has(kLayers)) && tex.a > 0.0) { // seed 003: lerp(refraction, colour texture, color_blend)
    float blend = s.params.z;
    c.add = mix(c.add, tex.rgb, blend);
    c.mul *= 1.0 - blend;
  }
  return c;
}

// Mip level of the blurred background for a surface of `roughness` and `ior`: the whole image
// at roughness 1 for ior >= 1.5, nothing for a clear or index-matched surface.
float blur_level(float roughness, float ior) {
  return glass.mode.w * roughness * clamp(2.0 * ior - 2.0, 0.0, 1.0);
}

// Where the ray o + s d enters the traced slab `j` (its face toward the ray) at distance `s`,
// with that face's normal `face_n`; false when it misses the rectangle or lies behind o.
bool hit_slab(int j, vec3 o, vec3 d, out float s, out vec3 face_n, out vec2 local) {
  GlassSurface g = glass.surfaces[j];
  s = 0.0;
  face_n = vec3(0.0);
  local = vec2(0.0);
  if (g.axis_u.w < 0.5) {
    return false;
  }
  float dn = dot(d, g.normal.xyz);
  if (abs(dn) < 1e-5) {
    return false;
  }
  face_n = dn < 0.0 ? g.normal.xyz : -g.normal.xyz;
  vec3 face_c = g.center.xyz + face_n * (0.5 * g.center.w);
  s = dot(face_c - o, face_n) / dot(d, face_n);
  if (s <= 1e-4) {
    return false;
  }
  vec3 q = o + d * s - face_c;
  local = vec2(dot(q, g.axis_u.xyz) / dot(g.axis_u.xyz, g.axis_u.xyz),
               dot(q, g.axis_v.xyz) / dot(g.axis_v.xyz, g.axis_v.xyz));
  return abs(local.x) <= 1.0 && abs(local.y) <= 1.0;
}

// Colour texture of a textured pane at texture coordinate `uv` (a = 0 when untextured).
vec4 pane_texture(GlassSurface s, vec2 uv) {
  return (has(kTextured) || has(kLayers)) && s.params.w > 0.0 ? vec4(texture(color_map, uv * s.params.w).rgb, 1.0) : vec4(0.0);
}

// The light reaching the eye through this fragment for refractive index `ior` (one call per
// channel with dispersion).
vec3 radiance(GlassSurface s, vec3 n, vec3 v, float ior, vec2 offset, vec4 tex, vec2 uv0) {
  const int debug_view = int(kDebugView);
  Crossing first = cross_surface(s, in_world, n, v, ior, tex);
  if (debug_view == kDebugReflection) {
    return first.reflected;
  }
  if (debug_view == kDebugFresnel) {
    return vec3(first.fresnel);
  }
  vec3 accum = debug_view == kDebugTransmission ? vec3(0.0) : first.add;
  vec3 through = debug_view == kDebugTransmission ? first.transmit : first.mul;
  float lod = has(kRough) ? blur_level(s.normal.w, ior) : 0.0;

  vec2 uv = uv0;
  if (has(kShift) || has(kLayers)) {
    // Unshifted: what the pixel itself shows behind the surface (always behind it: the surface
    // passed the depth test against it). The fallback when a shifted lookup finds an occluder.
    bool sky0;
    vec3 w0 = background_point(uv0, sky0);
    vec3 o = first.exit;
    vec3 d = first.dir;
    float s_hit = sky0 ? 1e6 : dot(w0 - o, d);
    // The cheapest lookup is the one not made: a ray that moved less than a quarter pixel on
    // screen sees the pixel itself.
    vec2 moved = (screen_uv(o + d * max(s_hit, 0.0)) - uv0) * glass.extent.xy;
    if (has(kShift) && dot(moved, moved) > 0.0625) {
      uv = trace_background(o, d, max(s_hit, 0.0), s_hit);
      if (s_hit < 0.0) {
        uv = uv0;
        s_hit = sky0 ? 1e6 : dot(w0 - o, d);
      }
    }

    // Slabs behind this one, nearest first, up to max_layers surfaces in all.
    if (has(kLayers)) {
      int current = int(draw.index.x);
      int count = int(draw.index.y);
      for (uint layer = 1u; layer < draw.index.z; ++layer) {
        int best = -1;
        float best_s = s_hit;
        vec3 best_n = vec3(0.0);
        vec2 best_local = vec2(0.0);
        for (int j = 0; j < count; ++j) {
          float sj;
          vec3 nj;
          vec2 lj;
          if (j != current && hit_slab(j, o, d, sj, nj, lj) && sj < best_s) {
            best = j;
            best_s = sj;
            best_n = nj;
            best_local = lj;
          }
        }
        if (best < 0) {
          break;
        }
        GlassSurface g = glass.surfaces[best];
        vec2 g_uv = vec2(best_local.x * 0.5 + 0.5, 0.5 - best_local.y * 0.5);
        Crossing c = cross_surface(g, o + d * best_s, best_n, d, g.axis_v.w, pane_texture(g, g_uv));
        accum += through * c.add;
        through *= c.mul;
        lod = max(lod, blur_level(g.normal.w, g.axis_v.w));
        float before = s_hit - best_s;
        o = c.exit;
        d = c.dir;
        current = best;
        uv = trace_background(o, d, max(before, 0.0), s_hit);
        if (s_hit < 0.0) {
          s_hit = 0.0; // an occluder inside the stack: keep the last lookup
        }
      }
    }
  }

  // The seed's normal-map offset, unless it lands on something in front of the surface.
  vec2 uv_final = uv;
  if (has(kTextured) && offset != vec2(0.0)) {
    uv_final += offset;
    bool sky_f;
    vec3 wf = background_point(clamp(uv_final, 0.0, 1.0), sky_f);
    if (!sky_f && dot(wf - in_world, v) < 0.0) {
      uv_final = uv;
    }
  }
  if (debug_view == kDebugOffset) {
    return vec3(0.5 + 10.0 * (uv_final - uv0), 0.5);
  }
  vec2 at = clamp(uv_final, 0.0, 1.0);
  // A constant level 0 keeps llvmpipe on its fast path when nothing is blurred.
  vec3 behind = has(kRough) ? textureLod(background, at, min(lod, glass.ambient.w)).rgb
                            : textureLod(background, at, 0.0).rgb;
  return accum + through * behind;
}

void main() {
  GlassSurface s = draw.self;
  vec3 v = normalize(in_world - glass.eye.xyz);
  vec3 n = normalize(in_normal);
  if (dot(n, v) > 0.0) {
    n = -n; // the side toward the eye (thin-walled surfaces are seen from both sides)
  }
  vec2 uv0 = gl_FragCoord.xy * glass.extent.zw;
  vec2 offset = vec2(0.0);
  vec4 tex = vec4(0.0);
  if (has(kTextured) && s.params.w > 0.0) {
    vec3 bump = texture(normal_map, in_uv * s.params.w).xyz * 2.0 - 1.0;
    offset = bump.xy * s.params.y;
    tex = pane_texture(s, in_uv);
  }
  float ior = s.axis_v.w;
  vec3 color;
  if (has(kDispersion) && s.params.x > 0.0) {
    // KHR_materials_dispersion: red below, blue above the base IOR.
    vec3 iors = dispersion_iors(ior, s.params.x);
    color.r = radiance(s, n, v, iors.r, offset, tex, uv0).r;
    color.g = radiance(s, n, v, iors.g, offset, tex, uv0).g;
    color.b = radiance(s, n, v, iors.b, offset, tex, uv0).b;
  } else {
    color = radiance(s, n, v, ior, offset, tex, uv0);
  }
  out_color = vec4(color, 1.0);
}
