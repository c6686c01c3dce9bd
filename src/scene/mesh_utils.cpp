// Internal: vertex-attribute generation and validation (see mesh_utils.hpp).
#include "mesh_utils.hpp"

#include <glm/geometric.hpp>

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
bool finite(glm::vec4 v) {
  return finite(glm::vec3(v)) && std::isfinite(v.w);
}

bool triangle_in_range(const std::vector<std::uint32_t>& indices, std::size_t first,
                       std::size_t vertex_count) {
  return indices[first] < vertex_count && indices[first + 1] < vertex_count &&
         indices[first + 2] < vertex_count;
}

glm::vec3 normalized_or(glm::vec3 v, glm::vec3 fallback) {
  return safe_normalize(v).value_or(fallback);
}

} // namespace

std::optional<glm::vec3> safe_normalize(glm::vec3 v) {
  // Divide by the largest component first: squaring components of 1e20 (or 1e-25) would
  // overflow (underflow) a float, although the direction is perfectly defined.
  const float m = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
  if (!(m > 0.0f) || !std::isfinite(m)) {
    return std::nullopt;
  }
  const glm::vec3 w = v / m;
  return w / std::sqrt(glm::dot(w, w));
}

glm::vec3 any_perpendicular(glm::vec3 n) {
  // Cross with the coordinate axis least aligned with n, so the result is never near zero.
  const glm::vec3 a = glm::abs(n);
  const glm::vec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::vec3(1, 0, 0)
                         : (a.y <= a.z)             ? glm::vec3(0, 1, 0)
                                                    : glm::vec3(0, 0, 1);
  return normalized_or(glm::cross(n, axis), glm::vec3(1, 0, 0));
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
      const Vertex& a = vertices[indices[3 * t]];
      const Vertex& b = vertices[indices[3 * t + 1]];
      const Vertex& c = vertices[indices[3 * t + 2]];
      const glm::vec3 n =
          normalized_or(glm::cross(b.position - a.position, c.position - a.position), up);
      for (const Vertex* v : {&a, &b, &c}) {
        flat.push_back(*v);
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

  std::vector<glm::vec3> sum(vertices.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < triangle_count; ++t) {
    if (!triangle_in_range(indices, 3 * t, vertices.size())) {
      continue;
    }
    const std::uint32_t i0 = indices[3 * t], i1 = indices[3 * t + 1], i2 = indices[3 * t + 2];
    // The unnormalised cross product's length is twice the triangle's area: summing it weights
    // every face by its area, so slivers at a seam do not skew the result.
    const glm::vec3 face = glm::cross(vertices[i1].position - vertices[i0].position,
                                      vertices[i2].position - vertices[i0].position);
    if (!finite(face)) {
      continue;
    }
    sum[i0] += face;
    sum[i1] += face;
    sum[i2] += face;
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i].normal = normalized_or(sum[i], up);
  }
}

void generate_tangents(std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices) {
  std::vector<glm::vec3> tan_sum(vertices.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> up_sum(vertices.size(), glm::vec3(0.0f)); // direction of decreasing v
  const std::size_t triangle_count = indices.size() / 3;
  for (std::size_t t = 0; t < triangle_count; ++t) {
    if (!triangle_in_range(indices, 3 * t, vertices.size())) {
      continue;
    }
    const std::uint32_t i0 = indices[3 * t], i1 = indices[3 * t + 1], i2 = indices[3 * t + 2];
    const glm::vec3 e1 = vertices[i1].position - vertices[i0].position;
    const glm::vec3 e2 = vertices[i2].position - vertices[i0].position;
    const glm::vec2 d1 = vertices[i1].uv - vertices[i0].uv;
    const glm::vec2 d2 = vertices[i2].uv - vertices[i0].uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(det) || std::abs(det) < 1e-20f) {
      continue; // Degenerate UVs: this triangle says nothing about the tangent frame.
    }
    // Solve [e1 e2] = [T B] [d1 d2] for T = dP/du and B = dP/dv (Lengyel). Each triangle's
    // contribution is scaled by |det| (its UV area) relative to the plain solution, so small UV
    // islands at seams do not dominate.
    const float sign = det > 0.0f ? 1.0f : -1.0f;
    const glm::vec3 dp_du = (e1 * d2.y - e2 * d1.y) * sign;
    const glm::vec3 dp_dv = (e2 * d1.x - e1 * d2.x) * sign;
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
    const glm::vec3 n = normalized_or(v.normal, glm::vec3(0, 1, 0));
    // Gram-Schmidt: remove the normal component so that the frame is orthonormal.
    const std::optional<glm::vec3> sum_dir = safe_normalize(tan_sum[i]);
    // Work on the unit direction (the sums may be huge or tiny), and fall back when it is (nearly)
    // parallel to the normal: what remains after removing the normal part would be rounding noise.
    const glm::vec3 t = sum_dir ? *sum_dir - n * glm::dot(n, *sum_dir) : glm::vec3(0.0f);
    const std::optional<glm::vec3> t_dir = safe_normalize(t);
    if (!t_dir || glm::dot(t, t) < 1e-8f) {
      v.tangent = glm::vec4(any_perpendicular(n), 1.0f);
      continue;
    }
    const glm::vec3 tn = *t_dir;
    const float handedness = glm::dot(glm::cross(n, tn), up_sum[i]) < 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(tn, handedness);
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
