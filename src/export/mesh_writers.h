// Mesh files of a tessellated Scene: Wavefront OBJ (+ MTL), binary PLY and
// binary glTF 2.0. Every file is written whole or not at all (a failure
// throws ModelError naming the path and leaves no partial file), and every
// format keeps provenance: which module, at which index of the interpreted
// string, made each triangle.
//
//  OBJ  one `g Name_index` per run of parts with the same provenance (e.g.
//       `g F_12`: module F at index 12), `usemtl color_N` per colour index;
//       materials in an MTL file beside it (same name, extension .mtl).
//       Pixel lines are `l` elements. "-" writes the OBJ alone to standard
//       output.
//  PLY  binary little endian; vertices with normals and colours (the diffuse
//       colour, alpha from transparency); faces with `module_index` and
//       `module_id`; pixel lines as the `edge` element, with the same two.
//  GLB  see write_glb.
//
// `provenance`, when not empty, is the run record's one-line JSON
// (api/provenance.h): OBJ `# sylva:provenance {json}` after the first
// comment, PLY `comment sylva:provenance {json}` in the header, GLB
// asset.extras["sylva:provenance"] (the JSON as a string).
#pragma once

#include <string>

#include "geometry/material.h"
#include "geometry/tessellation.h"
#include "io/texture_image.h"
#include "lstring/module_types.h"

namespace sylva::io {

void write_obj(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types);
void write_obj(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types, const std::string& provenance);

void write_ply(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types);
void write_ply(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types, const std::string& provenance);

// One mesh in one node; the mesh has one primitive per colour index used
// (triangles), and one per colour for pixel lines, each with the material
// `color_N`: base colour from the diffuse colour (alpha = 1 - transparency),
// emissive from the emission, roughness from the shininess; colours are
// taken as sRGB and stored linear, as glTF wants.
//
// Provenance stays out of the JSON so a million parts stay cheap: each
// primitive's extras hold {"sylva_provenance": {"bufferView": B, "count": N,
// "layout": ...}}, where buffer view B holds N records of four little-endian
// uint32: first element (triangle or line, counted within the primitive),
// element count, module index, module id. The mesh's extras hold
// {"sylva_module_names": [...]}: module names by module id.
// Textured parts (MeshPart::texture, an index into `textures`) get a
// material of their own whose base colour texture is that image, embedded
// as PNG, with TEXCOORD_0 from the mesh's texture coordinates.
void write_glb(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types, const std::vector<TextureImage>& textures = {},
               const std::string& provenance = {});
// The bytes write_glb writes.
std::string encode_glb(const geometry::TriangleMesh& mesh, const geometry::Palette& palette, const ModuleTypes& types,
                       const std::vector<TextureImage>& textures = {}, const std::string& provenance = {});

}  // namespace sylva::io
