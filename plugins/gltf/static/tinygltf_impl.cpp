// The static build's TinyGLTF (CMake option SMPL_STATIC): Debian ships
// TinyGLTF as a shared library only, so the static binary compiles the
// implementation from Debian's header, as its README.Debian describes. Images
// are never read or written by smpl-export, so stb_image is left out; the
// writer's code (WriteGltfSceneToStream) is the header's, as in the shared
// library, and the static binary's outputs are byte-identical to the dynamic
// build's (tests/package/static_chroot_test.sh).
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
