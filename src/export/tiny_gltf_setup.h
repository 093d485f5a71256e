// tinygltf as this project uses it: no image codecs (meshes carry no
// textures), so no stb dependency. Include this, never <tiny_gltf.h>
// directly, so every user sees the same declarations; gltf_writer.cpp holds
// the implementation.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
