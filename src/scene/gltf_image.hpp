// Internal: the image decoder the glTF loader gives tinygltf (TinyGLTF::SetImageLoader).
#pragma once

#include "gltf_tinygltf.hpp"

#include <string>

namespace snell::detail {

/// tinygltf::LoadImageDataFunction. `user_data` is the GltfLoadContext of the load.
/// Accepts PNG and JPEG (the glTF 2.0 core formats), reads the header with stbi_info_from_memory
/// and refuses images over GltfLimits::max_image_dimension / max_image_pixels /
/// max_total_image_pixels *before* decoding; decodes to RGBA8 (16-bit PNGs are reduced to 8 bits).
/// Failures are recorded in the context (unsupported, limit_exceeded, parse_error).
bool load_image_data(tinygltf::Image* image, int image_index, std::string* err, std::string* warn,
                     int req_width, int req_height, const unsigned char* bytes, int size,
                     void* user_data);

} // namespace snell::detail
