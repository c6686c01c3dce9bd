// The only translation unit that compiles the implementations of the header-only third-party
// libraries used by Snell: tinygltf, stb_image (decoding) and stb_image_write (PNG output for the
// runtime). It is compiled with -w (see src/CMakeLists.txt): their warnings are not ours to fix.
//
// tinygltf is compiled here from the Debian header rather than linked from libtinygltf.so, so
// that its configuration (gltf_tinygltf.hpp: no default file system, no built-in image loader)
// is ours and identical in every TU.

// nlohmann/json first, at default visibility: tinygltf would include it inside
// `#pragma GCC visibility push(hidden)`, which would give its inline functions a different
// visibility here than in gltf_prescan.cpp, which uses nlohmann/json too.
#include <nlohmann/json.hpp>

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h> // /usr/include/stb (SYSTEM PRIVATE include directory of snell_scene)

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

// tinygltf 2.7's writer uses std::ofstream even under TINYGLTF_NO_FS, which drops <fstream>.
// (Snell never calls the writer; it only has to compile.)
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include "gltf_tinygltf.hpp"
