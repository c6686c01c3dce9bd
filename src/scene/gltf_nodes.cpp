// Internal: the glTF node hierarchy (see gltf_nodes.hpp).
#include "gltf_nodes.hpp"

#include "mesh_utils.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace snell::detail {
namespace {

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) {
        return false;
      }
    }
  }
  return true;
}

// The node's transform relative to its parent (glTF: matrix, or T * R * S).
Result<glm::mat4> local_transform(const tinygltf::Node& node, const std::string& what,
                                  const GltfLoadContext& ctx) {
  if (node.matrix.size() == 16) {
    glm::mat4 m(1.0f);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        m[c][r] =
            static_cast<float>(node.matrix[static_cast<std::size_t>(4 * c + r)]); // Column-major.
      }
    }
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3) {
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (node.rotation.size() == 4) {
    // glTF stores (x, y, z, w); glm::quat's constructor takes (w, x, y, z).
    glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    const float len = glm::length(q);
    if (!(len > 1e-6f) || !std::isfinite(len)) {
      return ctx.fail(ErrorCode::parse_error, what + ": rotation is not a unit quaternion");
    }
    m = m * glm::mat4_cast(q / len); // Normalised: exporters round to a few digits.
  }
  if (node.scale.size() == 3) {
    m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return m;
}

class NodeWalker {
public:
  NodeWalker(const tinygltf::Model& model, Scene& scene, GeometryTotals& totals,
             const GltfLoadContext& ctx)
      : m_(model), scene_(scene), totals_(totals), ctx_(ctx), parent_(model.nodes.size(), -1) {}

  Result<void> run() {
    if (Result<void> r = check_hierarchy(); !r) {
      return r;
    }
    Result<std::vector<int>> roots = scene_roots();
    if (!roots) {
      return roots.error();
    }
    // Depth-first with an explicit stack: max_node_depth may be set high, and the call stack
    // must not depend on the file.
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto it = roots->rbegin(); it != roots->rend(); ++it) {
      stack.emplace_back(*it, glm::mat4(1.0f));
    }
    while (!stack.empty()) {
      const auto [index, parent_world] = stack.back();
      stack.pop_back();
      const tinygltf::Node& node = m_.nodes[static_cast<std::size_t>(index)];
      const std::string what = describe("node", static_cast<std::size_t>(index), node.name);
      Result<glm::mat4> local = local_transform(node, what, ctx_);
      if (!local) {
        return local.error();
      }
      const glm::mat4 world = parent_world * *local;
      if (!finite(world)) {
        return ctx_.fail(ErrorCode::parse_error, what + ": world transform is not finite");
      }
      if (Result<void> r = visit(node, what, world); !r) {
        return r;
      }
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
        stack.emplace_back(*it, world);
      }
    }
    return {};
  }

private:
  // Every node has at most one parent, there is no cycle, and no chain is deeper than the limit.
  // (Without the first two rules a small file could describe exponentially many instances.)
  Result<void> check_hierarchy() {
    const std::size_t n = m_.nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (const int child : m_.nodes[i].children) {
        const auto c = static_cast<std::size_t>(child); // In range: validate_model checked.
        if (parent_[c] != -1) {
          return ctx_.fail(ErrorCode::parse_error,
                           describe("node", c, m_.nodes[c].name) + " has two parents (nodes " +
                               std::to_string(parent_[c]) + " and " + std::to_string(i) +
                               "); glTF node hierarchies must be trees");
        }
        parent_[c] = static_cast<int>(i);
      }
    }
    // Depth of every node (root = 1) by walking up the parent links, memoised, so that the whole
    // check is linear. A walk that meets a node of its own path has found a cycle.
    constexpr int unknown = 0;
    constexpr int on_path = -1;
    std::vector<int> depth(n, unknown);
    std::vector<std::size_t> path;
    for (std::size_t start = 0; start < n; ++start) {
      path.clear();
      std::size_t v = start;
      int base = 0; // Depth of the node above the path's top.
      while (true) {
        if (depth[v] == on_path) {
          return ctx_.fail(ErrorCode::parse_error,
                           describe("node", v, m_.nodes[v].name) +
                               " is its own ancestor (a cycle in the node hierarchy)");
        }
        if (depth[v] != unknown) {
          base = depth[v];
          break;
        }
        depth[v] = on_path;
        path.push_back(v);
        if (parent_[v] == -1) {
          break;
        }
        v = static_cast<std::size_t>(parent_[v]);
      }
      for (auto it = path.rbegin(); it != path.rend(); ++it) {
        depth[*it] = ++base;
        if (static_cast<std::uint64_t>(depth[*it]) > ctx_.limits.max_node_depth) {
          return ctx_.fail(ErrorCode::limit_exceeded,
                           describe("node", *it, m_.nodes[*it].name) + " is at depth " +
                               std::to_string(depth[*it]) +
                               ", over the limit GltfLimits::max_node_depth = " +
                               std::to_string(ctx_.limits.max_node_depth));
        }
      }
    }
    return {};
  }

  Result<std::vector<int>> scene_roots() {
    std::vector<int> roots;
    if (m_.scenes.empty()) {
      for (std::size_t i = 0; i < m_.nodes.size(); ++i) {
        if (parent_[i] == -1) {
          roots.push_back(static_cast<int>(i));
        }
      }
      return roots;
    }
    const std::size_t chosen = m_.defaultScene >= 0 ? static_cast<std::size_t>(m_.defaultScene) : 0;
    const tinygltf::Scene& source = m_.scenes[chosen];
    if (!source.name.empty()) {
      scene_.name = source.name;
    }
    const std::string what = describe("scene", chosen, source.name);
    std::vector<bool> listed(m_.nodes.size(), false);
    for (const int root : source.nodes) {
      const auto r = static_cast<std::size_t>(root);
      if (listed[r]) {
        return ctx_.fail(ErrorCode::parse_error,
                         what + " lists node " + std::to_string(root) + " twice");
      }
      if (parent_[r] != -1) {
        return ctx_.fail(ErrorCode::parse_error, what + " lists node " + std::to_string(root) +
                                                     " as a root, but it is a child of node " +
                                                     std::to_string(parent_[r]));
      }
      listed[r] = true;
      roots.push_back(root);
    }
    return roots;
  }

  Result<void> visit(const tinygltf::Node& node, const std::string& what, const glm::mat4& world) {
    if (node.mesh >= 0) {
      if (Result<void> r = add_objects(node, what, world); !r) {
        return r;
      }
    }
    const glm::mat3 basis(world);
    if (node.camera >= 0 &&
        m_.cameras[static_cast<std::size_t>(node.camera)].type == "perspective") {
      const tinygltf::Camera& source = m_.cameras[static_cast<std::size_t>(node.camera)];
      // A glTF camera looks down its node's -Z with +Y up.
      const std::optional<glm::vec3> forward = safe_normalize(basis * glm::vec3(0.0f, 0.0f, -1.0f));
      const std::optional<glm::vec3> up = safe_normalize(basis * glm::vec3(0.0f, 1.0f, 0.0f));
      if (!forward || !up) {
        return ctx_.fail(ErrorCode::parse_error,
                         what + ": the transform of its camera is degenerate (zero scale)");
      }
      CameraDesc cam;
      cam.name = !source.name.empty() ? source.name
                 : !node.name.empty() ? node.name
                                      : "camera " + std::to_string(node.camera);
      cam.eye = glm::vec3(world[3]);
      cam.target = cam.eye + *forward;
      cam.up = *up;
      if (!std::isfinite(cam.target.x + cam.target.y + cam.target.z)) {
        return ctx_.fail(ErrorCode::parse_error, what + ": its camera's position is not finite");
      }
      cam.yfov = static_cast<float>(source.perspective.yfov);
      cam.z_near = static_cast<float>(source.perspective.znear);
      cam.z_far = source.perspective.zfar == 0.0 ? std::numeric_limits<float>::infinity()
                                                 : static_cast<float>(source.perspective.zfar);
      scene_.cameras.push_back(std::move(cam));
    }
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext != node.extensions.end() && !light_set_) {
      // The index was checked by validate_model.
      const tinygltf::Light& light =
          m_.lights[static_cast<std::size_t>(ext->second.Get("light").Get<int>())];
      if (light.type == "directional") {
        // Lights shine down their node's -Z.
        const std::optional<glm::vec3> direction =
            safe_normalize(basis * glm::vec3(0.0f, 0.0f, -1.0f));
        if (!direction) {
          return ctx_.fail(ErrorCode::parse_error,
                           what + ": the transform of its light is degenerate (zero scale)");
        }
        scene_.light.direction = *direction;
        if (light.color.size() == 3) {
          scene_.light.color = glm::vec3(light.color[0], light.color[1], light.color[2]);
        } else {
          scene_.light.color = glm::vec3(1.0f); // glTF's default light colour.
        }
        scene_.light.intensity = static_cast<float>(light.intensity);
        light_set_ = true;
      }
    }
    return {};
  }

  Result<void> add_objects(const tinygltf::Node& node, const std::string& what,
                           const glm::mat4& world) {
    auto cached = meshes_.find(node.mesh);
    if (cached == meshes_.end()) {
      Result<std::vector<int>> converted = convert_mesh(m_, node.mesh, scene_, totals_, ctx_);
      if (!converted) {
        return converted.error();
      }
      cached = meshes_.emplace(node.mesh, std::move(*converted)).first;
    }
    if (cached->second.size() > ctx_.limits.max_objects ||
        scene_.objects.size() > ctx_.limits.max_objects - cached->second.size()) {
      return ctx_.fail(ErrorCode::limit_exceeded,
                       what + ": its objects would exceed the limit GltfLimits::max_objects = " +
                           std::to_string(ctx_.limits.max_objects));
    }
    for (std::size_t p = 0; p < cached->second.size(); ++p) {
      Object object;
      object.name = node.name.empty() ? what : node.name;
      if (cached->second.size() > 1) {
        object.name += "/" + std::to_string(p);
      }
      object.mesh = cached->second[p];
      object.transform = world;
      scene_.objects.push_back(std::move(object));
    }
    return {};
  }

  const tinygltf::Model& m_;
  Scene& scene_;
  GeometryTotals& totals_;
  const GltfLoadContext& ctx_;
  std::vector<int> parent_;
  std::map<int, std::vector<int>> meshes_; // glTF mesh -> its Scene::meshes indices.
  bool light_set_ = false;
};

} // namespace

Result<void> convert_nodes(const tinygltf::Model& model, Scene& scene, GeometryTotals& totals,
                           const GltfLoadContext& ctx) {
  return NodeWalker(model, scene, totals, ctx).run();
}

} // namespace snell::detail
