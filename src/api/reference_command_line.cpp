#include "api/reference_command_line.h"

#include <cctype>
#include <stdexcept>

#include "inputs/input_text.h"

namespace sylva {
namespace {

// What a reference option does in a run without a window.
enum class Effect {
  None,            // already what Sylva does (batch mode, no graphics)
  Ignored,         // only meaningful in the reference program's window: a note
  Output,          // names an output file (lpfg's -out, cpfg's -png FILE ...)
  Environment,     // -e FILE
  WindowSize,      // -w W H
  CleanEa20,
  CompileOnly,
};

struct ReferenceOption {
  const char* name;
  int values;     // how many arguments follow it
  Effect effect;
  const char* what;  // for the note when it is ignored
};

// lpfg's options (comlineparam.cpp) and cpfg's (control.c) by exact spelling;
// -m, -M, -s and -c with a number attached are recognised apart.
constexpr ReferenceOption kOptions[] = {
    {"-a", 0, Effect::Ignored, "starting in animation mode"},
    {"-b", 0, Effect::None, "batch mode"},
    {"-g", 0, Effect::None, "no graphics"},
    {"-d", 0, Effect::Ignored, "the reference program's debug mode"},
    {"-V", 0, Effect::Ignored, "cpfg's verbose mode"},
    {"-q", 0, Effect::Ignored, "lpfg's quiet mode"},
    {"-c", 0, Effect::CompileOnly, "compiling only"},
    {"-cn", 0, Effect::Ignored, "lpfg's numeric checks"},
    {"-e", 1, Effect::Environment, "the environment"},
    {"-out", 1, Effect::Output, "lpfg's output file"},
    {"-w", 2, Effect::WindowSize, "the window size"},
    {"-wp", 2, Effect::Ignored, "the window position"},
    {"-wr", 2, Effect::Ignored, "the window size relative to the screen"},
    {"-wpr", 2, Effect::Ignored, "the window position relative to the screen"},
    {"-wt", 1, Effect::Ignored, "the window title"},
    {"-wnb", 0, Effect::Ignored, "a window without border"},
    {"-wnm", 0, Effect::Ignored, "a window without message log"},
    {"-mb", 0, Effect::Ignored, "the menu bar"},
    {"-rmode", 1, Effect::Ignored, "the recording mode"},
    {"-lp", 1, Effect::Ignored, "lpfg's installation path"},
    {"-dll", 1, Effect::Ignored, "a precompiled L-system library (Sylva compiles the model itself)"},
    {"-P", 1, Effect::Ignored, "cpfg's preprocessor (Sylva preprocesses the model itself)"},
    {"-C", 1, Effect::Ignored, "cpfg's distributed communication"},
    {"-S", 1, Effect::Ignored, "cpfg's server socket"},
    {"-pipestrb", 0, Effect::Ignored, "cpfg's string pipe"},
    {"-tablet", 0, Effect::Ignored, "the tablet mode"},
    {"-timer", 0, Effect::Ignored, "lpfg's timer"},
    {"-timed", 0, Effect::Ignored, "lpfg's timed mode"},
    {"-ds", 0, Effect::Ignored, "dumping the string on a key"},
    {"-dtf", 0, Effect::Ignored, "interpreting into a text file"},
    {"-dtfes", 0, Effect::Ignored, "writing the string every step"},
    {"-cleanEA20", 0, Effect::CleanEa20, ""},
    // cpfg's files to save to, one option per format.
    {"-str", 1, Effect::Output, "the string file"},
    {"-png", 1, Effect::Output, "the PNG image"},
    {"-ps", 1, Effect::Output, "the PostScript drawing"},
    {"-obj", 1, Effect::Output, "the OBJ mesh"},
    {"-rgb", 1, Effect::Ignored, "an SGI RGB image (not a format Sylva writes)"},
    {"-bmp", 1, Effect::Ignored, "a BMP image (not a format Sylva writes)"},
    {"-gif", 1, Effect::Ignored, "a GIF image (not a format Sylva writes)"},
    {"-jpg", 1, Effect::Ignored, "a JPEG image (not a format Sylva writes)"},
    {"-pbm", 1, Effect::Ignored, "a PBM image (not a format Sylva writes)"},
    {"-tiff", 1, Effect::Ignored, "a TIFF image (not a format Sylva writes)"},
    {"-ras", 1, Effect::Ignored, "a Sun raster image (not a format Sylva writes)"},
    {"-tga", 1, Effect::Ignored, "a Targa image (not a format Sylva writes)"},
    {"-rle", 1, Effect::Ignored, "an RLE image (not a format Sylva writes)"},
    {"-ray", 1, Effect::Ignored, "a Rayshade scene (not a format Sylva writes)"},
    {"-vv", 1, Effect::Ignored, "a view volume file (not a format Sylva writes)"},
    {"-strb", 1, Effect::Ignored, "a binary string (Sylva writes strings as text: use --string)"},
    {"-gls", 1, Effect::Ignored, "a GLS file (not a format Sylva writes)"},
};

const ReferenceOption* find_option(const std::string& name) {
  for (const ReferenceOption& option : kOptions)
    if (name == option.name) return &option;
  return nullptr;
}

// "-m", "-m2", "-M", "-M3": a colormap or material file follows; its number.
std::optional<int> colour_file_option(const std::string& name, char letter) {
  if (name.size() < 2 || name[0] != '-' || name[1] != letter) return std::nullopt;
  if (name.size() == 2) return 1;
  int number = 0;
  for (std::size_t i = 2; i < name.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(name[i])) || number > 1000) return std::nullopt;
    number = number * 10 + (name[i] - '0');
  }
  return number;
}

// "-s100000" (cpfg's string size) or "-c2" (cpfg's colormap number): a
// letter with a number attached.
bool letter_with_number(const std::string& name, char letter) {
  if (name.size() < 3 || name[0] != '-' || name[1] != letter) return false;
  for (std::size_t i = 2; i < name.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return false;
  return true;
}

bool is_option(const std::string& argument) { return argument.size() > 1 && argument[0] == '-'; }

// A file on the command line: its kind known from the option before it, or
// (Unknown) to be recognised from its name and place.
struct Named {
  io::InputFile file;
  bool positional;
};

// lpfg's -out and cpfg's format options: strings go to --string, the rest
// to the outputs Sylva writes.
void add_output(ReferenceCommandLine& line, const std::string& option, const std::string& path) {
  const std::string ext = io::extension_of(path);
  if (option == "-str" || ext == "str" || ext == "txt") {
    line.string_path = path;
  } else if (ext == "strb" || ext == "bin") {
    line.notes.push_back(option + " " + path + ": binary strings are not written; use --string for text");
  } else if (ext == "obj" || ext == "png" || ext == "pdf" || ext == "ps") {
    line.outputs.push_back(path);
  } else {
    line.notes.push_back(option + " " + path + ": not a format Sylva writes (.str, .obj, .png, .pdf, .ps); ignored");
  }
}

// Which positional file is the model: the .l file (the last, as lpfg keeps
// the last of each kind), else the first (cpfg's order). -1 if none.
int model_index(const std::vector<Named>& named, std::vector<std::string>& notes) {
  int model = -1, first = -1;
  for (int i = 0; i < static_cast<int>(named.size()); ++i) {
    if (!named[i].positional) continue;
    if (first < 0) first = i;
    if (io::extension_of(named[i].file.path) != "l") continue;
    if (model >= 0) notes.push_back(named[model].file.path + ": a second L-system, " + named[i].file.path +
                                    ", replaces it, as in lpfg");
    model = i;
  }
  return model >= 0 ? model : first;
}

}  // namespace

ReferenceCommandLine read_reference_command_line(const std::vector<std::string>& arguments,
                                                 const SylvaOptionArity& sylva_option) {
  ReferenceCommandLine line;
  std::vector<Named> named;
  bool help = false;
  auto value = [&](std::size_t& i, const std::string& option, const char* what) -> const std::string& {
    if (i + 1 >= arguments.size()) throw std::invalid_argument(option + " needs " + what + " after it");
    return arguments[++i];
  };
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (!is_option(argument)) {
      named.push_back({io::InputFile(argument), true});
      continue;
    }
    if (argument.rfind("--", 0) == 0) {  // long options are Sylva's
      line.sylva_arguments.push_back(argument);
      const std::optional<int> count = sylva_option(argument.substr(0, argument.find('=')));
      if (count && argument.find('=') == std::string::npos)
        for (int k = 0; k < *count && i + 1 < arguments.size(); ++k) line.sylva_arguments.push_back(arguments[++i]);
      continue;
    }
    if (argument == "-h") {  // cpfg's homomorphism flag, or Sylva's help
      help = true;
      continue;
    }
    if (std::optional<int> number = colour_file_option(argument, 'm')) {
      named.push_back({io::InputFile(value(i, argument, "a colormap file"), io::InputKind::Colormap, *number), false});
      continue;
    }
    if (std::optional<int> number = colour_file_option(argument, 'M')) {
      named.push_back({io::InputFile(value(i, argument, "a material file"), io::InputKind::Materials, *number), false});
      continue;
    }
    if (letter_with_number(argument, 's')) {
      line.notes.push_back(argument + ": cpfg's string size; Sylva's strings grow as they need; ignored");
      continue;
    }
    if (letter_with_number(argument, 'c')) {
      line.notes.push_back(argument + ": cpfg's colormap number; ignored");
      continue;
    }
    if (const ReferenceOption* option = find_option(argument)) {
      std::vector<std::string> values;
      for (int k = 0; k < option->values; ++k) values.push_back(value(i, argument, "a value"));
      switch (option->effect) {
        case Effect::None:
          break;
        case Effect::Ignored: {
          std::string shown = argument;
          for (const std::string& v : values) shown += " " + v;
          line.notes.push_back(shown + ": " + option->what + " has no meaning without a window; ignored");
          break;
        }
        case Effect::Output:
          add_output(line, argument, values[0]);
          break;
        case Effect::Environment:
          named.push_back({io::InputFile(values[0], io::InputKind::Environment), false});
          break;
        case Effect::WindowSize: {
          const std::optional<int> w = io::parse_int(values[0]), h = io::parse_int(values[1]);
          if (!w || !h || *w <= 0 || *h <= 0)
            throw std::invalid_argument("-w needs the window's width and height in pixels, not '" + values[0] +
                                        " " + values[1] + "'");
          line.width = *w;
          line.height = *h;
          break;
        }
        case Effect::CleanEa20:
          line.clean_ea20 = true;
          break;
        case Effect::CompileOnly:
          line.compile_only = true;
          break;
      }
      continue;
    }
    // Sylva's short options, with a value apart ("-o x.png") or attached ("-ox.png").
    line.sylva_arguments.push_back(argument);
    std::optional<int> count = sylva_option(argument);
    if (count)
      for (int k = 0; k < *count && i + 1 < arguments.size(); ++k) line.sylva_arguments.push_back(arguments[++i]);
  }

  const int model = model_index(named, line.notes);
  if (model >= 0) line.model = named[model].file.path;
  if (help) {
    if (model >= 0) line.interpreted_string = true;
    else line.sylva_arguments.push_back("-h");
  }
  // cpfg reads the files after the L-system by place: the view file, then
  // the animation file, whatever their names.
  int place = 0;
  const bool model_first = model >= 0 && [&] {
    for (int i = 0; i < model; ++i)
      if (named[i].positional) return false;
    return true;
  }();
  for (int i = 0; i < static_cast<int>(named.size()); ++i) {
    if (i == model) continue;
    io::InputFile file = named[i].file;
    if (named[i].positional && model_first && i > model) {
      ++place;
      if (file.kind == io::InputKind::Unknown && place == 1) file.kind = io::InputKind::View;
      if (file.kind == io::InputKind::Unknown && place == 2) file.kind = io::InputKind::Animation;
    }
    if (named[i].positional && io::extension_of(file.path) == "l") continue;  // noted by model_index
    line.inputs.push_back(std::move(file));
  }
  return line;
}

}  // namespace sylva
