#include "app/script.h"

#include <charconv>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "app/shortcuts.h"
#include "core/error.h"
#include "radiosity/radiosity_options.h"

namespace luz::app {
namespace {

bool is_int(const std::string& text) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

bool is_number(const std::string& text) {
  try {
    size_t used = 0;
    std::stof(text, &used);
    return used == text.size();
  } catch (...) {
    return false;
  }
}

// `radiosity WHAT [VALUE]`: the loop's controls, the mesh and the display switches of model 5.
std::string check_radiosity(const ScriptCommand& c) {
  const auto& a = c.args;
  if (a.empty()) return "`radiosity` takes run, pause, reset, step N, patch-size M, hemicube N, budget MS or a switch";
  const std::string& what = a[0];
  if (what == "run" || what == "pause" || what == "reset")
    return a.size() == 1 ? "" : fmt::format("`radiosity {}` takes no value", what);
  if (a.size() != 2) return fmt::format("`radiosity {}` takes one value", what);
  const std::string& value = a[1];
  if (what == "step") return is_int(value) && std::stoi(value) >= 1 ? "" : "`radiosity step N` takes N >= 1";
  if (what == "patch-size")
    return is_number(value) && std::stof(value) >= 0.0f ? "" : "`radiosity patch-size M` takes metres >= 0 (0: auto)";
  if (what == "hemicube") {
    const bool fits = is_int(value) && std::stoi(value) >= kMinHemicubeRes && std::stoi(value) <= kMaxHemicubeRes &&
                      std::stoi(value) % 2 == 0;
    return fits ? "" : fmt::format("`radiosity hemicube N` takes an even N in {} .. {}", kMinHemicubeRes, kMaxHemicubeRes);
  }
  if (what == "budget") return is_number(value) && std::stof(value) > 0.0f ? "" : "`radiosity budget MS` takes milliseconds > 0";
  for (const char* name : {"heat-map", "outlines", "flat-patches", "ambient-estimate", "shooter", "item-buffer", "rotation"})
    if (what == name) return value == "on" || value == "off" ? "" : fmt::format("`radiosity {}` takes on or off", name);
  return fmt::format("unknown radiosity setting \"{}\" (run, pause, reset, step, patch-size, hemicube, budget, "
                     "heat-map, outlines, flat-patches, ambient-estimate, shooter, item-buffer, rotation)", what);
}

// `solvers WHAT [VALUE]`: slide 36's window.
std::string check_solvers(const ScriptCommand& c) {
  const auto& a = c.args;
  if (a.empty()) return "`solvers` takes open, close, run, pause, reset, budget MS or patches N";
  const std::string& what = a[0];
  if (what == "open" || what == "close" || what == "run" || what == "pause" || what == "reset")
    return a.size() == 1 ? "" : fmt::format("`solvers {}` takes no value", what);
  if (a.size() != 2) return fmt::format("`solvers {}` takes one value", what);
  if (what == "budget") return is_number(a[1]) && std::stof(a[1]) > 0.0f ? "" : "`solvers budget MS` takes milliseconds > 0";
  if (what == "patches") return is_int(a[1]) && std::stoi(a[1]) >= 10 ? "" : "`solvers patches N` takes N >= 10";
  return fmt::format("unknown solvers setting \"{}\" (open, close, run, pause, reset, budget, patches)", what);
}

// The arguments a verb takes: "" when they are right, else what is wrong.
std::string check(const ScriptCommand& c) {
  const auto& a = c.args;
  auto count = [&](size_t low, size_t high) -> std::string {
    if (a.size() < low || a.size() > high)
      return low == high ? fmt::format("`{}` takes {} argument{}", c.verb, low, low == 1 ? "" : "s")
                         : fmt::format("`{}` takes {} to {} arguments", c.verb, low, high);
    return "";
  };
  if (c.verb == "key") {
    if (auto e = count(1, 1); !e.empty()) return e;
    int key = 0, mods = 0;
    return parse_key(a[0], key, mods) ? "" : fmt::format("unknown key \"{}\"", a[0]);
  }
  if (c.verb == "click") {
    if (auto e = count(2, 2); !e.empty()) return e;
    return is_int(a[0]) && is_int(a[1]) ? "" : "`click X Y` takes whole window coordinates";
  }
  if (c.verb == "drag") {
    if (auto e = count(4, 5); !e.empty()) return e;
    for (size_t i = 0; i < 4; ++i)
      if (!is_int(a[i])) return "`drag X0 Y0 X1 Y1 [left|right]` takes whole window coordinates";
    if (a.size() == 5 && a[4] != "left" && a[4] != "right") return "the drag button is left or right";
    return "";
  }
  if (c.verb == "scroll") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return is_number(a[0]) ? "" : "`scroll STEPS` takes a number";
  }
  if (c.verb == "wait") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return is_int(a[0]) && std::stoi(a[0]) >= 0 ? "" : "`wait N` takes a number of frames";
  }
  if (c.verb == "screenshot") {
    if (auto e = count(1, 2); !e.empty()) return e;
    if (a.size() == 2 && a[1] != "--with-panel") return fmt::format("unknown option \"{}\"", a[1]);
    return a[0].ends_with(".png") ? "" : "screenshots are .png files";
  }
  if (c.verb == "camera") return count(1, 1);
  if (c.verb == "model") {
    if (auto e = count(1, 1); !e.empty()) return e;
    for (const char* model : {"flat", "gouraud", "phong", "whitted", "radiosity", "hybrid"})
      if (a[0] == model) return "";
    return fmt::format("unknown model \"{}\" (flat, gouraud, phong, whitted, radiosity, hybrid)", a[0]);
  }
  if (c.verb == "set") {
    if (auto e = count(2, 2); !e.empty()) return e;
    if (a[0] == "exposure") return is_number(a[1]) ? "" : "`set exposure EV` takes a number";
    for (const char* name : {"depth", "spp", "light-samples"})  // Whitted's numbers
      if (a[0] == name)
        return is_int(a[1]) && std::stoi(a[1]) >= (a[0] == "depth" ? 0 : 1)
                   ? "" : fmt::format("`set {}` takes a whole number{}", name, a[0] == "depth" ? " >= 0" : " >= 1");
    if (a[0] == "fog")
      return a[1] == "off" || a[1] == "linear" || a[1] == "exponential"
                 ? "" : "`set fog` takes off, linear or exponential";
    for (const char* name : {"ambient", "diffuse", "specular", "emission", "textures", "blinn", "panel", "inspector",
                             "shadows", "transparency", "reflection-map", "fresnel", "adaptive", "brute-force",
                             "shadow-rays"})
      if (a[0] == name) return a[1] == "on" || a[1] == "off" ? "" : fmt::format("`set {}` takes on or off", name);
    return fmt::format("cannot set \"{}\" (ambient, diffuse, specular, emission, textures, blinn, "
                       "panel, inspector, shadows, transparency, reflection-map, fog, exposure, depth, spp, "
                       "light-samples, fresnel, adaptive, brute-force, shadow-rays)", a[0]);
  }
  if (c.verb == "resize") {
    if (auto e = count(2, 2); !e.empty()) return e;
    return is_int(a[0]) && is_int(a[1]) && std::stoi(a[0]) > 0 && std::stoi(a[1]) > 0
               ? "" : "`resize W H` takes a positive window size";
  }
  if (c.verb == "load") return count(1, 1);
  if (c.verb == "dump-inspector") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return a[0].ends_with(".json") ? "" : "the inspector dumps to a .json file";
  }
  if (c.verb == "trace") {
    if (auto e = count(0, 1); !e.empty()) return e;
    return a.empty() || a[0] == "--no-wait" ? "" : fmt::format("unknown option \"{}\" (--no-wait)", a[0]);
  }
  if (c.verb == "dump-ray-tree" || c.verb == "dump-trace") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return a[0].ends_with(".json") ? "" : fmt::format("`{}` writes a .json file", c.verb);
  }
  if (c.verb == "radiosity") return check_radiosity(c);
  if (c.verb == "wait-shots") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return is_int(a[0]) && std::stoi(a[0]) >= 1 ? "" : "`wait-shots N` takes a number of shots >= 1";
  }
  if (c.verb == "dump-patch" || c.verb == "dump-radiosity") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return a[0].ends_with(".json") ? "" : fmt::format("`{}` writes a .json file", c.verb);
  }
  if (c.verb == "solvers") return check_solvers(c);
  if (c.verb == "wait-solver-rows") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return is_int(a[0]) && std::stoi(a[0]) >= 1 ? "" : "`wait-solver-rows N` takes a number of rows >= 1";
  }
  if (c.verb == "dump-solvers") {
    if (auto e = count(1, 1); !e.empty()) return e;
    return a[0].ends_with(".json") ? "" : "`dump-solvers` writes a .json file";
  }
  if (c.verb == "reload" || c.verb == "quit" || c.verb == "wait-trace") return count(0, 0);
  return fmt::format("unknown command \"{}\"", c.verb);
}

// Commands whose effect the next command must see drawn: they end the frame.
bool ends_frame(const std::string& verb) {
  return verb == "click" || verb == "drag" || verb == "screenshot" || verb == "resize" ||
         verb == "load" || verb == "reload" || verb == "camera" || verb == "dump-inspector" ||
         verb == "trace" || verb == "wait-trace" || verb == "radiosity" || verb == "wait-shots" ||
         verb == "dump-patch" || verb == "dump-radiosity" || verb == "solvers" || verb == "wait-solver-rows" ||
         verb == "dump-solvers";
}

}  // namespace

Script parse_script_text(const std::string& text, const std::filesystem::path& name) {
  Script script;
  script.file = name;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    ScriptCommand command;
    command.line = number;
    if (!(words >> command.verb) || command.verb.starts_with('#')) continue;
    for (std::string word; words >> word && !word.starts_with('#');)  // # starts a comment
      command.args.push_back(word);
    if (const std::string problem = check(command); !problem.empty())
      throw Error(ErrorKind::usage, fmt::format("{}:{}: {}", name.string(), number, problem));
    script.commands.push_back(std::move(command));
  }
  return script;
}

Script parse_script(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error(ErrorKind::usage, fmt::format("{}: cannot read the script", file.string()));
  std::stringstream text;
  text << in.rdbuf();
  return parse_script_text(text.str(), file);
}

bool ScriptRunner::step(ScriptTarget& target, std::string& error) {
  if (waiting_ > 0) {
    --waiting_;
    return true;
  }
  if (target.busy()) return true;
  while (next_ < script_.commands.size()) {
    const ScriptCommand& command = script_.commands[next_++];
    if (command.verb == "wait") {
      waiting_ = std::stoi(command.args[0]);
      if (waiting_ > 0) --waiting_;  // this frame is the first of them
      return true;
    }
    std::string problem;
    if (!target.run(command, problem)) {
      error = fmt::format("{}:{}: {}", script_.file.string(), command.line, problem);
      return false;
    }
    if (ends_frame(command.verb)) return true;
  }
  return true;
}

}  // namespace luz::app
