// Internal: vertex-attribute generation and validation (see mesh_utils.hpp).
//
// Face normals and tangent frames are computed in double precision: products of differences of
// float positions overflow a float as soon as coordinates reach about 1e19, while in double they
// are exact enough for any finite float input, so even absurd (but finite) files get unit normals.
#include "mesh_utils.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace snell::detail {
namespace {

bool finite(glm::vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}
bool finite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(glm::vec4 v) {
  return finite(glm::vec3(v)) && std::isfinite(v.w);
}

bool triangle_in_range(const std::vector<std::uint32_t>& indices, std::size_t first,
                       std::size_t vertex_count) {
  return indices[first] < vertex_count && indices[first + 1] < vertex_count &&
         indices[first + 2] < vertex_count;
}

// Unit direction of a double vector, scaled first so that squaring cannot overflow.
std::optional<glm::dvec3> safe_normalize(glm::dvec3 v) {
  if (!finite(v)) {
    return std::nullopt;
  }
  const double m = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
  if (!(m > 0.0)) {
    return std::nullopt;
  }
  const glm::dvec3 w = v / m;
  return w / std::sqrt(glm::dot(w, w));
}

glm::vec3 normalized_or(glm::dvec3 v, glm::vec3 fallback) {
  const std::optional<glm::dvec3> n = safe_normalize(v);
  return n ? glm::vec3(*n) : fallback;
}

glm::dvec3 position(const std::vector<Vertex>& vertices, std::uint32_t i) {
  return glm::dvec3(vertices[i].position);
}

// Twice the area times the unit normal of triangle (a, b, c), counter-clockwise = front.
glm::dvec3 face_vector(const std::vector<Vertex>& v, std::uint32_t a, std::uint32_t b,
                       std::uint32_t c) {
  return glm::cross(position(v, b) - position(v, a), position(v, c) - position(v, a));
}

} // namespace

std::optional<glm::vec3> safe_normalize(glm::vec3 v) {
  const std::optional<glm::dvec3> n = safe_normalize(glm::dvec3(v));
  if (!n) {
    return std::nullopt;
  }
  return glm::vec3(*n);
}

glm::vec3 any_perpendicular(glm::vec3 n) {
  // Cross with the coordinate axis least aligned with n, so the result is never near zero.
  const glm::vec3 a = glm::abs(n);
  const glm::dvec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::dvec3(1, 0, 0)
                          : (a.y <= a.z)             ? glm::dvec3(0, 1, 0)
                                                     : glm::dvec3(0, 0, 1);
  return normalized_or(glm::cross(glm::dvec3(n), axis), glm::vec3(1, 0, 0));
}

void generate_flat_or_smooth_normals(std::vector<Vertex>& vertices,
                                     std::vector<std::uint32_t>& indices, NormalMode mode) {
  const std::size_t triangle_count = indices.size() / 3;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  if (mode == NormalMode::flat) {
    std::vector<Vertex> flat;
    flat.reserve(triangle_count * 3);
    for (std::size_t t = 0; t < triangle_count; ++t) {
      if (!triangle_in_range(indices, 3 * t, vertices.size())) {
        continue;
      }
      const std::uint32_t* tri = &indices[3 * t];
      const glm::vec3 n = normalized_or(face_vector(vertices, tri[0], tri[1], tri[2]), up);
      for (int k = 0; k < 3; ++k) {
        flat.push_back(vertices[tri[k]]);
        flat.back().normal = n;
      }
    }
    vertices = std::move(flat);
    indices.resize(vertices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
      indices[i] = static_cast<std::uint32_t>(i);
    }
    return;
  }

  std::vector<glm::dvec3> sum(vertices.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t < triangle_count; ++t) {
    if (!triangle_in_range(indices, 3 * t, vertices.size())) {
      continue;
    }
    const std::uint32_t* tri = &indices[3 * t];
    // The unnormalised cross product's length is twice the triangle's area: summing it weights
    // every face by its area, so slivers at a seam do not skew the result.
    const glm::dvec3 face = face_vector(vertices, tri[0], tri[1], tri[2]);
    for (int k = 0; k < 3; ++k) {
      sum[tri[k]] += face;
    }
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i].normal = normalized_or(sum[i], up);
  }
}

void generate_tangents(std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices) {
  std::vector<glm::dvec3> tan_sum(vertices.size(), glm::dvec3(0.0));
  std::vector<glm::dvec3> up_sum(vertices.size(), glm::dvec3(0.0)); // direction of decreasing v
  const std::size_t triangle_count = indices.size() / 3;
  for (std::size_t t = 0; t < triangle_count; ++t) {
    if (!triangle_in_range(indices, 3 * t, vertices.size())) {
      continue;
    }
    const std::uint32_t i0 = indices[3 * t], i1 = indices[3 * t + 1], i2 = indices[3 * t + 2];
    const glm::dvec3 e1 = position(vertices, i1) - position(vertices, i0);
    const glm::dvec3 e2 = position(vertices, i2) - position(vertices, i0);
    const glm::dvec2 d1 = glm::dvec2(vertices[i1].uv) - glm::dvec2(vertices[i0].uv);
    const glm::dvec2 d2 = glm::dvec2(vertices[i2].uv) - glm::dvec2(vertices[i0].uv);
    const double det = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(det) || det == 0.0) {
      continue; // Degenerate UVs: this triangle says nothing about the tangent frame.
    }
    // Solve [e1 e2] = [T B] [d1 d2] for T = dP/du and B = dP/dv (Lengyel). Each triangle's
    // contribution is scaled by |det| (its UV area) relative to the plain solution, so small UV
    // islands at seams do not dominate.
    const double sign = det > 0.0 ? 1.0 : -1.0;
    const glm::dvec3 dp_du = (e1 * d2.y - e2 * d1.y) * sign;
    const glm::dvec3 dp_dv = (e2 * d1.x - e1 * d2.x) * sign;
    if (!finite(dp_du) || !finite(dp_dv)) {
      continue;
    }
    for (const std::uint32_t i : {i0, i1, i2}) {
      tan_sum[i] += dp_du;
      up_sum[i] -= dp_dv;
    }
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    Vertex& v = vertices[i];
    const glm::dvec3 n = safe_normalize(glm::dvec3(v.normal)).value_or(glm::dvec3(0, 1, 0));
    const glm::vec3 fallback = any_perpendicular(glm::vec3(n));
    // Gram-Schmidt on the unit direction (the sums may be huge or tiny), with a fallback when it
    // is (nearly) parallel to the normal: what remains after removing the normal part would be
    // rounding noise.
    const std::optional<glm::dvec3> sum_dir = safe_normalize(tan_sum[i]);
    const glm::dvec3 t = sum_dir ? *sum_dir - n * glm::dot(n, *sum_dir) : glm::dvec3(0.0);
    const std::optional<glm::dvec3> t_dir = safe_normalize(t);
    if (!t_dir || glm::dot(t, t) < 1e-8) {
      v.tangent = glm::vec4(fallback, 1.0f);
      continue;
    }
    const double handedness = glm::dot(glm::cross(n, *t_dir), up_sum[i]);
    v.tangent = glm::vec4(glm::vec3(*t_dir), handedness < 0.0 ? -1.0f : 1.0f);
  }
}

std::optional<std::size_t> first_non_finite_position(const std::vector<Vertex>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!finite(v[i].position)) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> first_non_finite_vertex(const std::vector<Vertex>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!finite(v[i].position) || !finite(v[i].normal) || !finite(v[i].tangent) ||
        !finite(v[i].uv)) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> first_index_out_of_range(const std::vector<std::uint32_t>& indices,
                                                    std::size_t vertex_count) {
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= vertex_count) {
      return i;
    }
  }
  return std::nullopt;
}

} // namespace snell::detail
