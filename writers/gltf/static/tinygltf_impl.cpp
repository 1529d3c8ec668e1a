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

namespace tinygltf {

// The default image callbacks, which the other files (compiled without the
// macros above, as for the shared library) name in TinyGLTF's constructor.
// smpl-export's models have no images, so these are never called; if one is,
// it fails with a message instead of decoding without stb_image.
bool LoadImageData(Image*, const int, std::string* err, std::string*, int, int,
                   const unsigned char*, int, void*) {
  if (err) *err += "images are not supported by this build (SMPL_STATIC)\n";
  return false;
}

bool WriteImageData(const std::string*, const std::string*, const Image*, bool,
                    std::string* out_uri, void*) {
  if (out_uri) out_uri->clear();
  return false;
}

}  // namespace tinygltf
