// tinygltf's implementation, compiled once here with Draco decoding (Debian's libtinygltf is
// built without it) and without stb: images are kept as bytes, decoded where drawn (the
// switches are the module's compile definitions, the same for every file that includes it).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
