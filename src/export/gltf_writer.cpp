#define TINYGLTF_IMPLEMENTATION
#include "export/tiny_gltf_setup.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <cstring>
#include <map>
#include <sstream>

#include "export/mesh_support.h"
#include "export/mesh_writers.h"
#include "io/output_file.h"
#include "io/texture_image.h"
#include "support/diagnostic.h"

namespace sylva::io {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are written as the host's little-endian bytes");

using geometry::MeshPart;
using geometry::Vec3;

// Palette colours are what lpfg shows on screen, i.e. sRGB; glTF factors are linear.
double linear(float srgb) {
  double c = std::clamp(std::isfinite(srgb) ? static_cast<double>(srgb) : 0.0, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// A material per colour index, and a one-sided copy for parts with a back
// colour of their own (geometry/back_sides.h); two-sided ones first.
struct MaterialKey {
  bool one_sided = false;
  int color = 1;
  int texture = -1;
  auto operator<=>(const MaterialKey&) const = default;
};
MaterialKey material_key(const MeshPart& part, std::size_t texture_count) {
  const bool textured = part.texture >= 0 && static_cast<std::size_t>(part.texture) < texture_count;
  return {part.side != MeshPart::Side::Both, part.color, textured ? part.texture : -1};
}
using MaterialIndex = std::map<MaterialKey, int>;

tinygltf::Material material(int color, const geometry::Material& m, bool double_sided, int texture) {
  tinygltf::Material out;
  out.name = mesh_support::material_name(color) + (texture >= 0 ? "_texture_" + std::to_string(texture) : "") +
             (double_sided ? "" : "_one_sided");
  // The texture multiplies the colour, as OpenGL's modulate does in lpfg.
  if (texture >= 0) out.pbrMetallicRoughness.baseColorTexture.index = texture;
  double alpha = std::clamp(1.0 - static_cast<double>(m.transparency), 0.0, 1.0);
  out.pbrMetallicRoughness.baseColorFactor = {linear(m.diffuse.r), linear(m.diffuse.g), linear(m.diffuse.b), alpha};
  out.pbrMetallicRoughness.metallicFactor = 0;
  // The usual Blinn-Phong exponent to GGX roughness match.
  out.pbrMetallicRoughness.roughnessFactor = std::sqrt(2.0 / (std::max(0.0f, m.shininess) + 2.0));
  out.emissiveFactor = {linear(m.emission.r), linear(m.emission.g), linear(m.emission.b)};
  out.alphaMode = alpha < 1 ? "BLEND" : "OPAQUE";
  // Flat strips, discs and the turtle's polygons are seen from both sides,
  // unless the back has a colour of its own (a part of its own).
  out.doubleSided = double_sided;
  return out;
}

class GlbBuilder {
 public:
  GlbBuilder(const geometry::TriangleMesh& mesh, tinygltf::Model& model, std::size_t texture_count)
      : mesh_(mesh),
        model_(model),
        texture_count_(texture_count),
        stamp_(mesh.positions.size(), 0),
        remap_(mesh.positions.size()) {
    model_.buffers.emplace_back();
    model_.buffers[0].data.reserve(mesh.positions.size() * 2 * sizeof(Vec3) +
                                   (mesh.indices.size() + mesh.line_indices.size()) * sizeof(std::uint32_t) +
                                   (mesh.parts.size() + mesh.line_parts.size()) * 4 * sizeof(std::uint32_t));
  }

  // One primitive per colour: `per` indices an element (3 triangles, 2 lines).
  void add_primitives(const std::vector<MeshPart>& parts, const std::vector<std::uint32_t>& indices, int mode,
                      std::uint32_t per, const MaterialIndex& material_of, tinygltf::Mesh& out) {
    std::map<MaterialKey, std::vector<const MeshPart*>> by_material;
    for (const MeshPart& part : parts) by_material[material_key(part, texture_count_)].push_back(&part);
    for (const auto& [key, group] : by_material) {
      ++serial_;
      textured_ = key.texture >= 0 && !mesh_.texcoords.empty();
      positions_.clear();
      normals_.clear();
      texcoords_.clear();
      indices_.clear();
      records_.clear();
      for (const MeshPart* part : group) {
        std::uint32_t count = part->index_count - part->index_count % per;
        if (count == 0) continue;
        records_.insert(records_.end(), {static_cast<std::uint32_t>(indices_.size() / per), count / per,
                                         part->from.module_index, part->from.module_id});
        for (std::uint32_t k = 0; k < count; ++k) indices_.push_back(vertex(indices[part->first_index + k]));
      }
      if (indices_.empty()) continue;

      tinygltf::Primitive primitive;
      primitive.mode = mode;
      primitive.material = material_of.at(key);
      primitive.attributes["POSITION"] = accessor(view(positions_, TINYGLTF_TARGET_ARRAY_BUFFER), TINYGLTF_TYPE_VEC3,
                                                  TINYGLTF_COMPONENT_TYPE_FLOAT, positions_.size(), true);
      primitive.attributes["NORMAL"] = accessor(view(normals_, TINYGLTF_TARGET_ARRAY_BUFFER), TINYGLTF_TYPE_VEC3,
                                                TINYGLTF_COMPONENT_TYPE_FLOAT, normals_.size(), false);
      if (textured_)
        primitive.attributes["TEXCOORD_0"] = accessor(view(texcoords_, TINYGLTF_TARGET_ARRAY_BUFFER), TINYGLTF_TYPE_VEC2,
                                                      TINYGLTF_COMPONENT_TYPE_FLOAT, texcoords_.size(), false);
      primitive.indices = accessor(view(indices_, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER), TINYGLTF_TYPE_SCALAR,
                                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices_.size(), false);
      tinygltf::Value::Object provenance;
      provenance["bufferView"] = tinygltf::Value(view(records_, 0));
      provenance["count"] = tinygltf::Value(static_cast<int>(records_.size() / 4));
      provenance["layout"] = tinygltf::Value(std::string(
          "little-endian uint32 records: first element, element count, module index, module id"));
      tinygltf::Value::Object extras;
      extras["sylva_provenance"] = tinygltf::Value(std::move(provenance));
      primitive.extras = tinygltf::Value(std::move(extras));
      out.primitives.push_back(std::move(primitive));
    }
  }

  // Bytes of their own (an embedded image) as a buffer view.
  int add_bytes(const std::string& bytes) {
    std::vector<unsigned char> data(bytes.begin(), bytes.end());
    // Views that follow start on a 4-byte boundary, as glTF wants for accessors.
    while (data.size() % 4) data.push_back(0);
    const int v = view(data, 0);
    model_.bufferViews[static_cast<std::size_t>(v)].byteLength = bytes.size();
    return v;
  }

 private:
  std::uint32_t vertex(std::uint32_t i) {
    if (stamp_[i] != serial_) {
      stamp_[i] = serial_;
      remap_[i] = static_cast<std::uint32_t>(positions_.size());
      positions_.push_back(mesh_.positions[i]);
      normals_.push_back(i < mesh_.normals.size() ? mesh_.normals[i] : Vec3{0, 0, 1});
      // glTF's v runs down the image from its top row.
      if (textured_) {
        const geometry::TexCoord t = i < mesh_.texcoords.size() ? mesh_.texcoords[i] : geometry::TexCoord{};
        texcoords_.push_back({t.u, 1 - t.v});
      }
    }
    return remap_[i];
  }

  template <typename T>
  int view(const std::vector<T>& data, int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer.size();
    v.byteLength = data.size() * sizeof(T);
    v.target = target;
    buffer.resize(buffer.size() + v.byteLength);
    std::memcpy(buffer.data() + v.byteOffset, data.data(), v.byteLength);
    model_.bufferViews.push_back(std::move(v));
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  int accessor(int view, int type, int component_type, std::size_t count, bool bounds) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.type = type;
    a.componentType = component_type;
    a.count = count;
    if (bounds) {
      geometry::Box box;
      for (const Vec3& p : positions_) box.add(p);
      a.minValues = {box.min.x, box.min.y, box.min.z};
      a.maxValues = {box.max.x, box.max.y, box.max.z};
    }
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size() - 1);
  }

  const geometry::TriangleMesh& mesh_;
  tinygltf::Model& model_;
  std::size_t texture_count_;
  bool textured_ = false;
  std::vector<geometry::TexCoord> texcoords_;
  // remap_[i] is vertex i's index in the current primitive when stamp_[i] ==
  // serial_: no table to clear per primitive.
  std::vector<std::uint32_t> stamp_, remap_;
  std::uint32_t serial_ = 0;
  std::vector<Vec3> positions_, normals_;
  std::vector<std::uint32_t> indices_, records_;
};

}  // namespace

std::string encode_glb(const geometry::TriangleMesh& mesh, const geometry::Palette& palette, const ModuleTypes& types,
                       const std::vector<TextureImage>& textures, const std::string& provenance) {
  static_assert(sizeof(Vec3) == 12, "positions are copied as packed float triples");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Sylva";
  // Provenance (api/provenance.h): the run record's JSON, as a string.
  if (!provenance.empty()) {
    tinygltf::Value::Object asset_extras;
    asset_extras["sylva:provenance"] = tinygltf::Value(provenance);
    model.asset.extras = tinygltf::Value(std::move(asset_extras));
  }

  MaterialIndex material_of;
  for (const auto* parts : {&mesh.parts, &mesh.line_parts})
    for (const MeshPart& part : *parts) material_of.emplace(material_key(part, textures.size()), 0);
  // Each texture a material uses, its image embedded as PNG in the buffer.
  std::map<int, int> texture_of;
  std::vector<std::string> pngs;  // of model.images, in order
  for (auto& [key, index] : material_of) {
    int texture = -1;
    if (key.texture >= 0) {
      auto [at, added] = texture_of.emplace(key.texture, static_cast<int>(model.textures.size()));
      if (added) {
        tinygltf::Image image;
        image.name = "texture_" + std::to_string(key.texture);
        image.mimeType = "image/png";
        model.images.push_back(std::move(image));
        pngs.push_back(encode_texture_png(textures[static_cast<std::size_t>(key.texture)]));
        tinygltf::Texture t;
        t.source = static_cast<int>(model.images.size() - 1);
        model.textures.push_back(t);
      }
      texture = at->second;
    }
    index = static_cast<int>(model.materials.size());
    model.materials.push_back(material(key.color, palette.at(key.color), !key.one_sided, texture));
  }

  tinygltf::Mesh out;
  out.name = "sylva";
  {
    GlbBuilder builder(mesh, model, textures.size());
    builder.add_primitives(mesh.parts, mesh.indices, TINYGLTF_MODE_TRIANGLES, 3, material_of, out);
    builder.add_primitives(mesh.line_parts, mesh.line_indices, TINYGLTF_MODE_LINE, 2, material_of, out);
    for (std::size_t k = 0; k < pngs.size(); ++k) model.images[k].bufferView = builder.add_bytes(pngs[k]);
  }
  if (model.buffers[0].data.empty()) model.buffers.clear();

  tinygltf::Scene scene;
  // tinygltf writes a scene with no members as null, which readers reject.
  scene.name = "sylva";
  if (!out.primitives.empty()) {
    std::size_t name_count = types.size();
    for (const auto* parts : {&mesh.parts, &mesh.line_parts})
      for (const MeshPart& part : *parts) name_count = std::max<std::size_t>(name_count, part.from.module_id + 1u);
    tinygltf::Value::Array names;
    names.reserve(name_count);
    for (std::size_t id = 0; id < name_count; ++id)
      names.emplace_back(mesh_support::module_name(types, static_cast<abi::ModuleId>(id)));
    tinygltf::Value::Object extras;
    extras["sylva_module_names"] = tinygltf::Value(std::move(names));
    out.extras = tinygltf::Value(std::move(extras));
    model.meshes.push_back(std::move(out));
    tinygltf::Node node;
    node.name = "sylva";
    node.mesh = 0;
    model.nodes.push_back(std::move(node));
    scene.nodes.push_back(0);
  }
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;

  std::ostringstream stream;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&model, stream, false, true)) throw ModelError("cannot encode the glTF file");
  return std::move(stream).str();
}

void write_glb(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types, const std::vector<TextureImage>& textures, const std::string& provenance) {
  write_output_file(path, encode_glb(mesh, palette, types, textures, provenance));
}

}  // namespace sylva::io
