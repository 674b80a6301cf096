// The languages: the .mo reader against what GNU msgfmt writes, the choice of language from the
// environment, the shipped catalogues, the fonts' Latin-1, and numbers read the same whatever
// the locale.
#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>

#include <imgui.h>

#include "app/cli/command_language.h"
#include "app/common/i18n.h"
#include "app/common/label_text.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/ui_glyphs.h"
#include "core/error.h"
#include "support.h"

namespace luz {
namespace {

using i18n::Catalogue;
using i18n::Language;

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A catalogue with the cases the reader must handle: UTF-8, an escaped quote and newline, a
// fuzzy entry (msgfmt leaves it out), an untranslated one, and a plural.
const char* kPo = R"(msgid ""
msgstr ""
"Content-Type: text/plain; charset=UTF-8\n"
"Plural-Forms: nplurals=2; plural=(n != 1);\n"

msgid "diffuse reflection"
msgstr "reflexión difusa"

msgid "say \"hi\"\nthen go"
msgstr "di \"hola\"\ny vete"

#, fuzzy
msgid "patch"
msgstr "parche"

msgid "hemicube"
msgstr ""

msgid "one shot"
msgid_plural "{} shots"
msgstr[0] "un disparo"
msgstr[1] "{} disparos"
)";

Catalogue compile(const test::ScratchDir& dir, const std::string& endianness) {
  write(dir / "test.po", kPo);
  const std::filesystem::path mo = dir / ("test-" + endianness + ".mo");
  EXPECT_EQ(shell(std::string(LUZ_MSGFMT) + " --endianness=" + endianness + " -o " + mo.string() + " " +
                  (dir / "test.po").string()), 0);
  return Catalogue::read(mo);
}

TEST(MoReader, ReadsWhatMsgfmtWritesInEitherByteOrder) {
  const test::ScratchDir dir;
  for (const char* endianness : {"little", "big"}) {
    SCOPED_TRACE(endianness);
    const Catalogue c = compile(dir, endianness);
    ASSERT_NE(c.find("diffuse reflection"), nullptr);
    EXPECT_EQ(*c.find("diffuse reflection"), "reflexión difusa");
    ASSERT_NE(c.find("say \"hi\"\nthen go"), nullptr);
    EXPECT_EQ(*c.find("say \"hi\"\nthen go"), "di \"hola\"\ny vete");
    EXPECT_EQ(c.find("patch"), nullptr);     // fuzzy: not a translation yet
    EXPECT_EQ(c.find("hemicube"), nullptr);  // untranslated
    ASSERT_NE(c.find("one shot"), nullptr);  // a plural keeps its singular pair
    EXPECT_EQ(*c.find("one shot"), "un disparo");
    EXPECT_EQ(c.size(), 3u);
    // and its forms, chosen by "plural=(n != 1)"
    ASSERT_NE(c.find_plural("one shot", 1), nullptr);
    EXPECT_EQ(*c.find_plural("one shot", 1), "un disparo");
    EXPECT_EQ(*c.find_plural("one shot", 2), "{} disparos");
    EXPECT_EQ(*c.find_plural("one shot", 0), "{} disparos");
    EXPECT_EQ(c.find_plural("diffuse reflection", 2), nullptr);  // not a plural entry
  }
}

TEST(MoReader, RefusesWhatIsNotACatalogueNamingTheFile) {
  const test::ScratchDir dir;
  compile(dir, "little");
  std::ifstream in(dir / "test-little.mo", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const std::string& broken : {bytes.substr(0, 12), bytes.substr(0, bytes.size() / 2), std::string(40, 'x')}) {
    try {
      Catalogue::parse(broken, "broken.mo");
      ADD_FAILURE() << "accepted " << broken.size() << " bytes";
    } catch (const Error& error) {
      EXPECT_EQ(error.kind, ErrorKind::bad_value);
      EXPECT_NE(std::string(error.what()).find("broken.mo: not a GNU .mo catalogue"), std::string::npos) << error.what();
    }
  }
}

TEST(Language, FromLocaleNames) {
  for (const char* spanish : {"es", "es_ES", "es_ES.UTF-8", "es_AR.utf8", "es_MX@euro"})
    EXPECT_EQ(i18n::language_from_locale_name(spanish), Language::es) << spanish;
  for (const char* other : {"C", "POSIX", "C.UTF-8", "en_US.UTF-8", "de_DE.UTF-8", "est_EE", ""})
    EXPECT_EQ(i18n::language_from_locale_name(other), Language::en) << other;
}

// POSIX: LC_ALL overrides LC_MESSAGES, which overrides LANG; an empty one does not count.
TEST(Language, FromTheEnvironmentInPosixOrder) {
  struct Case {
    const char *all, *messages, *lang;
    Language expected;
  };
  const Case cases[] = {{nullptr, nullptr, "es_ES.UTF-8", Language::es},
                        {nullptr, "en_GB.UTF-8", "es_ES.UTF-8", Language::en},
                        {"es_CL.UTF-8", "en_GB.UTF-8", "en_US", Language::es},
                        {"", "es_ES", "en_US", Language::es},
                        {nullptr, nullptr, nullptr, Language::en}};
  for (const Case& c : cases) {
    const std::pair<const char*, const char*> variables[] = {{"LC_ALL", c.all}, {"LC_MESSAGES", c.messages}, {"LANG", c.lang}};
    for (const auto& [name, value] : variables) value ? setenv(name, value, 1) : unsetenv(name);
    EXPECT_EQ(i18n::language_from_environment(), c.expected)
        << (c.all ? c.all : "-") << " " << (c.messages ? c.messages : "-") << " " << (c.lang ? c.lang : "-");
  }
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) unsetenv(name);
}

// The build's catalogues: Spanish in the lecture's words, English the ids, switched at run time,
// with no setlocale() anywhere.
TEST(Catalogues, SwitchAtRunTimeAndUseTheLecturesTerms) {
  i18n::set_language(Language::es);
  EXPECT_STREQ(app::tr("radiosity"), "radiosidad");
  EXPECT_STREQ(app::tr("hybrid"), "híbrido");
  EXPECT_EQ(app::trf("step {}", 3), "paso 3");
  i18n::set_language(Language::en);
  EXPECT_STREQ(app::tr("radiosity"), "radiosity");
  EXPECT_EQ(app::trf("step {}", 3), "step 3");
  const char* unknown = "a message no catalogue has";
  EXPECT_EQ(app::tr(unknown), unknown);
}

// Counts take the language's plural form: "1 luz", "2 luces" (gettext's ngettext), never "1 luces".
TEST(Catalogues, CountsTakeThePluralForm) {
  i18n::set_language(Language::es);
  EXPECT_EQ(app::trnf("{} light", "{} lights", 1, 1), "1 luz");
  EXPECT_EQ(app::trnf("{} light", "{} lights", 2, 2), "2 luces");
  EXPECT_EQ(app::trnf("{} light", "{} lights", 0, 0), "0 luces");
  EXPECT_EQ(app::trnf("ray tree of pixel ({}, {}): {} ray", "ray tree of pixel ({}, {}): {} rays", 1, 3, 4, 1),
            "árbol de rayos del píxel (3, 4): 1 rayo");
  i18n::set_language(Language::en);
  EXPECT_EQ(app::trnf("{} light", "{} lights", 1, 1), "1 light");
  EXPECT_EQ(app::trnf("{} light", "{} lights", 3, 3), "3 lights");
  EXPECT_EQ(app::trnf("a count no catalogue has", "{} counts no catalogue has", 2, 2), "2 counts no catalogue has");
}

// A Spanish run leaves no English in the help of any command: a line the two languages print
// alike holds only an option's names and its values' shapes (--fog off|linear|exponential), and the
// usage line names the scene in Spanish.
TEST(Catalogues, TheSpanishHelpLeavesNoEnglish) {
  const std::regex flag_only(R"(\s*(-\w, )?--[\w-]+( [A-Za-z0-9.|,{}\[\]=:+-]+)?\s*)");
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{}, {"render"}, {"compare"}, {"solvers"}, {"bench"}}) {
    std::vector<std::string> help[2];
    for (const char* language : {"es", "en"}) {
      std::vector<std::string> args = command;
      args.insert(args.end(), {"--help", "--lang", language});
      const test::CommandResult result = test::run_luz(args);
      EXPECT_EQ(result.exit_code, 0) << result.output;
      std::istringstream lines(result.output);
      for (std::string line; std::getline(lines, line);) help[language[0] == 'e' && language[1] == 'n'].push_back(line);
    }
    const std::string name = command.empty() ? "luz" : command[0];
    ASSERT_GT(help[0].size(), 3u) << name;
    for (const std::string& line : help[0]) {
      if (line.find_first_not_of(' ') == std::string::npos) continue;
      if (std::find(help[1].begin(), help[1].end(), line) == help[1].end()) continue;
      EXPECT_TRUE(std::regex_match(line, flag_only)) << name << ": English left in Spanish: \"" << line << "\"";
    }
    // The placeholders and CLI11's words, in any line (a checked option's "TEXT:{es,en}" too).
    const std::regex placeholder(R"(\b(SCENE|TEXT|FILE|SECONDS|REQUIRED|Excludes|Needs)\b)");
    for (const std::string& line : help[0])
      EXPECT_FALSE(std::regex_search(line, placeholder)) << name << ": English left in Spanish: \"" << line << "\"";
  }
}

// CLI11 writes its usage errors in English: each of its shapes comes back in the current
// language with the names and values it quotes; a message of ours passes untouched.
TEST(Catalogues, CliElevenUsageErrorsAreTranslatedKeepingTheirPieces) {
  i18n::set_language(Language::es);
  EXPECT_EQ(app::translated_usage_error("The following argument was not expected: --bogus"),
            app::trf("The following argument was not expected: {}", "--bogus"));
  EXPECT_EQ(app::translated_usage_error("--out is required"), app::trf("{} is required", "--out"));
  EXPECT_EQ(app::translated_usage_error("--shots excludes --converge"), app::trf("{} excludes {}", "--shots", "--converge"));
  EXPECT_EQ(app::translated_usage_error("--lang: fr not in {es,en}"), app::trf("{}: {} not in {{{}}}", "--lang", "fr", "es,en"));
  EXPECT_EQ(app::translated_usage_error("--depth: Value 99 not in range 1 to 64"),
            app::trf("{}: Value {} not in range {} to {}", "--depth", "99", "1", "64"));
  EXPECT_NE(app::translated_usage_error("--out is required"), "--out is required");
  EXPECT_EQ(app::translated_usage_error("--size: ya traducido"), "--size: ya traducido");
  i18n::set_language(Language::en);
  EXPECT_EQ(app::translated_usage_error("--out is required"), "--out is required");
}

// F1 lists each shortcut's keys through tr(): every key name with a word in it ("Space",
// "Shift+P", "Up / Down") is a catalogue id, so that Spanish shows "Espacio", "Mayús+P".
TEST(Catalogues, TheKeyNamesOfF1AreTranslated) {
  const std::regex word("[A-Za-z]{2,}");
  size_t named = 0;
  for (const app::Shortcut& s : app::shortcuts()) {
    if (!std::regex_search(s.shown, word)) continue;
    ++named;
    EXPECT_NE(i18n::catalogue(Language::es).find(s.shown), nullptr) << s.shown;
  }
  EXPECT_GE(named, 8u);
  i18n::set_language(Language::es);
  EXPECT_STREQ(app::tr("Space"), "Espacio");
  EXPECT_STREQ(app::tr("Shift+P"), "Mayús+P");
  i18n::set_language(Language::en);
}

// A translation must take its id's arguments: as many {} fields (fmt) and the same % directives
// (printf) in the same order, or a message would throw or print garbage in one language only.
TEST(Catalogues, EveryTranslationTakesItsIdsArguments) {
  const std::regex directive(R"(\{\}|%%|%[-+#0]*[0-9]*(\.[0-9]+)?(z|l|ll|h)?[diouxXeEfgGcsp])");
  auto fields = [&](const std::string& text) {
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), directive); it != std::sregex_iterator(); ++it)
      out.push_back(it->str());
    return out;
  };
  for (Language language : {Language::es, Language::en}) {
    const Catalogue& c = i18n::catalogue(language);
    EXPECT_GT(c.size(), 100u) << i18n::language_name(language);
    for (const auto& [id, text] : c.entries()) EXPECT_EQ(fields(id), fields(text)) << id << " -> " << text;
    for (const auto& [id, forms] : c.plurals())
      for (const std::string& form : forms) EXPECT_EQ(fields(id), fields(form)) << id << " -> " << form;
  }
}

TEST(Fonts, TheViewersGlyphRangesHoldLatin1) {
  // Every range is a (first, last) pair and the list ends in 0.
  const size_t n = std::size(app::kUiGlyphRanges);
  ASSERT_EQ(n % 2, 1u);
  EXPECT_EQ(app::kUiGlyphRanges[n - 1], 0);
  for (char32_t c = 0x20; c <= 0xFF; ++c) {
    bool covered = false;
    for (size_t i = 0; i + 1 < n; i += 2)
      covered = covered || (c >= app::kUiGlyphRanges[i] && c <= app::kUiGlyphRanges[i + 1]);
    if (c < 0x7F || c >= 0xA0) {
      EXPECT_TRUE(covered) << "U+" << std::hex << unsigned(c);
    }
  }
}

const char* kSpanish = "áéíóúñ¿¡ÁÉÍÓÚÑü";

// Dear ImGui's atlas built as the viewer builds it (DejaVu Sans, kUiGlyphRanges), without a
// window: each Spanish letter has its own glyph, and the glyph has ink.
TEST(Fonts, ImGuiDrawsTheSpanishLetters) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  ASSERT_NE(io.Fonts->AddFontFromFileTTF(app::LabelFont::default_file().c_str(), 16.0f, nullptr,
                                         reinterpret_cast<const ImWchar*>(app::kUiGlyphRanges)), nullptr);
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsAlpha8(&pixels, &width, &height);
  const ImFont* font = io.Fonts->Fonts[0];
  for (char32_t c : app::decode_utf8(kSpanish)) {
    const ImFontGlyph* glyph = font->FindGlyphNoFallback(ImWchar(c));
    ASSERT_NE(glyph, nullptr) << "U+" << std::hex << unsigned(c);
    int ink = 0;
    for (int y = int(glyph->V0 * float(height)); y < int(glyph->V1 * float(height)); ++y)
      for (int x = int(glyph->U0 * float(width)); x < int(glyph->U1 * float(width)); ++x)
        ink += pixels[y * width + x] > 128;
    EXPECT_GT(ink, 4) << "U+" << std::hex << unsigned(c);
  }
  ImGui::DestroyContext();
}

// The labels of `luz render`'s panes (stb_truetype): every Latin-1 letter is in the font, and
// each of the Spanish ones draws ink of its own.
TEST(Fonts, LabelTextDrawsTheSpanishLetters) {
  const app::LabelFont font;
  for (char32_t c = 0xC0; c <= 0xFF; ++c) EXPECT_TRUE(font.has_glyph(c)) << "U+" << std::hex << unsigned(c);
  for (char32_t c : app::decode_utf8(kSpanish)) {
    std::string one;
    one += char(0xC0 | (c >> 6));
    one += char(0x80 | (c & 0x3F));
    Image image(40, 40);
    font.draw(image, 4, 4, one, 24.0f, Rgb(1.0f));
    int ink = 0;
    for (const Rgb& p : image.pixels) ink += p.r > 0.5f;
    EXPECT_GT(ink, 10) << one;
  }
  EXPECT_EQ(app::decode_utf8("a\xC3"), std::u32string(U"a\uFFFD"));  // a cut sequence
}

// A German locale writes 0,5: if anything in luz set the locale from the environment, strtod
// and iostreams would read --exposure 0.5 as 0 and the pictures would differ.
TEST(Locale, NumbersAreReadTheSameWhateverTheLocale) {
  const test::ScratchDir dir;
  const std::filesystem::path locales = dir / "locales";
  std::filesystem::create_directories(locales);
  ASSERT_EQ(shell("localedef -i de_DE -f UTF-8 " + (locales / "de_DE.UTF-8").string() + " >/dev/null 2>&1"), 0)
      << "localedef (libc-bin) and the locale sources of Debian's locales package make the test's German locale";
  // The locale is real: in this process it turns the decimal point into a comma.
  setenv("LOCPATH", locales.c_str(), 1);
  ASSERT_NE(std::setlocale(LC_NUMERIC, "de_DE.UTF-8"), nullptr);
  EXPECT_EQ(std::strtod("0.5", nullptr), 0.0);
  std::setlocale(LC_NUMERIC, "C");
  unsetenv("LOCPATH");

  const std::string args = " render " + (test::scene_dir() / "local_effects.gltf").string() +
                           " --size 96x72 --exposure 0.5 --fog linear --fog-near 1.5 --fog-far 9.5 -q --out ";
  ASSERT_EQ(shell("LC_ALL=C " + test::luz_binary().string() + args + (dir / "c.png").string()), 0);
  ASSERT_EQ(shell("LOCPATH=" + locales.string() + " LC_ALL=de_DE.UTF-8 LC_NUMERIC=de_DE.UTF-8 LANG=es_ES.UTF-8 " +
                  test::luz_binary().string() + args + (dir / "de.png").string()), 0);
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(bytes(dir / "c.png"), bytes(dir / "de.png"));
  ASSERT_EQ(shell("LC_ALL=C " + test::luz_binary().string() + args.substr(0, args.find("0.5")) + "0 --fog linear "
                  "--fog-near 1.5 --fog-far 9.5 -q --out " + (dir / "zero.png").string()), 0);
  EXPECT_NE(bytes(dir / "c.png"), bytes(dir / "zero.png"));  // the exposure did count
}

}  // namespace
}  // namespace luz
