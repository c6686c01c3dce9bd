// snell::load_gltf: glTF 2.0 (.gltf / .glb) to snell::Scene.
//
// Order of work, each step relying on the previous ones:
//   1. read the file (size-limited);
//   2. pre-scan the JSON (gltf_prescan.cpp): what tinygltf would act on blindly (data: URI sizes,
//      URIs, buffer sizes, image buffer views);
//   3. tinygltf parses, with our file-system callbacks (gltf_fs.cpp) and image decoder
//      (gltf_image.cpp), which record precise errors in the GltfLoadContext;
//   4. validate the model's references and ranges (gltf_validate.cpp);
//   5. convert images/materials, then nodes, converting meshes on first use.
#include "gltf_loader.hpp"

#include "gltf_context.hpp"
#include "gltf_fs.hpp"
#include "gltf_image.hpp"
#include "gltf_material.hpp"
#include "gltf_mesh.hpp"
#include "gltf_nodes.hpp"
#include "gltf_prescan.hpp"
#include "gltf_tinygltf.hpp"
#include "gltf_validate.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <new>
#include <optional>
#include <system_error>

namespace snell {
namespace detail {
namespace {

// tinygltf's error text on one line: its messages end with '\n' and several may accumulate.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
    text.pop_back();
  }
  std::replace(text.begin(), text.end(), '\n', ';');
  if (text.size() > 400) {
    text = text.substr(0, 400) + "...";
  }
  return text.empty() ? "unknown error" : text;
}

// The folder tinygltf joins URIs to: absolute, normal, without a trailing '/'.
std::string base_folder(const std::filesystem::path& base_dir) {
  std::error_code ec;
  std::filesystem::path base = std::filesystem::absolute(base_dir, ec);
  if (ec) {
    base = base_dir;
  }
  std::string text = base.lexically_normal().generic_string();
  while (text.size() > 1 && text.back() == '/') {
    text.pop_back();
  }
  return text;
}

Result<Scene> load(const std::uint8_t* data, std::size_t size,
                   const std::filesystem::path& base_dir, bool is_binary, const GltfLimits& limits,
                   const std::string& name) {
  GltfLoadContext ctx;
  ctx.name = name;
  ctx.limits = limits;
  const std::string base = base_folder(base_dir);
  ctx.base_dir = base;
  ctx.base_prefix = base == "/" ? base : base + "/";

  if (size > std::numeric_limits<std::uint32_t>::max()) {
    return ctx.fail(ErrorCode::limit_exceeded,
                    std::to_string(size) + " bytes; tinygltf reads glTF files under 4 GiB");
  }

  // 2. Pre-scan. When the container or the JSON cannot be read, tinygltf is still run, with every
  // file and image refused, only to obtain its own description of the problem.
  bool checked = false;
  if (is_binary) {
    if (const std::optional<GlbLayout> layout = parse_glb_layout(data, size)) {
      Result<bool> r = prescan_gltf_json(layout->json, true, layout->bin_size, ctx);
      if (!r) {
        return r.error();
      }
      checked = *r;
    }
  } else {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Result<bool> r = prescan_gltf_json(text, false, 0, ctx);
    if (!r) {
      return r.error();
    }
    checked = *r;
  }
  ctx.deny_all = !checked;

  // 3. tinygltf.
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(make_fs_callbacks(ctx));
  loader.SetImageLoader(&load_image_data, &ctx);
  tinygltf::Model model;
  std::string err;
  std::string warn;
  const auto length = static_cast<unsigned int>(size);
  bool ok = false;
  try {
    ok = is_binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, length, base)
                   : loader.LoadASCIIFromString(&model, &err, &warn,
                                                reinterpret_cast<const char*>(data), length, base);
  } catch (const std::bad_alloc&) {
    return ctx.fail(ErrorCode::out_of_memory, "out of memory while parsing");
  } catch (const std::exception& e) {
    // tinygltf is built with exceptions, and nlohmann/json may throw from inside it. A failure a
    // callback recorded before is the more precise report.
    return ctx.error ? *ctx.error
                     : ctx.fail(ErrorCode::parse_error,
                                std::string("not a valid glTF file: ") + e.what());
  }
  const std::string empty_hint = size == 0 ? " (empty file)" : "";
  if (!checked) {
    return ctx.fail(ErrorCode::parse_error,
                    "not a valid glTF file" + empty_hint + ": " +
                        (ok ? "unreadable container or JSON" : one_line(err)));
  }
  if (ctx.error) {
    return *ctx.error;
  }
  if (!ok) {
    return ctx.fail(ErrorCode::parse_error,
                    "not a valid glTF file" + empty_hint + ": " + one_line(err));
  }

  // 4. and 5.
  if (Result<void> r = validate_model(model, ctx); !r) {
    return r.error();
  }
  Scene scene;
  scene.name = std::filesystem::path(name).filename().string();
  if (Result<void> r = convert_materials(model, scene, ctx); !r) {
    return r.error();
  }
  GeometryTotals totals;
  if (Result<void> r = convert_nodes(model, scene, totals, ctx); !r) {
    return r.error();
  }
  return scene;
}

bool has_glb_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".glb";
}

} // namespace

Result<Scene> load_gltf_from_memory(const std::uint8_t* data, std::size_t size,
                                    const std::filesystem::path& base_dir, bool is_binary,
                                    const GltfLimits& limits, const std::string& name) {
  try {
    return load(data, size, base_dir, is_binary, limits, name);
  } catch (const std::bad_alloc&) {
    return fail(ErrorCode::out_of_memory, name + ": out of memory while loading");
  } catch (const std::exception& e) {
    return fail(ErrorCode::parse_error, name + ": " + e.what());
  }
}

} // namespace detail

Result<Scene> load_gltf(const std::filesystem::path& path, const GltfLimits& limits) {
  const std::string name = path.string();
  if (name.empty()) {
    return fail(ErrorCode::file_not_found, "load_gltf: empty path");
  }
  try {
    Result<std::vector<std::uint8_t>> bytes =
        detail::read_file_limited(path, limits.max_file_bytes, name);
    if (!bytes) {
      return bytes.error();
    }
    // The container decides, not the name: a .glb starts with "glTF". A file named .glb without
    // that magic is still handed to the binary parser, whose message says what is wrong.
    const bool binary = (bytes->size() >= 4 && std::memcmp(bytes->data(), "glTF", 4) == 0) ||
                        detail::has_glb_extension(path);
    std::error_code ec;
    std::filesystem::path folder = std::filesystem::absolute(path, ec).parent_path();
    if (ec) {
      folder = path.parent_path();
    }
    return detail::load_gltf_from_memory(bytes->data(), bytes->size(), folder, binary, limits,
                                         name);
  } catch (const std::bad_alloc&) {
    return fail(ErrorCode::out_of_memory, name + ": out of memory while loading");
  } catch (const std::exception& e) {
    return fail(ErrorCode::io_error, name + ": " + e.what());
  }
}

} // namespace snell
