// Internal: structural validation of a parsed glTF model (see gltf_validate.hpp).
#include "gltf_validate.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

namespace snell::detail {
namespace {

// The extensions the converter reads. A file that *requires* any other extension would be
// rendered wrongly (compressed geometry, texture transforms, ...), so it is refused.
constexpr std::array<std::string_view, 7> supported_extensions = {
    "KHR_lights_punctual",  "KHR_materials_transmission",
    "KHR_materials_ior",    "KHR_materials_emissive_strength",
    "KHR_materials_volume", "KHR_materials_dispersion",
    "KHR_mesh_quantization"};

template <class T> std::string count_text(const std::vector<T>& items, const char* plural) {
  return "(" + std::to_string(items.size()) + " " + plural + ")";
}

// True when `index` is a valid position in `items`.
template <class T> bool in_range(int index, const std::vector<T>& items) {
  return index >= 0 && static_cast<std::size_t>(index) < items.size();
}

// The converter stores file values as float: a finite double beyond FLT_MAX would not convert
// (undefined behaviour in C++), so "finite" here means "a finite float".
bool finite_float(double v) {
  return std::isfinite(v) && std::abs(v) <= static_cast<double>(std::numeric_limits<float>::max());
}

bool all_finite(const std::vector<double>& values) {
  for (const double v : values) {
    if (!finite_float(v)) {
      return false;
    }
  }
  return true;
}

class Validator {
public:
  Validator(const tinygltf::Model& model, const GltfLoadContext& ctx) : m_(model), ctx_(ctx) {}

  Result<void> run() {
    for (auto step :
         {&Validator::extensions, &Validator::buffer_views, &Validator::accessors,
          &Validator::meshes, &Validator::materials, &Validator::textures, &Validator::nodes,
          &Validator::scenes, &Validator::cameras, &Validator::lights}) {
      if (Result<void> r = (this->*step)(); !r) {
        return r;
      }
    }
    return {};
  }

private:
  Error fail(const std::string& what) const { return ctx_.fail(ErrorCode::parse_error, what); }

  // "<what> <kind> <index> does not exist (<n> <kinds>)" unless index is in range or -1 is allowed.
  template <class T>
  Result<void> reference(const std::string& what, const char* kind, int index,
                         const std::vector<T>& items, const char* plural, bool optional) const {
    if ((optional && index == -1) || in_range(index, items)) {
      return {};
    }
    return fail(what + ": " + kind + " " + std::to_string(index) + " does not exist " +
                count_text(items, plural));
  }

  Result<void> extensions() {
    for (const std::string& name : m_.extensionsRequired) {
      bool known = false;
      for (const std::string_view s : supported_extensions) {
        known = known || name == s;
      }
      if (!known) {
        std::string list;
        for (const std::string_view s : supported_extensions) {
          list += (list.empty() ? "" : ", ") + std::string(s);
        }
        return ctx_.fail(ErrorCode::unsupported, "requires the extension '" + name +
                                                     "', which Snell does not support "
                                                     "(supported: " +
                                                     list + ")");
      }
    }
    return {};
  }

  Result<void> buffer_views() {
    for (std::size_t i = 0; i < m_.bufferViews.size(); ++i) {
      const tinygltf::BufferView& view = m_.bufferViews[i];
      const std::string what = describe("bufferView", i, view.name);
      if (Result<void> r = reference(what, "buffer", view.buffer, m_.buffers, "buffers", false);
          !r) {
        return r;
      }
      const std::size_t size = m_.buffers[static_cast<std::size_t>(view.buffer)].data.size();
      if (view.byteLength == 0 || view.byteOffset > size ||
          view.byteLength > size - view.byteOffset) {
        return fail(what + " (offset " + std::to_string(view.byteOffset) + ", length " +
                    std::to_string(view.byteLength) + ") lies outside buffer " +
                    std::to_string(view.buffer) + " (" + std::to_string(size) + " bytes)");
      }
      if (view.byteStride != 0 && (view.byteStride < 4 || view.byteStride > 252)) {
        return fail(what + ": byteStride " + std::to_string(view.byteStride) +
                    " is outside [4, 252]");
      }
    }
    return {};
  }

  // Checks that `count` elements of `element` bytes, `stride` apart, starting `offset` bytes into
  // buffer view `view_index`, lie inside it.
  Result<void> fits_in_view(const std::string& what, int view_index, std::uint64_t offset,
                            std::uint64_t count, std::uint64_t stride,
                            std::uint64_t element) const {
    if (Result<void> r =
            reference(what, "bufferView", view_index, m_.bufferViews, "buffer views", false);
        !r) {
      return r;
    }
    const tinygltf::BufferView& view = m_.bufferViews[static_cast<std::size_t>(view_index)];
    const std::optional<std::uint64_t> end = span_end(offset, count, stride, element);
    if (!end || *end > view.byteLength) {
      return fail(what + ": " + std::to_string(count) + " elements of " + std::to_string(element) +
                  " bytes (stride " + std::to_string(stride) + ") from offset " +
                  std::to_string(offset) + " run past the end of bufferView " +
                  std::to_string(view_index) + " (" + std::to_string(view.byteLength) + " bytes)");
    }
    return {};
  }

  Result<void> accessors() {
    for (std::size_t i = 0; i < m_.accessors.size(); ++i) {
      const tinygltf::Accessor& a = m_.accessors[i];
      const std::string what = describe("accessor", i, a.name);
      const int size = component_size(a.componentType);
      const int components = component_count(a.type);
      if (size == 0 || components == 0) {
        return fail(what + ": componentType " + std::to_string(a.componentType) + " / type " +
                    std::to_string(a.type) + " is not a glTF 2.0 accessor format");
      }
      if (a.count == 0) {
        return fail(what + ": count is 0 (the minimum is 1)");
      }
      const std::uint64_t element = static_cast<std::uint64_t>(size) * components;
      if (a.bufferView != -1) {
        if (Result<void> r =
                reference(what, "bufferView", a.bufferView, m_.bufferViews, "buffer views", false);
            !r) {
          return r;
        }
        const std::size_t declared_stride =
            m_.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
        if (declared_stride != 0 && declared_stride < element) {
          return fail(what + ": bufferView " + std::to_string(a.bufferView) + " byteStride " +
                      std::to_string(declared_stride) + " is smaller than an element (" +
                      std::to_string(element) + " bytes)");
        }
        const std::uint64_t stride = declared_stride != 0 ? declared_stride : element;
        if (Result<void> r =
                fits_in_view(what, a.bufferView, a.byteOffset, a.count, stride, element);
            !r) {
          return r;
        }
      }
      if (a.sparse.isSparse) {
        if (Result<void> r = sparse(what, a, element); !r) {
          return r;
        }
      }
    }
    return {};
  }

  Result<void> sparse(const std::string& what, const tinygltf::Accessor& a,
                      std::uint64_t element) const {
    const auto& s = a.sparse;
    if (s.count < 1 || static_cast<std::uint64_t>(s.count) > a.count) {
      return fail(what + ": sparse count " + std::to_string(s.count) + " is outside [1, " +
                  std::to_string(a.count) + "]");
    }
    const int index_size = component_size(s.indices.componentType);
    if (s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      return fail(what + ": sparse indices componentType " +
                  std::to_string(s.indices.componentType) + " is not an unsigned integer type");
    }
    if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) {
      return fail(what + ": negative sparse byteOffset");
    }
    const auto count = static_cast<std::uint64_t>(s.count);
    if (Result<void> r = fits_in_view(what + " sparse indices", s.indices.bufferView,
                                      static_cast<std::uint64_t>(s.indices.byteOffset), count,
                                      static_cast<std::uint64_t>(index_size),
                                      static_cast<std::uint64_t>(index_size));
        !r) {
      return r;
    }
    return fits_in_view(what + " sparse values", s.values.bufferView,
                        static_cast<std::uint64_t>(s.values.byteOffset), count, element, element);
  }

  Result<void> meshes() {
    for (std::size_t i = 0; i < m_.meshes.size(); ++i) {
      const tinygltf::Mesh& mesh = m_.meshes[i];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        const std::string what = describe("mesh", i, mesh.name) + " primitive " + std::to_string(p);
        if (prim.mode < TINYGLTF_MODE_POINTS || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
          return fail(what + ": mode " + std::to_string(prim.mode) + " is not a glTF mode");
        }
        if (Result<void> r =
                reference(what, "material", prim.material, m_.materials, "materials", true);
            !r) {
          return r;
        }
        if (Result<void> r =
                reference(what, "indices accessor", prim.indices, m_.accessors, "accessors", true);
            !r) {
          return r;
        }
        for (const auto& [semantic, index] : prim.attributes) {
          if (Result<void> r = reference(what + " attribute " + semantic, "accessor", index,
                                         m_.accessors, "accessors", false);
              !r) {
            return r;
          }
        }
        for (const auto& target : prim.targets) {
          for (const auto& [semantic, index] : target) {
            if (Result<void> r = reference(what + " morph target " + semantic, "accessor", index,
                                           m_.accessors, "accessors", false);
                !r) {
              return r;
            }
          }
        }
      }
    }
    return {};
  }

  Result<void> texture_ref(const std::string& what, const char* slot, int index) const {
    return reference(what + " " + slot, "texture", index, m_.textures, "textures", true);
  }

  Result<void> materials() {
    for (std::size_t i = 0; i < m_.materials.size(); ++i) {
      const tinygltf::Material& mat = m_.materials[i];
      const std::string what = describe("material", i, mat.name);
      const auto& pbr = mat.pbrMetallicRoughness;
      for (const auto& [slot, index] :
           {std::pair<const char*, int>{"baseColorTexture", pbr.baseColorTexture.index},
            {"metallicRoughnessTexture", pbr.metallicRoughnessTexture.index},
            {"normalTexture", mat.normalTexture.index},
            {"occlusionTexture", mat.occlusionTexture.index},
            {"emissiveTexture", mat.emissiveTexture.index}}) {
        if (Result<void> r = texture_ref(what, slot, index); !r) {
          return r;
        }
      }
      if (pbr.baseColorFactor.size() != 4 || !all_finite(pbr.baseColorFactor)) {
        return fail(what + ": baseColorFactor must be 4 finite numbers");
      }
      if (mat.emissiveFactor.size() != 3 || !all_finite(mat.emissiveFactor)) {
        return fail(what + ": emissiveFactor must be 3 finite numbers");
      }
      if (!(pbr.roughnessFactor >= 0.0 && pbr.roughnessFactor <= 1.0)) {
        return fail(what + ": roughnessFactor " + std::to_string(pbr.roughnessFactor) +
                    " is outside [0, 1]");
      }
      if (!(mat.alphaCutoff >= 0.0) || !finite_float(mat.alphaCutoff)) {
        return fail(what + ": alphaCutoff " + std::to_string(mat.alphaCutoff) +
                    " is not a finite number >= 0");
      }
      if (!finite_float(mat.normalTexture.scale)) {
        return fail(what + ": normalTexture.scale is not finite");
      }
      if (mat.alphaMode != "OPAQUE" && mat.alphaMode != "MASK" && mat.alphaMode != "BLEND") {
        return fail(what + ": alphaMode '" + mat.alphaMode.substr(0, 40) +
                    "' is not OPAQUE, MASK or BLEND");
      }
    }
    return {};
  }

  Result<void> textures() {
    for (std::size_t i = 0; i < m_.textures.size(); ++i) {
      const tinygltf::Texture& tex = m_.textures[i];
      const std::string what = describe("texture", i, tex.name);
      if (Result<void> r = reference(what, "image", tex.source, m_.images, "images", true); !r) {
        return r;
      }
      if (Result<void> r = reference(what, "sampler", tex.sampler, m_.samplers, "samplers", true);
          !r) {
        return r;
      }
    }
    return {};
  }

  Result<void> nodes() {
    for (std::size_t i = 0; i < m_.nodes.size(); ++i) {
      const tinygltf::Node& node = m_.nodes[i];
      const std::string what = describe("node", i, node.name);
      if (Result<void> r = reference(what, "mesh", node.mesh, m_.meshes, "meshes", true); !r) {
        return r;
      }
      if (Result<void> r = reference(what, "camera", node.camera, m_.cameras, "cameras", true);
          !r) {
        return r;
      }
      if (Result<void> r = reference(what, "skin", node.skin, m_.skins, "skins", true); !r) {
        return r;
      }
      for (const int child : node.children) {
        if (Result<void> r = reference(what, "child node", child, m_.nodes, "nodes", false); !r) {
          return r;
        }
      }
      for (const auto& [field, values, expected] :
           {std::tuple<const char*, const std::vector<double>*, std::size_t>{"matrix", &node.matrix,
                                                                             16},
            {"translation", &node.translation, 3},
            {"rotation", &node.rotation, 4},
            {"scale", &node.scale, 3}}) {
        if (!values->empty() && (values->size() != expected || !all_finite(*values))) {
          return fail(what + ": " + field + " must be " + std::to_string(expected) +
                      " finite numbers (got " + std::to_string(values->size()) + ")");
        }
      }
      const auto light = node.extensions.find("KHR_lights_punctual");
      if (light != node.extensions.end()) {
        const tinygltf::Value& index = light->second.Get("light");
        if (!index.IsInt() || !in_range(index.Get<int>(), m_.lights)) {
          return fail(what + ": KHR_lights_punctual light " +
                      (index.IsInt() ? std::to_string(index.Get<int>()) : std::string("?")) +
                      " does not exist " + count_text(m_.lights, "lights"));
        }
      }
    }
    return {};
  }

  Result<void> scenes() {
    if (m_.defaultScene != -1 && !in_range(m_.defaultScene, m_.scenes)) {
      return fail("the default scene " + std::to_string(m_.defaultScene) + " does not exist " +
                  count_text(m_.scenes, "scenes"));
    }
    for (std::size_t i = 0; i < m_.scenes.size(); ++i) {
      for (const int node : m_.scenes[i].nodes) {
        if (Result<void> r = reference(describe("scene", i, m_.scenes[i].name), "node", node,
                                       m_.nodes, "nodes", false);
            !r) {
          return r;
        }
      }
    }
    return {};
  }

  Result<void> cameras() {
    for (std::size_t i = 0; i < m_.cameras.size(); ++i) {
      const tinygltf::Camera& cam = m_.cameras[i];
      const std::string what = describe("camera", i, cam.name);
      if (cam.type == "orthographic") {
        continue; // Not converted (Snell's cameras are perspective).
      }
      if (cam.type != "perspective") {
        return fail(what + ": type '" + cam.type.substr(0, 40) +
                    "' is not perspective or orthographic");
      }
      const tinygltf::PerspectiveCamera& p = cam.perspective;
      if (!(p.yfov > 0.0 && p.yfov < 3.14159265358979)) {
        return fail(what + ": yfov " + std::to_string(p.yfov) + " is outside (0, pi)");
      }
      // Compared as the floats CameraDesc will hold.
      if (!finite_float(p.znear) || !(static_cast<float>(p.znear) > 0.0f)) {
        return fail(what + ": znear " + std::to_string(p.znear) + " is not a finite number > 0");
      }
      // tinygltf stores an absent zfar as 0: an infinite far plane.
      if (p.zfar != 0.0 &&
          !(finite_float(p.zfar) && static_cast<float>(p.zfar) > static_cast<float>(p.znear))) {
        return fail(what + ": zfar " + std::to_string(p.zfar) + " is not greater than znear");
      }
    }
    return {};
  }

  Result<void> lights() {
    for (std::size_t i = 0; i < m_.lights.size(); ++i) {
      const tinygltf::Light& light = m_.lights[i];
      const std::string what = describe("KHR_lights_punctual light", i, light.name);
      if (!light.color.empty() && (light.color.size() != 3 || !all_finite(light.color))) {
        return fail(what + ": color must be 3 finite numbers");
      }
      if (!(light.intensity >= 0.0) || !finite_float(light.intensity)) {
        return fail(what + ": intensity " + std::to_string(light.intensity) +
                    " is not a finite number >= 0");
      }
    }
    return {};
  }

  const tinygltf::Model& m_;
  const GltfLoadContext& ctx_;
};

} // namespace

int component_size(int component_type) {
  switch (component_type) {
  case TINYGLTF_COMPONENT_TYPE_BYTE:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return 1;
  case TINYGLTF_COMPONENT_TYPE_SHORT:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    return 2;
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
  case TINYGLTF_COMPONENT_TYPE_FLOAT:
    return 4;
  default:
    return 0;
  }
}

int component_count(int type) {
  switch (type) {
  case TINYGLTF_TYPE_SCALAR:
    return 1;
  case TINYGLTF_TYPE_VEC2:
    return 2;
  case TINYGLTF_TYPE_VEC3:
    return 3;
  case TINYGLTF_TYPE_VEC4:
  case TINYGLTF_TYPE_MAT2:
    return 4;
  case TINYGLTF_TYPE_MAT3:
    return 9;
  case TINYGLTF_TYPE_MAT4:
    return 16;
  default:
    return 0;
  }
}

std::optional<std::uint64_t> span_end(std::uint64_t offset, std::uint64_t count,
                                      std::uint64_t stride, std::uint64_t element) {
  constexpr std::uint64_t max = ~std::uint64_t{0};
  if (count == 0) {
    return offset;
  }
  const std::uint64_t steps = count - 1;
  if (stride != 0 && steps > max / stride) {
    return std::nullopt;
  }
  const std::uint64_t last = steps * stride;
  if (last > max - offset || element > max - offset - last) {
    return std::nullopt;
  }
  return offset + last + element;
}

Result<void> validate_model(const tinygltf::Model& model, const GltfLoadContext& ctx) {
  return Validator(model, ctx).run();
}

} // namespace snell::detail
