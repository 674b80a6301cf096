#include "app/cli/man_page.h"

#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/common/i18n.h"
#include "core/version.h"

namespace luz::app {
namespace {

// Text as roff reads it: backslashes and minus signs escaped, a line that would start with a
// control character ('.' or ') made plain text, a blank line a paragraph space.
std::string roff(std::string_view text) {
  std::string out;
  bool line_start = true;
  for (const char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    line_start = c == '\n';
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  std::string spaced;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) spaced += line.empty() ? ".sp\n" : line + "\n";
  return spaced;
}

// roff() of a text that stays within one line of the page.
std::string roff_inline(std::string_view text) {
  std::string out = roff(text);
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// One option's row: its names in bold, then what --help writes after them (the value's type,
// the choices, the default, REQUIRED, Excludes) and its description.
std::string option_row(const CLI::Formatter& format, const CLI::Option& option) {
  const bool positional = !option.nonpositional();
  return ".TP\n\\fB" + roff_inline(format.make_option_name(&option, positional)) + "\\fR" +
         roff_inline(format.make_option_opts(&option)) + "\n" + roff(format.make_option_desc(&option));
}

std::string options_of(const CLI::Formatter& format, const CLI::App& app) {
  std::string out;
  // Positionals first, as --help lists them; an option with no group is hidden from --help.
  for (const bool positional : {true, false})
    for (const CLI::Option* option : app.get_options())
      if (!option->get_group().empty() && option->nonpositional() != positional) out += option_row(format, *option);
  return out;
}

// "Usage: luz render [OPTIONS] SCENE" without the label.
std::string usage_of(const CLI::Formatter& format, const CLI::App& app, const std::string& name) {
  std::string usage = format.make_usage(&app, name);
  usage.erase(0, usage.find(':') + 1);
  while (!usage.empty() && (usage.front() == ' ' || usage.back() == '\n')) {
    if (usage.front() == ' ') usage.erase(0, 1);
    else usage.pop_back();
  }
  return usage;
}

std::vector<const CLI::App*> subcommands_of(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App* sub) { return !sub->get_name().empty(); });
}

void synopsis(const CLI::Formatter& format, const CLI::App& app, const std::string& name, std::string& out) {
  out += ".br\n" + roff(usage_of(format, app, name));
  for (const CLI::App* sub : subcommands_of(app)) synopsis(format, *sub, name + " " + sub->get_name(), out);
}

// A subcommand's section, then its own subcommands' (luz bench whitted, ...).
void command(const CLI::Formatter& format, const CLI::App& app, const std::string& name, std::string& out) {
  out += ".SS \"" + roff_inline(name) + "\"\n";
  out += roff(app.get_description());
  out += ".PP\n" + roff(usage_of(format, app, name));
  out += options_of(format, app);
  if (const std::string footer = app.get_footer(); !footer.empty()) out += ".PP\n" + roff(footer);
  for (const CLI::App* sub : subcommands_of(app)) command(format, *sub, name + " " + sub->get_name(), out);
}

}  // namespace

std::string man_page(const CLI::App& app) {
  const auto format = std::dynamic_pointer_cast<CLI::Formatter>(app.get_formatter());
  if (!format) return {};
  // UTF-8 (the lecture's title, the Spanish page): the first line tells man's preconv.
  std::string out = ".\\\" -*- coding: UTF-8 -*-\n";
  out += fmt::format(".TH LUZ 1 \"\" \"luz {}\" \"{}\"\n", version(), tr("User commands"));
  out += fmt::format(".SH \"{}\"\n", tr("NAME"));
  out += "luz \\- " + roff(tr("interactive lab for realistic image synthesis"));
  out += fmt::format(".SH \"{}\"\n", tr("SYNOPSIS"));
  synopsis(*format, app, "luz", out);
  out += fmt::format(".SH \"{}\"\n", tr("DESCRIPTION"));
  out += roff(app.get_description());
  out += fmt::format(".SH \"{}\"\n", tr("OPTIONS"));
  out += options_of(*format, app);
  out += fmt::format(".SH \"{}\"\n", tr("COMMANDS"));
  for (const CLI::App* sub : subcommands_of(app)) command(*format, *sub, "luz " + sub->get_name(), out);
  out += fmt::format(".SH \"{}\"\n", tr("EXIT STATUS"));
  out += roff(app.get_footer());
  out += fmt::format(".SH \"{}\"\n", tr("ENVIRONMENT"));
  out += roff(tr("LC_ALL, LC_MESSAGES, LANG: the language of the messages and labels (es or en), unless --lang "
                 "says. DISPLAY, WAYLAND_DISPLAY: the display the viewer opens on. LUZ_GL: the headless OpenGL "
                 "of luz render, egl or osmesa."));
  out += fmt::format(".SH \"{}\"\n", tr("FILES"));
  out += roff(tr("PREFIX/share/luz: the shaders, the shipped scenes (the viewer opens its Cornell box when given "
                 "no scene), the lessons and the message catalogues, found from the executable's own folder "
                 "(PREFIX/bin/../share/luz). luz --version lists the folders it reads."));
  return out;
}

int write_man_page(const CLI::App& app, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  out << man_page(app);
  if (!out.flush()) {
    fmt::print(stderr, "luz: {}\n", trf("{}: cannot be written", file.string()));
    return 1;
  }
  return 0;
}

}  // namespace luz::app
