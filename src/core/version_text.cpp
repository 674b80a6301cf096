#include "core/version.h"

#include <filesystem>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "core/i18n.h"
#include "core/resources.h"

namespace luz {

std::string version_text() {
  using i18n::tr;
  std::string text = fmt::format("luz {}", version());
  if (const std::string_view git = git_description(); !git.empty()) text += fmt::format(" (git {})", git);
  text += "\n";
  const std::pair<const char*, std::filesystem::path> folders[] = {
      {tr("shaders"), shader_dir()}, {tr("scenes"), scene_dir()},
      {tr("lessons"), lesson_dir()}, {tr("catalogues"), locale_dir()}};
  for (const auto& [label, folder] : folders) text += fmt::format("{}: {}\n", label, folder.string());
  text.pop_back();  // CLI11 ends the text with its own newline
  return text;
}

}  // namespace luz
