// The fuzzers compile stb's PNG decoder and zlib compressor from Debian's headers (libstb-dev), so
// that they are instrumented for coverage and the sanitizers; the normal builds link libstb.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>
