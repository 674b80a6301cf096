#include "support.h"

#include <array>
#include <cstdio>
#include <random>
#include <sys/wait.h>

namespace luz::test {

std::filesystem::path scene_dir() { return LUZ_SCENE_DIR; }
std::filesystem::path test_data_dir() { return LUZ_TEST_DATA_DIR; }
std::filesystem::path luz_binary() { return LUZ_BINARY; }

ScratchDir::ScratchDir() {
  std::random_device random;
  path = std::filesystem::temp_directory_path() / ("luz-test-" + std::to_string(random()));
  std::filesystem::create_directories(path);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path, ignored);
}

static std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

CommandResult run_luz(const std::vector<std::string>& args, const CommandOptions& options) {
  std::string command;
  if (!options.cwd.empty()) command += "cd " + shell_quote(options.cwd.string()) + " && ";
  if (options.no_display) command += "env -u DISPLAY -u WAYLAND_DISPLAY ";
  command += options.locale + " ";
  command += shell_quote(luz_binary().string());
  for (const std::string& arg : args) {
    command += ' ';  // appended apart: GCC 12 warns falsely (-Wrestrict) on " " + a temporary
    command += shell_quote(arg);
  }
  command += " 2>&1 </dev/null";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> chunk;
  while (size_t n = fread(chunk.data(), 1, chunk.size(), pipe)) result.output.append(chunk.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace luz::test
