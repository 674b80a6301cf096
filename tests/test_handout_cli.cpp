// `luz lesson --handout / --png-dir` as a teacher runs it: one PDF page per kStepsPerPage steps
// with the steps' titles in the chosen language, one PNG per step at --size, nothing left at the
// outputs' paths when a step fails, and the exit codes. Also the headless sheets a handout is
// made of: `luz render --model A,B,...` --size is the whole sheet's, its radiosity and hybrid
// panes share one solve, and `luz compare --heatmap` states a fixed scale.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "core/image_compare.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::run_luz;

constexpr int kStepsPerPage = 2;  // handout_pdf.h: what a reader of the handout counts on

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
std::string cornell() { return (test::scene_dir() / "cornell_box.gltf").string(); }
fs::path shipped_lesson() { return test::scene_dir().parent_path() / "lessons" / "sintesis.json"; }

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool have(const char* tool) { return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0; }

// Pages of a PDF: pdfinfo's count where poppler-utils is installed, else the page objects of the
// file itself ("/Type /Page" not followed by "s"), which Cairo writes uncompressed.
int pdf_pages(const fs::path& pdf) {
  if (have("pdfinfo")) {
    const std::string out = (pdf.parent_path() / "info.txt").string();
    if (std::system(("pdfinfo '" + pdf.string() + "' > '" + out + "'").c_str()) != 0) return -1;
    std::smatch match;
    const std::string info = read_all(out);
    static const std::regex pages(R"(Pages:\s+(\d+))");
    return std::regex_search(info, match, pages) ? std::stoi(match[1]) : -1;
  }
  const std::string bytes = read_all(pdf);
  static const std::regex page(R"(/Type\s*/Page[^s])");
  return int(std::distance(std::sregex_iterator(bytes.begin(), bytes.end(), page), std::sregex_iterator()));
}

// The text of a PDF with its white space collapsed (pdftotext), so wrapped lines still match.
std::string collapse(const std::string& text) { return std::regex_replace(text, std::regex(R"(\s+)"), " "); }
std::string pdf_text(const fs::path& pdf) {
  const std::string out = (pdf.parent_path() / "text.txt").string();
  EXPECT_EQ(std::system(("pdftotext -enc UTF-8 '" + pdf.string() + "' '" + out + "'").c_str()), 0);
  return collapse(read_all(out));
}

// A lesson of three quick steps on the Cornell box (the local models); `step3` is the last one's
// JSON, so a test can make it fail.
fs::path write_lesson(const fs::path& dir, const std::string& step3 = R"("model": "flat")") {
  const std::string scene = nlohmann::json(cornell()).dump();
  const fs::path file = dir / "lesson.json";
  std::ofstream(file) << R"({"title": {"es": "Prueba", "en": "Test"}, "steps": [
    {"slide": 2, "title": {"es": "Primer paso", "en": "First step"}, "text": {"es": "uno", "en": "one"},
     "scene": )" << scene << R"(, "model": "phong"},
    {"slide": 3, "title": {"es": "Segundo paso", "en": "Second step"}, "text": {"es": "dos", "en": "two"},
     "model": "gouraud", "panes": ["flat", "phong"]},
    {"slide": 4, "title": {"es": "Tercer paso", "en": "Third step"}, "text": {"es": "tres", "en": "three"}, )"
                    << step3 << "}]}";
  return file;
}

TEST(HandoutCli, HelpNamesItsFlags) {
  const auto help = run_luz({"lesson", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"--handout", "--png-dir", "--lang", "--size", "--steps", "--time"})
    EXPECT_TRUE(contains(help.output, flag)) << flag << " in " << help.output;
}

TEST(HandoutCli, OnePagePerTwoStepsWithTheTitlesInTheChosenLanguage) {
  test::ScratchDir dir;
  const fs::path lesson = write_lesson(dir.path);
  for (const auto& [language, titles, others] :
       {std::tuple<std::string, std::vector<std::string>, std::vector<std::string>>{
            "es", {"Primer paso", "Segundo paso", "Tercer paso"}, {"First step", "Third step"}},
        {"en", {"First step", "Second step", "Third step"}, {"Primer paso", "Tercer paso"}}}) {
    const fs::path pdf = dir / ("handout-" + language + ".pdf");
    const auto run = run_luz({"lesson", lesson.string(), "--lang", language, "--handout", pdf.string(), "--size", "96x54"});
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_TRUE(contains(run.output, language == "es" ? "paso 3 de 3" : "step 3 of 3")) << run.output;  // progress
    EXPECT_EQ(pdf_pages(pdf), (3 + kStepsPerPage - 1) / kStepsPerPage);
    if (!have("pdftotext")) {
      std::cout << "pdftotext (poppler-utils) is not installed: the titles' text is not checked\n";
      continue;
    }
    const std::string text = pdf_text(pdf);
    for (const std::string& title : titles) EXPECT_TRUE(contains(text, title)) << title << " in " << text;
    for (const std::string& title : others) EXPECT_FALSE(contains(text, title)) << title << " in " << text;
    EXPECT_TRUE(contains(text, language == "es" ? "Transparencia 3 · paso 2 de 3" : "Slide 3 · step 2 of 3")) << text;
  }
}

TEST(HandoutCli, TheShippedLessonsFirstStepsInSpanish) {
  test::ScratchDir dir;
  const auto run = run_luz({"lesson", "--lang", "es", "--steps", "1-3", "--handout", (dir / "h.pdf").string(),
                            "--size", "64x36", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(pdf_pages(dir / "h.pdf"), 2);
  if (!have("pdftotext")) return;
  const nlohmann::json lesson = nlohmann::json::parse(read_all(shipped_lesson()));
  const std::string text = pdf_text(dir / "h.pdf");
  for (int i = 0; i < 3; ++i) {
    const std::string title = lesson["steps"][size_t(i)]["title"]["es"];
    EXPECT_TRUE(contains(text, collapse(title))) << title << " in " << text;
  }
}

// A radiosity step showing the heat map of the unshot power has the map's fixed scale under it.
TEST(HandoutCli, HeatMapStepStatesItsScale) {
  if (!have("pdftotext")) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  test::ScratchDir dir;
  const fs::path lesson = write_lesson(
      dir.path, R"("model": "radiosity", "radiosity": {"heat-map": true}, "actions": ["reset-solver", {"shots": 2}])");
  const auto run = run_luz({"lesson", lesson.string(), "--handout", (dir / "h.pdf").string(), "--size", "64x36"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string text = pdf_text(dir / "h.pdf");
  EXPECT_TRUE(contains(text, "mean emitted exitance (fixed scale)")) << text;
  EXPECT_TRUE(contains(text, "0.001")) << text;  // the ramp's first decade
  EXPECT_TRUE(contains(text, "black: nothing left to shoot")) << text;
}

TEST(HandoutCli, PngDirHoldsOnePicturePerStepAtTheSize) {
  test::ScratchDir dir;
  const fs::path lesson = write_lesson(dir.path);
  const auto run = run_luz({"lesson", lesson.string(), "--png-dir", (dir / "pictures").string(), "--size", "90x44",
                            "--steps", "2-3"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir / "pictures")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"step-02.png", "step-03.png"}));
  for (const std::string& name : names) {
    const Image picture = io::read_image(dir / "pictures" / name);
    EXPECT_EQ(picture.width, 90) << name;  // step 2's two panes share the size: 45 x 44 each
    EXPECT_EQ(picture.height, 44) << name;
  }
  EXPECT_FALSE(fs::exists(dir / "pictures.partial"));
}

// Nothing at the outputs' paths, nor a temporary beside them, unless every step was drawn.
void expect_nothing_written(const test::ScratchDir& dir) {
  for (const auto& entry : fs::directory_iterator(dir.path)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "lesson.json" || name == "bad.json") << name << " was left";
  }
}

TEST(HandoutCli, AFailingStepLeavesNoFile) {
  test::ScratchDir dir;
  // The third step asks for a camera the Cornell box does not have: found while drawing it,
  // after the first two steps are written.
  const fs::path lesson = write_lesson(dir.path, R"("model": "flat", "camera": "nowhere")");
  const auto run = run_luz({"lesson", lesson.string(), "--handout", (dir / "h.pdf").string(), "--png-dir",
                            (dir / "pictures").string(), "--size", "64x36"});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_TRUE(contains(run.output, "nowhere")) << run.output;
  expect_nothing_written(dir);
}

TEST(HandoutCli, BadLessonAndUnwritablePathsExitOneWithoutAFile) {
  test::ScratchDir dir;
  std::ofstream(dir / "bad.json") << "{\"title\": {\"es\": \"x\", \"en\": \"x\"}, \"steps\": [\n  {\"slide\": 2,}]}";
  const auto bad = run_luz({"lesson", (dir / "bad.json").string(), "--handout", (dir / "h.pdf").string()});
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_TRUE(contains(bad.output, "bad.json:2")) << bad.output;
  const fs::path lesson = write_lesson(dir.path);
  const auto missing = run_luz({"lesson", (dir / "none.json").string(), "--handout", (dir / "h.pdf").string()});
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  const auto pdf = run_luz({"lesson", lesson.string(), "--handout", (dir / "no" / "such" / "h.pdf").string()});
  EXPECT_EQ(pdf.exit_code, 1) << pdf.output;
  EXPECT_TRUE(contains(pdf.output, "h.pdf")) << pdf.output;
  const auto png = run_luz({"lesson", lesson.string(), "--png-dir", (dir / "lesson.json" / "pictures").string()});
  EXPECT_EQ(png.exit_code, 1) << png.output;
  EXPECT_TRUE(contains(png.output, "pictures")) << png.output;
  // The PDF's temporary, opened before the folder failed, goes too.
  const auto both = run_luz({"lesson", lesson.string(), "--handout", (dir / "h.pdf").string(), "--png-dir",
                             (dir / "lesson.json" / "pictures").string()});
  EXPECT_EQ(both.exit_code, 1) << both.output;
  expect_nothing_written(dir);
}

TEST(HandoutCli, BadFlagsAreUsageErrors) {
  test::ScratchDir dir;
  const fs::path lesson = write_lesson(dir.path);
  const std::string pdf = (dir / "h.pdf").string();
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"lesson", lesson.string()},                                  // no output
           {"lesson", lesson.string(), "--handout", (dir / "h.txt").string()},
           {"lesson", lesson.string(), "--handout", pdf, "--steps", "3-2"},
           {"lesson", lesson.string(), "--handout", pdf, "--steps", "1-4"},  // past the last step
           {"lesson", lesson.string(), "--handout", pdf, "--size", "0x10"},
           {"lesson", lesson.string(), "--handout", pdf, "--lang", "fr"},
           {"lesson", lesson.string(), "--handout", pdf, "--time", "-1"}}) {
    const auto run = run_luz(args);
    EXPECT_EQ(run.exit_code, 2) << args.back() << ": " << run.output;
  }
  expect_nothing_written(dir);
}

TEST(RenderGridCli, SizeIsTheWholeSheets) {
  test::ScratchDir dir;
  const auto run = run_luz({"render", cornell(), "--model", "flat,gouraud,phong,whitted", "--size", "161x81", "--out",
                            (dir / "g.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const Image sheet = io::read_image(dir / "g.png");
  EXPECT_EQ(sheet.width, 161);
  EXPECT_EQ(sheet.height, 81);
  EXPECT_TRUE(contains(run.output, "2x2 panes (80x40 each)")) << run.output;
  // The pixel a division leaves over stays black, as between the window's panes.
  EXPECT_EQ(sheet.at(160, 20).r + sheet.at(160, 20).g + sheet.at(160, 20).b, 0.0f);
}

TEST(RenderGridCli, RadiosityAndHybridShareOneSolve) {
  test::ScratchDir dir;
  const auto run = run_luz({"render", cornell(), "--model", "radiosity,hybrid", "--shots", "30", "--size", "80x40",
                            "--out", (dir / "g.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // run_radiosity_solver's summary line, once per solve.
  const std::regex solve("radiosity: \\d+ patches");
  EXPECT_EQ(std::distance(std::sregex_iterator(run.output.begin(), run.output.end(), solve), std::sregex_iterator()), 1)
      << run.output;
  const Image sheet = io::read_image(dir / "g.png");
  EXPECT_EQ(sheet.width, 80);
}

// Two comparisons whose differences spread differently colour the same difference alike: the
// scale is fixed (50% unless --range says otherwise), and said.
TEST(CompareCli, HeatMapScaleIsFixedAndStated) {
  test::ScratchDir dir;
  Image reference(40, 40, Rgb(0.5f)), wide(40, 40, Rgb(0.5f * 1.4f)), narrow(40, 40, Rgb(0.5f * 1.01f));
  wide.at(5, 5) = narrow.at(5, 5) = Rgb(0.5f * 1.25f);
  io::write_image(reference, dir / "b.exr", 0.0f);
  io::write_image(wide, dir / "wide.exr", 0.0f);
  io::write_image(narrow, dir / "narrow.exr", 0.0f);
  const auto heat = [&](const std::string& a, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"compare", (dir / a).string(), (dir / "b.exr").string(), "--heatmap",
                                     (dir / (a + ".png")).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto run = run_luz(args);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return std::pair(run.output, io::read_image(dir / (a + ".png")));
  };
  const auto [wide_text, wide_map] = heat("wide.exr");
  const auto [narrow_text, narrow_map] = heat("narrow.exr");
  EXPECT_TRUE(contains(wide_text, "(blue -50% .. red +50%)")) << wide_text;
  EXPECT_TRUE(contains(narrow_text, "(blue -50% .. red +50%)")) << narrow_text;
  // +25% on a +-50% scale: half way to saturated red, in both.
  const Rgb expected = diverging_colour(0.5f);
  for (const Image* map : {&wide_map, &narrow_map}) {
    EXPECT_NEAR(map->at(5, 5).r, expected.r, 0.01f);
    EXPECT_NEAR(map->at(5, 5).g, expected.g, 0.01f);
    EXPECT_NEAR(map->at(5, 5).b, expected.b, 0.01f);
  }
  const auto [fitted_text, fitted_map] = heat("narrow.exr", {"--range", "auto"});
  EXPECT_TRUE(contains(fitted_text, "(blue -1% .. red +1%)")) << fitted_text;
  EXPECT_EQ(run_luz({"compare", (dir / "wide.exr").string(), (dir / "b.exr").string(), "--range", "0"}).exit_code, 2);
}

}  // namespace
}  // namespace luz
