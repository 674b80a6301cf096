#pragma once
// The command line in the user's language: `luz --help`, CLI11's own usage errors and the
// choice of language before any help text is written.
#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace luz::app {

// The language from LC_ALL / LC_MESSAGES / LANG, then from a `--lang es|en` (or --lang=es)
// anywhere among the arguments. Done before the options are declared, since CLI11 keeps each
// option's help text as it was given.
void choose_language(int argc, const char* const* argv);

// Before any option or subcommand is added (they inherit it): CLI11's headings (Usage,
// Options, Subcommands, REQUIRED...), the help flag's text and the failure message, in the
// current language.
void speak_the_language(CLI::App& app);

// CLI11 writes its usage errors in English, in a few fixed shapes ("--out is required", "The
// following argument was not expected: --bogus", "Value 3 not in range 64 to 1024"): the same
// message in the current language, the names and values it quotes kept. A message of no known
// shape (one of ours, already translated) comes back as it is.
std::string translated_usage_error(const std::string& message);

}  // namespace luz::app
