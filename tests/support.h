#pragma once
// What the tests share: where things are, and running the `luz` command as a user would.
#include <filesystem>
#include <string>
#include <vector>

namespace luz::test {

std::filesystem::path scene_dir();      // the shipped scenes
std::filesystem::path test_data_dir();  // tests/data (goldens, fixtures)
std::filesystem::path luz_binary();

// A fresh empty folder for one test, removed when the object goes.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir();
  ~ScratchDir();
  std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

struct CommandOptions {
  std::filesystem::path cwd;  // empty: the test's own
  bool no_display = false;    // unset DISPLAY and WAYLAND_DISPLAY, as on a headless machine
  // The locale variables luz runs with: English by default, whatever the developer's language,
  // since tests match the messages' words; "LC_ALL= LANG=es_ES.UTF-8" asks for Spanish.
  std::string locale = "LC_ALL=C";
};

// Runs `luz ARGS...` (each argument shell-quoted) and collects its exit code and output.
CommandResult run_luz(const std::vector<std::string>& args, const CommandOptions& options = {});

}  // namespace luz::test
