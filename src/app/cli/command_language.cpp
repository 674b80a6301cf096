#include "app/cli/command_language.h"

#include <regex>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/args.h>

#include "app/common/i18n.h"

namespace luz::app {
namespace {

// CLI11's help headings and type names, by its own keys (Formatter::get_label), which are also
// their message ids.
constexpr const char* kLabels[] = {N_("Usage"),       N_("OPTIONS"),  N_("SUBCOMMAND"), N_("SUBCOMMANDS"),
                                   N_("Positionals"), N_("REQUIRED"), N_("Needs"),      N_("Excludes"),
                                   N_("TEXT"),        N_("INT"),      N_("NUMBER"),     N_("FLOAT"),
                                   N_("UINT"),        N_("FILE"),     N_("SECONDS")};
// The group every option is in unless told otherwise: CLI11's "Options", translated where shown.
[[maybe_unused]] constexpr const char* kOptionsGroup = N_("Options");

class TranslatedFormatter : public CLI::Formatter {
public:
  TranslatedFormatter() {
    for (const char* key : kLabels) label(key, tr(key));
  }
  std::string make_group(std::string group, bool is_positional, std::vector<const CLI::Option*> opts) const override {
    return CLI::Formatter::make_group(tr(group.c_str()), is_positional, std::move(opts));
  }
  // A checked option's type name is CLI11's word joined to its check's ("TEXT:{es,en}"), which
  // get_label, looking the whole up, would leave in English: the word is translated alone.
  std::string make_option_opts(const CLI::Option* opt) const override {
    std::string out = CLI::Formatter::make_option_opts(opt);
    const std::string type = opt->get_type_name();
    const size_t colon = type.find(':');
    if (colon == std::string::npos) return out;
    const std::string word = type.substr(0, colon);
    if (const size_t at = out.find(" " + type); at != std::string::npos) out.replace(at + 1, word.size(), get_label(word));
    return out;
  }
};

// One of CLI11's message shapes: its pieces in parentheses, and the message id they fill in order.
struct Shape {
  std::regex english;
  const char* id;
};

const std::vector<Shape>& shapes() {
  static const std::vector<Shape> table = {
      {std::regex("The following argument was not expected: (.*)"), N_("The following argument was not expected: {}")},
      {std::regex("The following arguments were not expected: (.*)"), N_("The following arguments were not expected: {}")},
      {std::regex("A subcommand is required"), N_("A subcommand is required")},
      {std::regex("(.+) is required"), N_("{} is required")},
      {std::regex("(.+) excludes (.+)"), N_("{} excludes {}")},
      {std::regex("(.+) requires (.+)"), N_("{} requires {}")},
      {std::regex("(.+): ([0-9]+) required (.+) missing"), N_("{}: {} required {} missing")},
      {std::regex("Could not convert: (.+) = (.*)"), N_("Could not convert: {} = {}")},
      {std::regex("The value (.+) is not an allowed value for (.+)"), N_("The value {} is not an allowed value for {}")},
      {std::regex("(.+): Value (.+) not in range (.+) to (.+)"), N_("{}: Value {} not in range {} to {}")},
      {std::regex("(.+): (.+) not in \\{(.*)\\}"), N_("{}: {} not in {{{}}}")},
      {std::regex("(.+): Failed parsing (.+) as a (.+)"), N_("{}: Failed parsing {} as a {}")},
      {std::regex("(.+): Value (.+) could not be converted(.*)"), N_("{}: Value {} could not be converted{}")},
  };
  return table;
}

// The same failure text as CLI11's FailureMessage::simple, in the current language.
std::string failure_message(const CLI::App* app, const CLI::Error& error) {
  std::string text = translated_usage_error(error.what()) + "\n";
  if (const CLI::Option* help = app->get_help_ptr())
    text += trf("Run with {} for more information.", help->get_name()) + "\n";
  return text;
}

}  // namespace

void choose_language(int argc, const char* const* argv) {
  i18n::set_language(i18n::language_from_environment());
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    std::optional<i18n::Language> chosen;
    if (arg == "--lang" && i + 1 < argc) chosen = i18n::parse_language(argv[i + 1]);
    if (arg.starts_with("--lang=")) chosen = i18n::parse_language(arg.substr(7));
    if (chosen) i18n::set_language(*chosen);  // a bad one is CLI11's usage error later
  }
}

void speak_the_language(CLI::App& app) {
  app.formatter(std::make_shared<TranslatedFormatter>());
  app.set_help_flag("-h,--help", tr("Print this help message and exit"));
  app.group(tr("Subcommands"));
  app.failure_message(failure_message);
}

std::string translated_usage_error(const std::string& message) {
  for (const Shape& shape : shapes()) {
    std::smatch match;
    if (!std::regex_match(message, match, shape.english)) continue;
    fmt::dynamic_format_arg_store<fmt::format_context> pieces;
    for (size_t i = 1; i < match.size(); ++i) pieces.push_back(match[i].str());
    return fmt::vformat(tr(shape.id), pieces);
  }
  return message;
}

}  // namespace luz::app
