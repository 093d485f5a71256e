#include <cstdio>
#include <filesystem>

#include "export/mesh_support.h"
#include "export/mesh_writers.h"
#include "io/output_file.h"
#include "support/diagnostic.h"

namespace sylva::io {
namespace {

using geometry::MeshPart;
using geometry::Rgb;
using mesh_support::append_number;

void append_rgb(std::string& out, const char* key, Rgb c) {
  out += key;
  for (float v : {c.r, c.g, c.b}) {
    out += ' ';
    append_number(out, v);
  }
  out += '\n';
}

std::string material_library(const geometry::TriangleMesh& mesh, const geometry::Palette& palette) {
  std::string out = "# Sylva materials, one per colour index\n";
  for (int color : mesh_support::colors_used(mesh)) {
    const geometry::Material& m = palette.at(color);
    out += "\nnewmtl " + mesh_support::material_name(color) + "\n";
    append_rgb(out, "Ka", m.ambient);
    append_rgb(out, "Kd", m.diffuse);
    append_rgb(out, "Ks", m.specular);
    append_rgb(out, "Ke", m.emission);
    // Both are the Phong exponent; MTL only allows a wider range.
    out += "Ns ";
    append_number(out, m.shininess);
    out += "\nd ";
    append_number(out, 1 - m.transparency);
    out += "\nillum 2\n";
  }
  return out;
}

// Group names are single OBJ tokens.
std::string group_name(const ModuleTypes& types, geometry::Provenance from) {
  std::string name = mesh_support::module_name(types, from.module_id);
  for (char& c : name)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '#') c = '_';
  return name + "_" + std::to_string(from.module_index);
}

// `element` is "f" or "l"; `per` the indices an element takes.
void append_parts(std::string& out, const std::vector<MeshPart>& parts, const std::vector<std::uint32_t>& indices,
                  const char* element, std::uint32_t per, const ModuleTypes& types) {
  const MeshPart* previous = nullptr;
  for (const MeshPart& part : parts) {
    // Parts of one module in a row (a module that drew several primitives)
    // share a group, so readers that make an object per group make fewer.
    bool same_module = previous && previous->from.module_index == part.from.module_index &&
                       previous->from.module_id == part.from.module_id;
    if (!same_module) out += "g " + group_name(types, part.from) + "\n";
    // After every `g`: readers differ on whether a material outlives a group.
    if (!same_module || previous->color != part.color)
      out += "usemtl " + mesh_support::material_name(part.color) + "\n";
    for (std::uint32_t k = 0; k + per <= part.index_count; k += per) {
      out += element;
      for (std::uint32_t j = 0; j < per; ++j) {
        std::uint64_t v = std::uint64_t{indices[part.first_index + k + j]} + 1;
        out += ' ';
        append_number(out, v);
        if (per == 3) {
          out += "//";
          append_number(out, v);
        }
      }
      out += '\n';
    }
    previous = &part;
  }
}

std::string obj_text(const geometry::TriangleMesh& mesh, const ModuleTypes& types, const std::string& library,
                     const std::string& provenance) {
  std::string out;
  out.reserve(mesh.positions.size() * 64 + mesh.indices.size() * 12 + (mesh.parts.size() + mesh.line_parts.size()) * 32);
  out += "# Sylva mesh: groups are Module_index (the module and its position in the string)\n";
  if (!provenance.empty()) out += "# sylva:provenance " + provenance + "\n";  // api/provenance.h
  if (!library.empty()) out += "mtllib " + library + "\n";
  for (const auto* list : {&mesh.positions, &mesh.normals}) {
    const char* key = list == &mesh.positions ? "v" : "vn";
    for (const geometry::Vec3& p : *list) {
      out += key;
      for (float v : {p.x, p.y, p.z}) {
        out += ' ';
        append_number(out, v);
      }
      out += '\n';
    }
  }
  append_parts(out, mesh.parts, mesh.indices, "f", 3, types);
  append_parts(out, mesh.line_parts, mesh.line_indices, "l", 2, types);
  return out;
}

}  // namespace

void write_obj(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types, const std::string& provenance) {
  if (path == "-") {
    write_output_file(path, obj_text(mesh, types, "", provenance));
    return;
  }
  namespace fs = std::filesystem;
  fs::path library = fs::path(path).replace_extension(".mtl");
  if (library == fs::path(path)) library = fs::path(path + ".mtl");
  // The library goes first, so an OBJ on disk never names a missing one; it
  // is removed again if the OBJ then fails and there was none before.
  std::error_code error;
  bool library_existed = fs::exists(library, error);
  try {
    write_output_file(library.string(), material_library(mesh, palette));
  } catch (const ModelError& e) {
    throw ModelError(SourceLocation{path, 0, 0}, "material file " + library.string() + ": " + e.message());
  }
  try {
    write_output_file(path, obj_text(mesh, types, library.filename().string(), provenance));
  } catch (...) {
    if (!library_existed) fs::remove(library, error);
    throw;
  }
}

void write_obj(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types) {
  write_obj(path, mesh, palette, types, std::string());
}

}  // namespace sylva::io
