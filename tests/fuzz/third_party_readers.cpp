// The fuzz build compiles tinygltf and stb_image from Debian's headers instead of linking Debian's
// shared libraries (the same sources and version), so that coverage instrumentation and the
// sanitizers reach inside the third-party parsers too.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>  // includes stb_image.h and stb_image_write.h, with their implementations
