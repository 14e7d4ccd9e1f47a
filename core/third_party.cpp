// Implementations of header-only libraries, compiled only when the build found them as headers
// (cmake/Dependencies.cmake: vcpkg's stb and tinygltf). Debian's packages ship them compiled, and then
// this file is empty.
#if defined(SHADOWLAB_STB_IMPLEMENTATION)
#define STB_IMAGE_IMPLEMENTATION  // tinygltf decodes images with it
#define STB_IMAGE_WRITE_IMPLEMENTATION
#endif
#if defined(SHADOWLAB_TINYGLTF_IMPLEMENTATION)
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
#elif defined(SHADOWLAB_STB_IMPLEMENTATION)
#include <stb_image.h>
#include <stb_image_write.h>
#endif
