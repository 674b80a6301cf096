#pragma once
// The words the user reads, in Spanish or English: gettext catalogues (po/es.po, po/en.po,
// compiled by msgfmt at build time into LANG/LC_MESSAGES/luz.mo) read by a small .mo reader of
// our own. The catalogue is chosen by name, never through setlocale(): a fresh Debian has no
// es_ES locale generated, and a locale set process-wide would also change how strtod and
// iostreams read the numbers of scenes and flags (the C locale's decimal point stays).
//
//   tr("Ambient")            the current language's text for an English message id
//   set_language(Language::es) switches at run time; every later tr() follows
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace luz::i18n {

enum class Language { en, es };

// "es" / "en" (the `--lang` and script `lang` values); std::nullopt for anything else.
std::optional<Language> parse_language(std::string_view name);
const char* language_name(Language language);  // "es" / "en"

// The language a POSIX environment asks for: the first of LC_ALL, LC_MESSAGES, LANG that is set
// and not empty decides (POSIX's precedence); es, es_ES.UTF-8, es_AR... -> Spanish, all else English.
Language language_from_environment();
Language language_from_locale_name(std::string_view name);  // the rule above, on one value

// One catalogue: message id -> translation, from a GNU .mo file. The layout (GNU gettext manual,
// "The Format of GNU MO Files"): a magic number 0x950412de in the file's byte order, a revision,
// the count N, the offsets of the table of original strings and of the table of translations;
// each table holds N (length, offset) pairs of 32-bit words.
class Catalogue {
public:
  Catalogue() = default;
  // Throws luz::Error (bad_value) naming the file and what is wrong with it.
  static Catalogue read(const std::filesystem::path& file);
  static Catalogue parse(std::string_view bytes, const std::string& name);

  // The translation, or nullptr when the id is not there (or is there untranslated).
  const std::string* find(std::string_view id) const;
  // A plural entry's form for the count n (gettext's ngettext), by the rule both catalogues
  // declare, "nplurals=2; plural=(n != 1)"; nullptr when the singular id has no plural entry.
  const std::string* find_plural(std::string_view singular, unsigned long n) const;
  size_t size() const { return entries_.size(); }
  const std::unordered_map<std::string, std::string>& entries() const { return entries_; }
  // The plural entries: singular id -> its forms (the singular's is in entries() too).
  const std::unordered_map<std::string, std::vector<std::string>>& plurals() const { return plurals_; }

private:
  std::unordered_map<std::string, std::string> entries_;
  std::unordered_map<std::string, std::vector<std::string>> plurals_;
};

// The catalogue of a language as the program uses it (read once, kept for the whole run, so
// the strings tr() returns stay valid). A missing or broken catalogue gives an empty one and a
// message on stderr: the program then speaks English.
const Catalogue& catalogue(Language language);

void set_language(Language language);
Language language();

// The current language's text for `id` (an English message id in the sources), or `id` itself
// when the catalogue lacks it. xgettext extracts the ids from tr("...") (docs/classroom.md).
const char* tr(const char* id);

// fmt::format with a translated format string: trf("{} shots", n). The translation must keep
// the {} fields (the tests check every catalogue entry formats with its id's arguments).
template <typename... Args>
std::string trf(const char* id, Args&&... args) {
  return fmt::format(fmt::runtime(tr(id)), std::forward<Args>(args)...);
}

// ngettext: the current language's form of a message for the count n ("1 light", "2 lights";
// "1 luz", "2 luces"), or the English one when the catalogue lacks it. xgettext extracts both ids.
const char* trn(const char* singular, const char* plural, unsigned long n);

// trn's form, formatted: trnf("{} light", "{} lights", n, n).
template <typename... Args>
std::string trnf(const char* singular, const char* plural, unsigned long n, Args&&... args) {
  return fmt::format(fmt::runtime(trn(singular, plural, n)), std::forward<Args>(args)...);
}

// Marks a message id where it is written, in a constant table, for xgettext (gettext's
// gettext_noop): the code translates it where it is shown, with tr().
constexpr const char* N_(const char* id) { return id; }

}  // namespace luz::i18n
