#include <sstream>

#include "lang/model_ir.h"

namespace sylva::lang {
namespace {

std::vector<std::string> split_types(const char* list) {
  std::vector<std::string> types;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
    if (b != std::string::npos) types.push_back(item.substr(b, e - b + 1));
  }
  return types;
}

}  // namespace

const std::vector<ModuleDecl>& predefined_modules() {
  static const std::vector<ModuleDecl> modules = [] {
    std::vector<ModuleDecl> list;
#define SYLVA_MODULE(name, ...) list.push_back(ModuleDecl{#name, split_types(#__VA_ARGS__), Token{}, {}});
#include "sylva/predefined_modules.def"
    return list;
  }();
  return modules;
}

}  // namespace sylva::lang
