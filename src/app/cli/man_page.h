#pragma once
// luz(1): the manual page, written from the command line's own tree (every option's row as
// `--help` shows it, every subcommand's description and footer), so it cannot drift from the
// options it documents. The build runs `luz --lang en --man-page FILE` (and es) to make it.
#include <filesystem>
#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace luz::app {

// The page in roff (man(7)), in the current language.
std::string man_page(const CLI::App& app);

// Writes man_page(app) to `file`: 0, or 1 with a message naming the file.
int write_man_page(const CLI::App& app, const std::filesystem::path& file);

}  // namespace luz::app
