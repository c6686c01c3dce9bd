// Internal: the one way Snell includes tinygltf. Every translation unit that sees tinygltf's types
// must see the same configuration macros (they change inline member initialisers of
// tinygltf::TinyGLTF), so nobody includes <tiny_gltf.h> directly.
#pragma once

// No default file-system callbacks: every file access goes through gltf_fs.cpp (sandboxed).
#define TINYGLTF_NO_FS
// No built-in image decoding or writing: images are decoded by gltf_image.cpp, which checks the
// dimensions against GltfLimits before decoding.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE

#include <tiny_gltf.h>
