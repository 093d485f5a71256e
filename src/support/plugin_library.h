// Plugins: parts of Sylva built as shared libraries of their own (libsylva_gl.so
// and the like, beside the program) because the libraries they link take long
// to load or much memory (OSMesa with LLVM, cairo, GraphicsMagick). The
// program opens one only when it needs what it does, so a run that writes a
// string loads none of them.
//
// A plugin exports one `extern "C"` function (marked SYLVA_PLUGIN_EXPORT) that
// returns its one object, an implementation of an abstract class declared in
// the plugin's door header; everything else in it stays hidden. Plugin and
// program are built together, from the same headers, so C++ types may cross.
#pragma once

#include <string>

#define SYLVA_PLUGIN_EXPORT __attribute__((visibility("default")))

namespace sylva {

// The address of `symbol` in plugin `file_name`, opened once: from the running
// program's folder, else from the build tree's. Throws ModelError saying
// what the plugin is for (`purpose`), where it was looked for and why it
// could not be opened.
void* plugin_symbol(const std::string& file_name, const char* symbol, const std::string& purpose);

// The object made by the plugin's factory `symbol`, a `T* ()` function.
template <class T>
T& plugin_object(const std::string& file_name, const char* symbol, const std::string& purpose) {
  auto* factory = reinterpret_cast<T* (*)()>(plugin_symbol(file_name, symbol, purpose));
  return *factory();
}

}  // namespace sylva
