// Internal: the sandboxed file access of the glTF loader (see gltf_fs.hpp).
//
// tinygltf 2.7 resolves an external URI by calling ExpandFilePath(JoinPath(dir, uri)) and then
// FileExists on the result, first for dir = the folder we pass and then for dir = "." (the
// process's working directory), and finally ReadWholeFile. These callbacks allow only the first
// form, re-check the URI policy there, and confine the resolved file to the model's folder.
#include "gltf_fs.hpp"

#include "gltf_uri.hpp"

#include <fstream>
#include <optional>
#include <system_error>

namespace snell::detail {
namespace {

namespace fs = std::filesystem;

GltfLoadContext& context(void* user_data) {
  return *static_cast<GltfLoadContext*>(user_data);
}

// The URI part of a path tinygltf built from our folder, or nullopt when the path was not built
// from it (tinygltf's fallback to the working directory).
std::optional<std::string> relative_part(const GltfLoadContext& ctx, const std::string& path) {
  if (path.size() < ctx.base_prefix.size() ||
      path.compare(0, ctx.base_prefix.size(), ctx.base_prefix) != 0) {
    return std::nullopt;
  }
  return path.substr(ctx.base_prefix.size());
}

// True when `target` (an existing file) resolves inside the model's folder. Symbolic links are
// followed on both sides, so a link inside the folder that points outside it is refused, while a
// model folder reached through a link is fine.
bool inside_base(const GltfLoadContext& ctx, const fs::path& target) {
  std::error_code ec;
  const fs::path base = fs::canonical(ctx.base_dir, ec);
  if (ec) {
    return false;
  }
  const fs::path resolved = fs::canonical(target, ec);
  if (ec) {
    return false;
  }
  const fs::path rel = resolved.lexically_relative(base);
  return !rel.empty() && *rel.begin() != "..";
}

std::string expand_file_path(const std::string& path, void* user_data) {
  GltfLoadContext& ctx = context(user_data);
  if (ctx.deny_all) {
    return {};
  }
  const std::optional<std::string> rel = relative_part(ctx, path);
  if (!rel) {
    return {}; // Never search the working directory.
  }
  if (const std::optional<std::string> why = uri_path_violation(*rel)) {
    ctx.record(ErrorCode::access_denied,
               "file reference '" + clip_for_message(*rel) + "' refused: it " + *why);
    return {};
  }
  // RFC 3986 removes dot segments before a reference is resolved ("sub/../a.bin" is "a.bin",
  // whether or not a folder "sub" exists); uri_path_violation has ensured none climbs out.
  return ctx.base_prefix + fs::path(*rel).lexically_normal().generic_string();
}

bool file_exists(const std::string& path, void* user_data) {
  GltfLoadContext& ctx = context(user_data);
  const std::optional<std::string> rel = relative_part(ctx, path);
  if (ctx.deny_all || path.empty() || !rel) {
    return false;
  }
  std::error_code ec;
  const fs::file_status status = fs::status(fs::path(path), ec);
  if (ec || !fs::exists(status)) {
    ctx.record(ErrorCode::file_not_found, "referenced file '" + clip_for_message(*rel) +
                                              "' not found in '" + ctx.base_dir.string() + "'");
    return false;
  }
  if (!fs::is_regular_file(status)) {
    ctx.record(ErrorCode::file_not_found,
               "referenced file '" + clip_for_message(*rel) + "' " +
                   (fs::is_directory(status) ? "is a folder" : "is not a regular file"));
    return false;
  }
  if (!inside_base(ctx, fs::path(path))) {
    ctx.record(ErrorCode::access_denied, "file reference '" + clip_for_message(*rel) +
                                             "' refused: it resolves (through a symbolic link) "
                                             "outside the model's folder");
    return false;
  }
  return true;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user_data) {
  GltfLoadContext& ctx = context(user_data);
  // tinygltf only passes paths that file_exists accepted; checked again so that this callback is
  // safe on its own.
  const std::optional<std::string> rel = relative_part(ctx, path);
  if (ctx.deny_all || !rel || uri_path_violation(*rel) || !inside_base(ctx, fs::path(path))) {
    if (err != nullptr) {
      *err += "snell: file access refused";
    }
    if (!ctx.deny_all) {
      ctx.record(ErrorCode::access_denied,
                 "file reference '" + clip_for_message(rel.value_or(path)) + "' refused");
    }
    return false;
  }
  Result<std::vector<std::uint8_t>> data =
      read_file_limited(fs::path(path), ctx.limits.max_file_bytes,
                        "referenced file '" + clip_for_message(*rel) + "'");
  if (!data) {
    ctx.record(data.error().code, data.error().message);
    if (err != nullptr) {
      *err += data.error().message;
    }
    return false;
  }
  *out = std::move(*data);
  return true;
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
  if (err != nullptr) {
    *err += "snell: the glTF loader never writes files";
  }
  return false;
}

} // namespace

Result<std::vector<std::uint8_t>> read_file_limited(const fs::path& path, std::uint64_t max_bytes,
                                                    const std::string& label) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    return fail(ErrorCode::file_not_found, label + ": file not found");
  }
  if (fs::is_directory(status)) {
    return fail(ErrorCode::file_not_found, label + ": is a folder, not a file");
  }
  if (!fs::is_regular_file(status)) {
    return fail(ErrorCode::file_not_found, label + ": not a regular file");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) {
    return fail(ErrorCode::io_error, label + ": cannot read its size: " + ec.message());
  }
  if (size > max_bytes) {
    return fail(
        ErrorCode::limit_exceeded,
        label + ": file is " + std::to_string(size) +
            " bytes, over the limit GltfLimits::max_file_bytes = " + std::to_string(max_bytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return fail(ErrorCode::io_error, label + ": cannot open the file");
  }
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) {
    return fail(ErrorCode::io_error, label + ": read " + std::to_string(in.gcount()) + " of " +
                                         std::to_string(size) + " bytes");
  }
  return bytes;
}

tinygltf::FsCallbacks make_fs_callbacks(GltfLoadContext& ctx) {
  tinygltf::FsCallbacks callbacks{};
  callbacks.FileExists = &file_exists;
  callbacks.ExpandFilePath = &expand_file_path;
  callbacks.ReadWholeFile = &read_whole_file;
  callbacks.WriteWholeFile = &write_whole_file;
  callbacks.user_data = &ctx;
  return callbacks;
}

} // namespace snell::detail
