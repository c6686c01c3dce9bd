// Internal: reading glTF accessors into plain arrays (see gltf_accessor.hpp).
#include "gltf_accessor.hpp"

#include "gltf_validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace snell::detail {
namespace {

template <class T> T load(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value); // Accessors need not be aligned in memory.
  return value;
}

// One component as glTF defines its value (KHR_mesh_quantization's normalisation formulas).
double component_value(const std::uint8_t* p, int component_type, bool normalized) {
  switch (component_type) {
  case TINYGLTF_COMPONENT_TYPE_BYTE: {
    const double v = load<std::int8_t>(p);
    return normalized ? std::max(v / 127.0, -1.0) : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
    const double v = load<std::uint8_t>(p);
    return normalized ? v / 255.0 : v;
  }
  case TINYGLTF_COMPONENT_TYPE_SHORT: {
    const double v = load<std::int16_t>(p);
    return normalized ? std::max(v / 32767.0, -1.0) : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
    const double v = load<std::uint16_t>(p);
    return normalized ? v / 65535.0 : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
    const double v = load<std::uint32_t>(p);
    return normalized ? v / 4294967295.0 : v;
  }
  case TINYGLTF_COMPONENT_TYPE_FLOAT:
    return static_cast<double>(load<float>(p));
  default:
    return 0.0; // Unreachable after validate_model().
  }
}

std::uint32_t index_value(const std::uint8_t* p, int component_type) {
  switch (component_type) {
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return load<std::uint8_t>(p);
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    return load<std::uint16_t>(p);
  default:
    return load<std::uint32_t>(p);
  }
}

// Start of the bytes of `view_index` plus `offset`, after re-checking that `count` elements
// fit (validate_model checked it; re-checked so that this reader is memory-safe on its own).
const std::uint8_t* view_data(const tinygltf::Model& model, int view_index, std::uint64_t offset,
                              std::uint64_t count, std::uint64_t stride, std::uint64_t element) {
  if (view_index < 0 || static_cast<std::size_t>(view_index) >= model.bufferViews.size()) {
    return nullptr;
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(view_index)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    return nullptr;
  }
  const std::vector<unsigned char>& data =
      model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::optional<std::uint64_t> end = span_end(offset, count, stride, element);
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset || !end ||
      *end > view.byteLength) {
    return nullptr;
  }
  return data.data() + view.byteOffset + offset;
}

const char* type_name(int type) {
  switch (type) {
  case TINYGLTF_TYPE_SCALAR:
    return "SCALAR";
  case TINYGLTF_TYPE_VEC2:
    return "VEC2";
  case TINYGLTF_TYPE_VEC3:
    return "VEC3";
  case TINYGLTF_TYPE_VEC4:
    return "VEC4";
  default:
    return "a matrix type";
  }
}

// Visits every element of the accessor: base data (or zeros), then sparse substitutions.
// `store(element, bytes)` receives a pointer to the element's first component, or nullptr for a
// zero element.
template <class Store>
Result<void> visit_elements(const tinygltf::Model& model, const tinygltf::Accessor& a,
                            const std::string& what, const GltfLoadContext& ctx, Store store) {
  const std::uint64_t element = static_cast<std::uint64_t>(component_size(a.componentType)) *
                                static_cast<std::uint64_t>(component_count(a.type));
  if (a.bufferView >= 0) {
    const std::size_t declared =
        model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
    const std::uint64_t stride = declared != 0 ? declared : element;
    const std::uint8_t* base =
        view_data(model, a.bufferView, a.byteOffset, a.count, stride, element);
    if (base == nullptr) {
      return ctx.fail(ErrorCode::parse_error, what + ": accessor data outside its buffer view");
    }
    for (std::size_t e = 0; e < a.count; ++e) {
      store(e, base + e * stride);
    }
  } else {
    for (std::size_t e = 0; e < a.count; ++e) {
      store(e, nullptr); // glTF: an accessor without a buffer view is all zeros.
    }
  }
  if (!a.sparse.isSparse) {
    return {};
  }
  const auto count = static_cast<std::uint64_t>(a.sparse.count);
  const auto index_size =
      static_cast<std::uint64_t>(component_size(a.sparse.indices.componentType));
  const std::uint8_t* indices =
      view_data(model, a.sparse.indices.bufferView,
                static_cast<std::uint64_t>(std::max(a.sparse.indices.byteOffset, 0)), count,
                index_size, index_size);
  const std::uint8_t* values = view_data(
      model, a.sparse.values.bufferView,
      static_cast<std::uint64_t>(std::max(a.sparse.values.byteOffset, 0)), count, element, element);
  if (indices == nullptr || values == nullptr || a.sparse.indices.byteOffset < 0 ||
      a.sparse.values.byteOffset < 0) {
    return ctx.fail(ErrorCode::parse_error, what + ": sparse data outside its buffer views");
  }
  for (std::uint64_t s = 0; s < count; ++s) {
    const std::uint32_t target =
        index_value(indices + s * index_size, a.sparse.indices.componentType);
    if (target >= a.count) {
      return ctx.fail(ErrorCode::parse_error, what + ": sparse index " + std::to_string(target) +
                                                  " is past the count " + std::to_string(a.count));
    }
    store(target, values + s * element);
  }
  return {};
}

// The accessor `index` after checking its type and size budget.
Result<const tinygltf::Accessor*> checked_accessor(const tinygltf::Model& model, int index,
                                                   int expected_type, const std::string& what,
                                                   std::uint64_t max_elements,
                                                   const GltfLoadContext& ctx) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    return ctx.fail(ErrorCode::parse_error,
                    what + ": accessor " + std::to_string(index) + " does not exist");
  }
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  const std::string name =
      what + " " + describe("accessor", static_cast<std::size_t>(index), a.name);
  if (a.type != expected_type) {
    return ctx.fail(ErrorCode::parse_error, name + ": type is " + type_name(a.type) +
                                                ", expected " + type_name(expected_type));
  }
  if (component_size(a.componentType) == 0) {
    return ctx.fail(ErrorCode::parse_error, name + ": componentType " +
                                                std::to_string(a.componentType) +
                                                " is not a glTF 2.0 type");
  }
  if (a.count > max_elements) {
    return ctx.fail(ErrorCode::limit_exceeded,
                    name + ": " + std::to_string(a.count) +
                        " elements would exceed the vertex/index limits of GltfLimits "
                        "(room left: " +
                        std::to_string(max_elements) + ")");
  }
  return &a;
}

} // namespace

Result<std::vector<float>> read_float_accessor(const tinygltf::Model& model, int index,
                                               int expected_type, const std::string& what,
                                               std::uint64_t max_elements,
                                               const GltfLoadContext& ctx) {
  Result<const tinygltf::Accessor*> checked =
      checked_accessor(model, index, expected_type, what, max_elements, ctx);
  if (!checked) {
    return checked.error();
  }
  const tinygltf::Accessor& a = **checked;
  const std::string name =
      what + " " + describe("accessor", static_cast<std::size_t>(index), a.name);
  const int components = component_count(a.type);
  const int size = component_size(a.componentType);
  std::vector<float> out(a.count * static_cast<std::size_t>(components), 0.0f);
  Result<void> visited =
      visit_elements(model, a, name, ctx, [&](std::size_t e, const std::uint8_t* bytes) {
        for (int c = 0; c < components; ++c) {
          out[e * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
              bytes == nullptr ? 0.0f
                               : static_cast<float>(component_value(bytes + c * size,
                                                                    a.componentType, a.normalized));
        }
      });
  if (!visited) {
    return visited.error();
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!std::isfinite(out[i])) {
      return ctx.fail(ErrorCode::parse_error,
                      name + ": element " +
                          std::to_string(i / static_cast<std::size_t>(components)) +
                          " is not finite (NaN or infinity)");
    }
  }
  return out;
}

Result<std::vector<std::uint32_t>> read_index_accessor(const tinygltf::Model& model, int index,
                                                       const std::string& what,
                                                       std::uint64_t max_elements,
                                                       const GltfLoadContext& ctx) {
  Result<const tinygltf::Accessor*> checked =
      checked_accessor(model, index, TINYGLTF_TYPE_SCALAR, what, max_elements, ctx);
  if (!checked) {
    return checked.error();
  }
  const tinygltf::Accessor& a = **checked;
  const std::string name =
      what + " " + describe("accessor", static_cast<std::size_t>(index), a.name);
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    return ctx.fail(ErrorCode::parse_error, name + ": componentType " +
                                                std::to_string(a.componentType) +
                                                " is not an unsigned integer type");
  }
  std::vector<std::uint32_t> out(a.count, 0);
  Result<void> visited =
      visit_elements(model, a, name, ctx, [&](std::size_t e, const std::uint8_t* bytes) {
        out[e] = bytes == nullptr ? 0u : index_value(bytes, a.componentType);
      });
  if (!visited) {
    return visited.error();
  }
  return out;
}

} // namespace snell::detail
