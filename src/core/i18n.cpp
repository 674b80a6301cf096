#include "core/i18n.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>

#include <fmt/format.h>

#include "core/error.h"
#include "core/resources.h"

namespace luz::i18n {
namespace fs = std::filesystem;

std::optional<Language> parse_language(std::string_view name) {
  if (name == "es") return Language::es;
  if (name == "en") return Language::en;
  return std::nullopt;
}

const char* language_name(Language language) { return language == Language::es ? "es" : "en"; }

Language language_from_locale_name(std::string_view name) {
  // "es", "es_ES.UTF-8", "es_MX@euro": the language is what comes before _ . @
  const std::string_view code = name.substr(0, name.find_first_of("_.@"));
  return code == "es" ? Language::es : Language::en;
}

Language language_from_environment() {
  for (const char* variable : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(variable);
    if (value && *value) return language_from_locale_name(value);
  }
  return Language::en;
}

// ---- the .mo reader -----------------------------------------------------------------------

Catalogue Catalogue::parse(std::string_view bytes, const std::string& name) {
  auto fail = [&](const std::string& what) {
    return Error(ErrorKind::bad_value, fmt::format("{}: not a GNU .mo catalogue: {}", name, what));
  };
  if (bytes.size() < 20) throw fail("shorter than its header");
  // The magic number tells the byte order the file was written in.
  auto word_le = [&](size_t at) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
  };
  auto swap = [](std::uint32_t w) {
    return (w >> 24) | ((w >> 8) & 0xff00u) | ((w << 8) & 0xff0000u) | (w << 24);
  };
  constexpr std::uint32_t kMagic = 0x950412de;
  const std::uint32_t magic = word_le(0);
  if (magic != kMagic && swap(magic) != kMagic) throw fail("wrong magic number");
  const bool swapped = magic != kMagic;
  auto word = [&](size_t at) -> std::uint32_t {
    if (at + 4 > bytes.size()) throw fail(fmt::format("offset {} past the end", at));
    return swapped ? swap(word_le(at)) : word_le(at);
  };
  if (const std::uint32_t revision = word(4); revision >> 16 > 1)
    throw fail(fmt::format("unknown revision {}", revision));
  const std::uint32_t count = word(8), originals = word(12), translations = word(16);
  // A (length, offset) pair; the string must lie inside the file (gettext also writes a NUL
  // after it, which we do not need).
  auto string_at = [&](std::uint32_t table, std::uint32_t index) {
    const size_t entry = size_t(table) + 8 * size_t(index);
    const std::uint32_t length = word(entry), offset = word(entry + 4);
    if (size_t(offset) + length > bytes.size()) throw fail(fmt::format("string {} past the end", index));
    return std::string(bytes.substr(offset, length));
  };
  Catalogue catalogue;
  for (std::uint32_t i = 0; i < count; ++i) {
    std::string id = string_at(originals, i);
    if (id.empty()) continue;  // the header entry (Content-Type, Language, ...)
    // A plural entry is "singular\0plural" -> "form0\0form1...": keep the singular pair, which
    // is how tr() is called.
    std::string text = string_at(translations, i);
    if (const size_t nul = id.find('\0'); nul != std::string::npos) {
      id.resize(nul);
      std::vector<std::string> forms;
      for (size_t from = 0;;) {
        const size_t end = text.find('\0', from);
        forms.push_back(text.substr(from, end == std::string::npos ? std::string::npos : end - from));
        if (end == std::string::npos) break;
        from = end + 1;
      }
      if (std::none_of(forms.begin(), forms.end(), [](const std::string& f) { return f.empty(); }))
        catalogue.plurals_.emplace(id, std::move(forms));
    }
    if (const size_t nul = text.find('\0'); nul != std::string::npos) text.resize(nul);
    if (!text.empty()) catalogue.entries_.emplace(std::move(id), std::move(text));
  }
  return catalogue;
}

Catalogue Catalogue::read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::file_missing, fmt::format("{}: cannot be read", file.string()));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return parse(bytes.str(), file.string());
}

const std::string* Catalogue::find(std::string_view id) const {
  const auto it = entries_.find(std::string(id));
  return it == entries_.end() ? nullptr : &it->second;
}

const std::string* Catalogue::find_plural(std::string_view singular, unsigned long n) const {
  const auto it = plurals_.find(std::string(singular));
  if (it == plurals_.end()) return nullptr;
  const size_t form = n != 1 ? 1 : 0;
  return form < it->second.size() ? &it->second[form] : nullptr;
}

// ---- the program's catalogues ------------------------------------------------------------

namespace {

std::atomic<Language> current{Language::en};

// English needs a catalogue too: the ids are the sources' wording, and en.po is where an
// English text is corrected without touching the code.
Catalogue load(Language language) {
  const fs::path file = locale_dir() / language_name(language) / "LC_MESSAGES" / "luz.mo";
  try {
    return Catalogue::read(file);
  } catch (const Error& error) {
    fmt::print(stderr, "luz: warning: {} (the messages stay in English)\n", error.what());
    return {};
  }
}

}  // namespace

const Catalogue& catalogue(Language language) {
  static std::once_flag once[2];
  static Catalogue catalogues[2];
  const int index = int(language);
  std::call_once(once[index], [&] { catalogues[index] = load(language); });
  return catalogues[index];
}

void set_language(Language language) { current.store(language); }
Language language() { return current.load(); }

const char* tr(const char* id) {
  const std::string* text = catalogue(language()).find(id);
  return text ? text->c_str() : id;
}

const char* trn(const char* singular, const char* plural, unsigned long n) {
  const std::string* text = catalogue(language()).find_plural(singular, n);
  return text ? text->c_str() : n == 1 ? singular : plural;
}

}  // namespace luz::i18n
