// Internal: the state one glTF load shares between the loader and tinygltf's callbacks.
#pragma once

#include <snell/result.hpp>
#include <snell/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

namespace snell::detail {

/// One load: what is being loaded, from where, under which limits, and the first failure that a
/// tinygltf callback (file system, image decoder) reported. tinygltf only passes booleans and
/// free-text back, so the callbacks record the precise Error here and the loader returns it in
/// preference to tinygltf's own message.
struct GltfLoadContext {
  std::string name;                 ///< The model as the user named it: prefix of every message.
  std::filesystem::path base_dir;   ///< Absolute, lexically normal folder of the model.
  std::string base_prefix;          ///< base_dir as tinygltf joins URIs to it, ending with '/'.
  GltfLimits limits;                ///< Limits of this load.
  bool deny_all = false;            ///< Refuse every file and image (see gltf_loader.cpp).
  std::optional<Error> error;       ///< First failure recorded by a callback.
  std::uint64_t decoded_pixels = 0; ///< Pixels decoded so far (GltfLimits::max_total_image_pixels).

  /// An Error whose message is "<model>: <what>".
  [[nodiscard]] Error fail(ErrorCode code, const std::string& what) const {
    return Error{code, name + ": " + what};
  }
  /// Records "<model>: <what>" unless an earlier failure is already recorded (the first one is
  /// the cause; later ones are usually its consequences).
  void record(ErrorCode code, const std::string& what) {
    if (!error) {
      error = fail(code, what);
    }
  }
};

/// "mesh 3 'Body'" (or "mesh 3" when unnamed): how messages name a glTF object.
[[nodiscard]] inline std::string describe(const char* kind, std::size_t index,
                                          const std::string& object_name = {}) {
  std::string text = std::string(kind) + " " + std::to_string(index);
  if (!object_name.empty()) {
    text +=
        " '" + (object_name.size() > 60 ? object_name.substr(0, 60) + "..." : object_name) + "'";
  }
  return text;
}

} // namespace snell::detail
