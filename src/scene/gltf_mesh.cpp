// Internal: conversion of glTF meshes to snell::Mesh (see gltf_mesh.hpp).
#include "gltf_mesh.hpp"

#include "gltf_accessor.hpp"
#include "mesh_utils.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace snell::detail {
namespace {

std::uint64_t room(std::uint64_t limit, std::uint64_t used) {
  return used >= limit ? 0 : limit - used;
}

// Triangle list from a strip or fan, with the vertex orders glTF 2.0 specifies (section 3.7.2.1),
// which keep every triangle's winding consistent with the first one.
std::vector<std::uint32_t> to_triangle_list(const std::vector<std::uint32_t>& in, int mode) {
  std::vector<std::uint32_t> out;
  if (in.size() < 3) {
    return out;
  }
  out.reserve((in.size() - 2) * 3);
  for (std::size_t i = 0; i + 2 < in.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      const std::size_t odd = i % 2;
      out.insert(out.end(), {in[i], in[i + 1 + odd], in[i + 2 - odd]});
    } else { // fan
      out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
    }
  }
  return out;
}

class PrimitiveConverter {
public:
  PrimitiveConverter(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                     std::string what, GeometryTotals& totals, const GltfLoadContext& ctx)
      : model_(model), prim_(prim), what_(std::move(what)), totals_(totals), ctx_(ctx) {}

  // The converted mesh, or nullopt when the primitive is skipped.
  Result<std::optional<Mesh>> run() {
    const int mode = prim_.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      return std::optional<Mesh>{}; // Points and lines: see gltf_mesh.hpp.
    }
    const int position_accessor = attribute("POSITION");
    if (position_accessor < 0) {
      return std::optional<Mesh>{};
    }
    const GltfLimits& limits = ctx_.limits;
    if (Result<void> r =
            fits(model_.accessors[static_cast<std::size_t>(position_accessor)].count,
                 totals_.vertices, limits.max_total_vertices, "POSITION", "max_total_vertices");
        !r) {
      return r.error();
    }
    Result<std::vector<float>> positions =
        read_float_accessor(model_, position_accessor, TINYGLTF_TYPE_VEC3, what_ + " POSITION",
                            room(limits.max_total_vertices, totals_.vertices), ctx_);
    if (!positions) {
      return positions.error();
    }
    const std::size_t n = positions->size() / 3;
    std::vector<Vertex> vertices(n);
    for (std::size_t i = 0; i < n; ++i) {
      vertices[i].position = {(*positions)[3 * i], (*positions)[3 * i + 1],
                              (*positions)[3 * i + 2]};
    }

    Result<std::vector<std::uint32_t>> indices = read_indices(n);
    if (!indices) {
      return indices.error();
    }
    if (mode != TINYGLTF_MODE_TRIANGLES) {
      *indices = to_triangle_list(*indices, mode);
    } else if (indices->size() % 3 != 0) {
      return ctx_.fail(ErrorCode::parse_error, what_ + ": " + std::to_string(indices->size()) +
                                                   " indices do not form whole triangles");
    }
    if (indices->empty()) {
      return std::optional<Mesh>{}; // A strip or fan of fewer than 3 vertices draws nothing.
    }
    if (indices->size() > room(limits.max_total_indices, totals_.indices)) {
      return ctx_.fail(ErrorCode::limit_exceeded,
                       what_ + ": " + std::to_string(indices->size()) +
                           " triangle indices exceed GltfLimits::max_total_indices = " +
                           std::to_string(limits.max_total_indices) + " over all meshes");
    }

    // Flat normals give every triangle corner its own vertex: check the limit before that.
    const std::size_t final_vertices = attribute("NORMAL") < 0 ? indices->size() : n;
    if (final_vertices > room(limits.max_total_vertices, totals_.vertices)) {
      return ctx_.fail(ErrorCode::limit_exceeded,
                       what_ + ": " + std::to_string(final_vertices) +
                           " vertices (one per triangle corner when normals are generated) "
                           "exceed GltfLimits::max_total_vertices = " +
                           std::to_string(limits.max_total_vertices) + " over all meshes");
    }
    if (Result<void> r = read_attributes(vertices, *indices); !r) {
      return r.error();
    }
    totals_.vertices += vertices.size();
    totals_.indices += indices->size();

    Mesh mesh;
    mesh.vertices = std::move(vertices);
    mesh.indices = std::move(*indices);
    mesh.material = prim_.material;
    return std::optional<Mesh>(std::move(mesh));
  }

private:
  // Checks, before anything is allocated, that `count` more elements keep the total within
  // GltfLimits::<limit_name> = `limit`.
  Result<void> fits(std::uint64_t count, std::uint64_t used, std::uint64_t limit, const char* what,
                    const char* limit_name) const {
    if (count > room(limit, used)) {
      return ctx_.fail(ErrorCode::limit_exceeded,
                       what_ + " " + what + ": " + std::to_string(count) + " elements (" +
                           std::to_string(used) + " already loaded) exceed GltfLimits::" +
                           limit_name + " = " + std::to_string(limit) + " over all meshes");
    }
    return {};
  }

  int attribute(const char* semantic) const {
    const auto it = prim_.attributes.find(semantic);
    return it == prim_.attributes.end() ? -1 : it->second;
  }

  Result<std::vector<std::uint32_t>> read_indices(std::size_t vertex_count) const {
    const std::uint64_t index_room = room(ctx_.limits.max_total_indices, totals_.indices);
    if (prim_.indices < 0) {
      if (vertex_count > index_room) {
        return ctx_.fail(ErrorCode::limit_exceeded,
                         what_ + ": " + std::to_string(vertex_count) +
                             " implicit indices exceed GltfLimits::max_total_indices = " +
                             std::to_string(ctx_.limits.max_total_indices) + " over all meshes");
      }
      std::vector<std::uint32_t> implicit(vertex_count);
      for (std::size_t i = 0; i < vertex_count; ++i) {
        implicit[i] = static_cast<std::uint32_t>(i);
      }
      return implicit;
    }
    if (Result<void> r =
            fits(model_.accessors[static_cast<std::size_t>(prim_.indices)].count, totals_.indices,
                 ctx_.limits.max_total_indices, "indices", "max_total_indices");
        !r) {
      return r.error();
    }
    Result<std::vector<std::uint32_t>> indices =
        read_index_accessor(model_, prim_.indices, what_ + " indices", index_room, ctx_);
    if (!indices) {
      return indices;
    }
    if (const std::optional<std::size_t> bad = first_index_out_of_range(*indices, vertex_count)) {
      return ctx_.fail(ErrorCode::parse_error,
                       what_ + " indices accessor " + std::to_string(prim_.indices) +
                           ": index value " + std::to_string((*indices)[*bad]) + " at position " +
                           std::to_string(*bad) + " is past the vertex count " +
                           std::to_string(vertex_count));
    }
    return indices;
  }

  // Reads the optional attribute `semantic` of glTF type `type`, which must have one element per
  // vertex (checked before reading, so that a bogus count allocates nothing). Empty when absent.
  Result<std::vector<float>> optional_attribute(const char* semantic, int type,
                                                std::size_t vertex_count) const {
    const int accessor = attribute(semantic);
    if (accessor < 0) {
      return std::vector<float>{};
    }
    const std::size_t count = model_.accessors[static_cast<std::size_t>(accessor)].count;
    if (count != vertex_count) {
      return ctx_.fail(ErrorCode::parse_error,
                       what_ + " " + semantic + " accessor " + std::to_string(accessor) + " has " +
                           std::to_string(count) + " elements, POSITION has " +
                           std::to_string(vertex_count));
    }
    return read_float_accessor(model_, accessor, type, what_ + " " + semantic, vertex_count, ctx_);
  }

  Result<void> read_attributes(std::vector<Vertex>& vertices, std::vector<std::uint32_t>& indices) {
    const std::size_t n = vertices.size();
    Result<std::vector<float>> uv = optional_attribute("TEXCOORD_0", TINYGLTF_TYPE_VEC2, n);
    Result<std::vector<float>> normal = optional_attribute("NORMAL", TINYGLTF_TYPE_VEC3, n);
    Result<std::vector<float>> tangent = optional_attribute("TANGENT", TINYGLTF_TYPE_VEC4, n);
    for (const auto* r : {&uv, &normal, &tangent}) {
      if (!*r) {
        return r->error();
      }
    }
    for (std::size_t i = 0; i < n && !uv->empty(); ++i) {
      vertices[i].uv = {(*uv)[2 * i], (*uv)[2 * i + 1]};
    }
    if (normal->empty()) {
      // glTF 2.0 (3.7.2.1): without normals, flat normals, and any provided tangents ignored.
      generate_flat_or_smooth_normals(vertices, indices, NormalMode::flat);
      generate_tangents(vertices, indices);
      return {};
    }
    bool degenerate_normal = false;
    for (std::size_t i = 0; i < n; ++i) {
      const std::optional<glm::vec3> v =
          safe_normalize({(*normal)[3 * i], (*normal)[3 * i + 1], (*normal)[3 * i + 2]});
      degenerate_normal = degenerate_normal || !v;
      vertices[i].normal = v.value_or(glm::vec3(0.0f));
    }
    if (degenerate_normal) {
      // Zero-length normals (seen in exports of degenerate faces): only those vertices get the
      // smooth normal of their triangles, the others keep the file's normals.
      std::vector<Vertex> smooth = vertices;
      generate_flat_or_smooth_normals(smooth, indices, NormalMode::smooth);
      for (std::size_t i = 0; i < n; ++i) {
        if (vertices[i].normal == glm::vec3(0.0f)) {
          vertices[i].normal = smooth[i].normal;
        }
      }
    }
    if (tangent->empty()) {
      generate_tangents(vertices, indices);
      return {};
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::optional<glm::vec3> t =
          safe_normalize({(*tangent)[4 * i], (*tangent)[4 * i + 1], (*tangent)[4 * i + 2]});
      if (!t) {
        generate_tangents(vertices, indices); // Unusable tangents: generate them all.
        return {};
      }
      vertices[i].tangent = glm::vec4(*t, (*tangent)[4 * i + 3] < 0.0f ? -1.0f : 1.0f);
    }
    return {};
  }

  const tinygltf::Model& model_;
  const tinygltf::Primitive& prim_;
  std::string what_;
  GeometryTotals& totals_;
  const GltfLoadContext& ctx_;
};

} // namespace

Result<std::vector<int>> convert_mesh(const tinygltf::Model& model, int mesh_index, Scene& scene,
                                      GeometryTotals& totals, const GltfLoadContext& ctx) {
  const tinygltf::Mesh& source = model.meshes[static_cast<std::size_t>(mesh_index)];
  const std::string mesh_what = describe("mesh", static_cast<std::size_t>(mesh_index), source.name);
  const std::string base_name =
      source.name.empty() ? "mesh " + std::to_string(mesh_index) : source.name;
  std::vector<int> converted;
  for (std::size_t p = 0; p < source.primitives.size(); ++p) {
    Result<std::optional<Mesh>> mesh =
        PrimitiveConverter(model, source.primitives[p],
                           mesh_what + " primitive " + std::to_string(p), totals, ctx)
            .run();
    if (!mesh) {
      return mesh.error();
    }
    if (!*mesh) {
      continue;
    }
    (*mesh)->name = source.primitives.size() > 1 ? base_name + "/" + std::to_string(p) : base_name;
    converted.push_back(static_cast<int>(scene.meshes.size()));
    scene.meshes.push_back(std::move(**mesh));
  }
  return converted;
}

} // namespace snell::detail
