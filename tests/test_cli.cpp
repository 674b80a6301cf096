// The `luz` command as teachers' scripts call it: flags, exit codes (0 / 1 bad input /
// 2 usage), messages that name the file, and output files that appear whole or not at all.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/i18n.h"
#include "core/image.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::run_luz;

std::string cornell() { return (test::scene_dir() / "cornell_box.gltf").string(); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

double mean(const Image& image) {
  double sum = 0;
  for (const Rgb& p : image.pixels) sum += double(p.r + p.g + p.b);
  return sum / (3.0 * double(image.pixels.size()));
}

TEST(Cli, HelpListsTheRenderCommandAndItsFlags) {
  const auto top = run_luz({"--help"});
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_TRUE(contains(top.output, "render"));
  const auto render = run_luz({"render", "--help"});
  EXPECT_EQ(render.exit_code, 0);
  for (const char* flag : {"--model", "--out", "--size", "--camera", "--exposure", "--no-ambient",
                           "--no-diffuse", "--no-specular", "--blinn", "flat", "gouraud", "phong"})
    EXPECT_TRUE(contains(render.output, flag)) << flag;
}

TEST(Cli, UsageErrorsExitWithTwo) {
  test::ScratchDir dir;
  const std::string out = (dir / "x.png").string();
  EXPECT_EQ(run_luz({"render", cornell(), "--out", out, "--bogus"}).exit_code, 2);
  EXPECT_EQ(run_luz({"render", cornell(), "--out", out, "--model", "cartoon"}).exit_code, 2);
  EXPECT_EQ(run_luz({"render", cornell(), "--out", out, "--size", "12"}).exit_code, 2);
  EXPECT_EQ(run_luz({"render", cornell(), "--out", out, "--size", "0x10"}).exit_code, 2);
  EXPECT_EQ(run_luz({"render", cornell(), "--out", out, "--exposure", "bright"}).exit_code, 2);
  EXPECT_EQ(run_luz({"render", cornell()}).exit_code, 2);  // no --out
  const auto jpg = run_luz({"render", cornell(), "--out", (dir / "x.jpg").string()});
  EXPECT_EQ(jpg.exit_code, 2);
  EXPECT_TRUE(contains(jpg.output, "x.jpg"));
  // Slide 19's switches belong to the local models: with another model they are a usage error
  // that names the flag, never silently ignored.
  const auto fog = run_luz({"render", cornell(), "--out", out, "--model", "whitted", "--fog", "linear"});
  EXPECT_EQ(fog.exit_code, 2);
  EXPECT_TRUE(contains(fog.output, "--fog"));
  EXPECT_EQ(run_luz({"render", cornell(), "--out", out, "--model", "radiosity", "--shadows"}).exit_code, 2);
  const auto camera = run_luz({"render", cornell(), "--out", out, "--camera", "nowhere"});
  EXPECT_EQ(camera.exit_code, 2);
  EXPECT_TRUE(contains(camera.output, "nowhere"));
  EXPECT_TRUE(fs::is_empty(dir.path));
}

// Slide 19's switches: listed, checked, and a missing environment image is bad input naming it.
TEST(Cli, EffectFlagsAreListedAndChecked) {
  const auto help = run_luz({"render", "--help"});
  for (const char* flag : {"--fog", "linear|exponential", "--fog-colour", "--fog-near", "--fog-far", "--fog-density",
                           "--shadows", "--shadow-bias", "--shadow-slope-bias", "--shadow-normal-offset",
                           "--shadow-map-size", "--transparency", "--reflection-map", "--reflection-map-size",
                           "--environment"})
    EXPECT_TRUE(contains(help.output, flag)) << flag;

  test::ScratchDir dir;
  const std::string out = (dir / "x.png").string();
  const std::string plate = (test::scene_dir() / "local_effects.gltf").string();
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"--fog", "smoke"}, {"--fog-colour", "1,2"}, {"--fog-colour", "1,2,x"}, {"--fog-colour", "-1,0,0"},
           {"--fog-near", "-1"}, {"--fog-density", "thick"}, {"--shadow-bias", "-0.1"},
           {"--shadow-map-size", "8"}, {"--fog", "linear", "--fog-near", "5", "--fog-far", "4"}, {"--shadow-map-size", "100000"}, {"--reflection-map-size", "2"}}) {
    std::vector<std::string> args = {"render", plate, "--out", out};
    args.insert(args.end(), bad.begin(), bad.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << bad[0] << " " << bad[1] << ": " << result.output;
    EXPECT_TRUE(contains(result.output, bad[0])) << "the message names the flag: " << result.output;
  }
  EXPECT_TRUE(fs::is_empty(dir.path));

  const auto missing = run_luz({"render", plate, "--out", out, "--size", "40x30", "--reflection-map",
                                "--environment", (dir / "no-sky.exr").string()});
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_TRUE(contains(missing.output, "no-sky.exr")) << missing.output;
  EXPECT_FALSE(fs::exists(out));

  const auto good = run_luz({"render", plate, "--out", out, "--size", "40x30", "-q", "--fog", "Exponential",
                             "--fog-colour", "0.2,0.25,0.3", "--fog-density", "0.05", "--shadows",
                             "--shadow-bias", "0.001", "--shadow-map-size", "256", "--transparency",
                             "--reflection-map", "--reflection-map-size", "32"});
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_EQ(good.output, "");
  EXPECT_TRUE(fs::exists(out));
}

TEST(Cli, MissingSceneIsBadInputNamingTheFile) {
  test::ScratchDir dir;
  const auto result = run_luz({"render", (dir / "nope.gltf").string(), "--out", (dir / "x.png").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.output, "nope.gltf"));
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(Cli, BrokenSceneLeavesAnExistingOutputUntouched) {
  test::ScratchDir dir;
  std::ofstream(dir / "broken.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ {";
  std::ofstream(dir / "keep.png") << "previous picture";
  const auto result = run_luz({"render", (dir / "broken.gltf").string(), "--out", (dir / "keep.png").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.output, "broken.gltf"));
  std::ifstream kept(dir / "keep.png");
  std::string content((std::istreambuf_iterator<char>(kept)), {});
  EXPECT_EQ(content, "previous picture");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), {}), 2);  // no temporary left
}

TEST(Cli, UnwritableOutputIsBadInputAndLeavesNothing) {
  test::ScratchDir dir;
  const auto result = run_luz({"render", cornell(), "--out", (dir / "no" / "x.png").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.output, "x.png"));
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(Cli, RendersThePngAtTheRequestedSize) {
  test::ScratchDir dir;
  for (const char* model : {"flat", "gouraud", "phong"}) {
    const fs::path out = dir / (std::string(model) + ".png");
    const auto result = run_luz({"render", cornell(), "--model", model, "--size", "64x48", "--out", out.string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image image = io::read_image(out);
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
    EXPECT_GT(mean(image), 0.01) << model;
  }
}

TEST(Cli, PngIsTheExrExposedAndSrgbEncoded) {
  test::ScratchDir dir;
  const auto exr = dir / "a.exr", png = dir / "a.png";
  ASSERT_EQ(run_luz({"render", cornell(), "--size", "40x40", "--out", exr.string()}).exit_code, 0);
  ASSERT_EQ(run_luz({"render", cornell(), "--size", "40x40", "--exposure", "1.5", "--out", png.string()}).exit_code, 0);
  const Image linear = io::read_image(exr);
  const Image encoded = io::read_image(png);  // read back through the sRGB decode
  const float scale = std::exp2(1.5f);
  for (size_t i = 0; i < linear.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float expected = srgb_encode(linear.pixels[i][c] * scale);
      EXPECT_NEAR(srgb_encode(encoded.pixels[i][c]), expected, 1.0f / 255.0f) << "pixel " << i;
    }
}

TEST(Cli, EachTermSwitchesOff) {
  test::ScratchDir dir;
  auto render = [&](std::vector<std::string> flags) {
    const fs::path out = dir / "t.exr";
    std::vector<std::string> args = {"render", cornell(), "--size", "48x48", "--out", out.string()};
    args.insert(args.end(), flags.begin(), flags.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return mean(io::read_image(out));
  };
  // The lamp's own radiance would dominate the mean, so compare without it.
  const double diffuse = render({"--no-emission", "--no-ambient"});
  EXPECT_GT(diffuse, 0.01);
  EXPECT_EQ(render({"--no-emission", "--no-ambient", "--no-diffuse"}), 0.0);  // ks = 0 everywhere
  EXPECT_GT(render({"--no-emission"}), diffuse);                            // ambient adds
  EXPECT_GT(render({}), render({"--no-emission"}));                         // the lamp shows its Le
}

// The Cornell box with a second camera, "side_camera", 0.2 m to the left of the first one: a
// scene where ignoring --camera would show.
fs::path cornell_with_two_cameras(const test::ScratchDir& dir) {
  std::ifstream in(cornell());
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["cameras"].push_back(doc["cameras"][0]);
  doc["cameras"][1]["name"] = "side_camera";
  nlohmann::json node = {{"name", "side_camera"}, {"camera", 1}, {"rotation", {0.0, 1.0, 0.0, 0.0}},
                         {"translation", {0.078, 0.273, -0.8}}};
  doc["nodes"].push_back(node);
  doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
  const fs::path path = dir / "two_cameras.gltf";
  std::ofstream(path) << doc.dump();
  fs::copy_file(test::scene_dir() / "cornell_box.bin", dir / "cornell_box.bin");
  return path;
}

// Without --size the picture is 600 pixels high at the camera's aspect ratio, 4:3 where the file
// gives none.
TEST(Cli, WithoutSizeThePictureHasTheCamerasAspect) {
  test::ScratchDir dir;
  std::ifstream in(cornell());
  nlohmann::json doc = nlohmann::json::parse(in);
  fs::copy_file(test::scene_dir() / "cornell_box.bin", dir / "cornell_box.bin");
  for (const auto& [aspect, width] : {std::pair{2.0, 1200}, std::pair{0.0, 800}}) {
    if (aspect > 0.0) doc["cameras"][0]["perspective"]["aspectRatio"] = aspect;
    else doc["cameras"][0]["perspective"].erase("aspectRatio");
    const fs::path scene = dir / "wide.gltf", out = dir / "wide.png";
    std::ofstream(scene) << doc.dump();
    const auto result = run_luz({"render", scene.string(), "--model", "flat", "--out", out.string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image image = io::read_image(out);
    EXPECT_EQ(image.width, width) << "aspect " << aspect;
    EXPECT_EQ(image.height, 600) << "aspect " << aspect;
  }
}

TEST(Cli, CameraByIndex) {
  test::ScratchDir dir;
  const std::string scene = cornell_with_two_cameras(dir).string();
  const auto render = [&](const std::vector<std::string>& camera, const std::string& name) {
    std::vector<std::string> args = {"render", scene, "--size", "24x24", "--out", (dir / name).string()};
    args.insert(args.end(), camera.begin(), camera.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return io::read_image(dir / name).pixels;
  };
  const auto first = render({"--camera", "0"}, "0.png");
  const auto second = render({"--camera", "1"}, "1.png");
  EXPECT_EQ(render({}, "default.png"), first) << "the first camera is the default";
  EXPECT_EQ(render({"--camera", "side_camera"}, "by_name.png"), second) << "index 1 is side_camera";
  EXPECT_NE(first, second) << "the two cameras see different pictures";
  const auto beyond = run_luz({"render", scene, "--camera", "2", "--out", (dir / "2.png").string()});
  EXPECT_EQ(beyond.exit_code, 2) << beyond.output;
  EXPECT_TRUE(contains(beyond.output, "no camera \"2\"")) << beyond.output;
}

// Issue 3: with no display the viewer says so, points to `luz render` and exits 1; it writes
// nothing (setup.sh, not luz, renders a picture on a headless machine).
TEST(Cli, WithoutADisplayTheViewerPointsToLuzRenderAndExitsWithOne) {
  test::ScratchDir dir;
  for (const std::vector<std::string>& args : {std::vector<std::string>{}, std::vector<std::string>{cornell()}}) {
    const auto result = run_luz(args, {.cwd = dir.path, .no_display = true});
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_TRUE(contains(result.output, "no display")) << result.output;
    EXPECT_TRUE(contains(result.output, "luz render")) << result.output;
    EXPECT_TRUE(fs::is_empty(dir.path));
  }
}

// ---- the messages in Spanish ----------------------------------------------------------------
// The expectations are the catalogue's translations, read from the .mo the build compiled.

std::string spanish(const char* id) {
  const std::string* text = i18n::catalogue(i18n::Language::es).find(id);
  EXPECT_NE(text, nullptr) << "no Spanish for " << id;
  return text ? *text : std::string(id);
}

// A translated format string's text before its first field: what a message starts with whatever
// it quotes.
std::string spanish_start(const char* id) {
  const std::string text = spanish(id);
  return text.substr(0, text.find("{}"));
}

// --lang es on luz or on luz render, and LANG=es_ES.UTF-8 without --lang, choose Spanish.
std::vector<std::pair<test::CommandOptions, std::vector<std::string>>> spanish_ways() {
  test::CommandOptions environment;
  environment.locale = "LC_ALL= LC_MESSAGES= LANG=es_ES.UTF-8";
  return {{{}, {"--lang", "es"}}, {{}, {"--lang=es"}}, {environment, {}}};
}

std::vector<std::string> with_language(const std::vector<std::string>& language, std::vector<std::string> args) {
  args.insert(args.begin(), language.begin(), language.end());
  return args;
}

TEST(CliSpanish, UsageErrorsSpeakSpanishWithTheSameExitCode) {
  test::ScratchDir dir;
  const std::string out = (dir / "x.png").string();
  const std::vector<std::string> bogus = {"render", cornell(), "--out", out, "--bogus"};
  const std::vector<std::string> size = {"render", cornell(), "--out", out, "--size", "12"};
  const std::vector<std::string> no_out = {"render", cornell()};
  const std::vector<std::string> model = {"render", cornell(), "--out", out, "--model", "cartoon"};
  ASSERT_EQ(run_luz(bogus).exit_code, 2);
  for (const auto& [options, language] : spanish_ways()) {
    const auto unexpected = run_luz(with_language(language, bogus), options);
    EXPECT_EQ(unexpected.exit_code, 2) << unexpected.output;
    EXPECT_TRUE(contains(unexpected.output, spanish_start("The following argument was not expected: {}") + "--bogus"))
        << unexpected.output;
    EXPECT_TRUE(contains(unexpected.output, spanish_start("Run with {} for more information.") + "--help"))
        << unexpected.output;
    EXPECT_FALSE(contains(unexpected.output, "not expected")) << unexpected.output;
    const auto bad_size = run_luz(with_language(language, size), options);
    EXPECT_EQ(bad_size.exit_code, 2);
    EXPECT_TRUE(contains(bad_size.output, "--size: " + spanish("expected WxH with 1 <= W, H <= 16384, e.g. 800x600")))
        << bad_size.output;
    const auto missing = run_luz(with_language(language, no_out), options);
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_TRUE(contains(missing.output, "--out" + spanish("{} is required").substr(2))) << missing.output;
    const auto cartoon = run_luz(with_language(language, model), options);
    EXPECT_EQ(cartoon.exit_code, 2);
    EXPECT_TRUE(contains(cartoon.output, spanish_start("unknown model \"{}\" ({}, or 2 or 4 of them separated by commas)")))
        << cartoon.output;
  }
  // --lang after the subcommand, as `luz render --help` lists it.
  const auto after = run_luz({"render", "--lang", "es", cornell(), "--out", out, "--bogus"});
  EXPECT_EQ(after.exit_code, 2);
  EXPECT_TRUE(contains(after.output, spanish_start("The following argument was not expected: {}"))) << after.output;
  // And after every other command's name (a missing file is bad input, in Spanish).
  const std::string nope = (dir / "nope.gltf").string();
  for (const std::vector<std::string>& command : std::vector<std::vector<std::string>>{
           {"solvers", nope, "--csv", (dir / "s.csv").string()},
           {"compare", nope, nope},
           {"bench", "whitted", "--scenes", nope}}) {
    std::vector<std::string> args = command;
    args.insert(args.end(), {"--lang", "es"});
    const auto spoken = run_luz(args);
    EXPECT_EQ(spoken.exit_code, 1) << command.front() << ": " << spoken.output;
    EXPECT_TRUE(contains(spoken.output, "no existe")) << command.front() << ": " << spoken.output;
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(CliSpanish, ABrokenSceneIsBadInputInSpanish) {
  test::ScratchDir dir;
  std::ofstream(dir / "broken.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ {";
  const std::vector<std::string> render = {"render", (dir / "broken.gltf").string(), "--out", (dir / "x.png").string()};
  const auto english = run_luz(render);
  EXPECT_EQ(english.exit_code, 1);
  EXPECT_TRUE(contains(english.output, "broken.gltf: not glTF: the JSON does not parse")) << english.output;
  for (const auto& [options, language] : spanish_ways()) {
    const auto result = run_luz(with_language(language, render), options);
    EXPECT_EQ(result.exit_code, english.exit_code) << result.output;
    EXPECT_TRUE(contains(result.output, "broken.gltf: " + spanish_start("not glTF: the JSON does not parse ({})")))
        << result.output;
  }
  const auto missing = run_luz({"--lang", "es", "render", (dir / "nope.gltf").string(), "--out", (dir / "x.png").string()});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_TRUE(contains(missing.output, "nope.gltf: " + spanish("no such file (or not a regular file)"))) << missing.output;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// The summary of a render that succeeded: its words ("camera", "exposure") in Spanish.
TEST(CliSpanish, TheRunSummarySpeaksSpanish) {
  test::ScratchDir dir;
  const std::string summary = spanish("{}: {} {}x{}, camera \"{}\", exposure {:+g} EV, {:.3f} s");
  const size_t after_size = summary.find("{}x{}, ") + 7;
  const std::string camera = summary.substr(after_size, summary.find(" \"") - after_size);  // "cámara"
  ASSERT_NE(camera, "camera");
  const auto result = run_luz({"--lang", "es", "render", cornell(), "--size", "40x30", "--out", (dir / "x.png").string()});
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "40x30, " + camera + " \"")) << result.output;
}

TEST(CliSpanish, HelpSpeaksSpanish) {
  for (const auto& [options, language] : spanish_ways()) {
    const auto render = run_luz(with_language(language, {"render", "--help"}), options);
    EXPECT_EQ(render.exit_code, 0);
    for (const char* id : {"Print nothing on success", "Switch off the ambient term I_A = Ia*ka",
                           "Output image: .png (sRGB, exposed) or .exr (linear radiance)"})
      EXPECT_TRUE(contains(render.output, spanish(id))) << id << "\n" << render.output;
    EXPECT_TRUE(contains(render.output, spanish("Usage") + ":")) << render.output;
    EXPECT_TRUE(contains(render.output, spanish("Options") + ":")) << render.output;
    EXPECT_TRUE(contains(render.output, "--no-ambient")) << "the flags keep their names";
    EXPECT_FALSE(contains(render.output, "Print nothing on success")) << render.output;
    const auto top = run_luz(with_language(language, {"--help"}), options);
    EXPECT_EQ(top.exit_code, 0);
    EXPECT_TRUE(contains(top.output, spanish("Render one picture headless (OSMesa, no display needed)"))) << top.output;
    EXPECT_TRUE(contains(top.output, spanish("Subcommands") + ":")) << top.output;
  }
  const auto english = run_luz({"render", "--help"});
  EXPECT_TRUE(contains(english.output, "Print nothing on success")) << english.output;
  EXPECT_TRUE(contains(english.output, "Options:")) << english.output;
}

// The text of a translated format string between its fields ("{}", "{:.3f}", ...): what the
// message prints whatever figures it holds.
std::vector<std::string> spanish_pieces(const char* id) {
  const std::string text = spanish(id);
  std::vector<std::string> pieces;
  size_t from = 0;
  for (size_t open = text.find('{'); open != std::string::npos; open = text.find('{', from)) {
    pieces.push_back(text.substr(from, open - from));
    from = text.find('}', open) + 1;
  }
  pieces.push_back(text.substr(from));
  return pieces;
}

// Every piece of `id`'s Spanish, in order, on one line of `output`.
bool has_spanish_line(const std::string& output, const char* id) {
  const std::vector<std::string> pieces = spanish_pieces(id);
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    size_t at = 0;
    bool all = true;
    for (const std::string& piece : pieces) {
      at = line.find(piece, at);
      if (at == std::string::npos) {
        all = false;
        break;
      }
      at += piece.size();
    }
    if (all) return true;
  }
  return false;
}

// The characters (not bytes) before each '|' of a table line: where its groups of columns end.
std::vector<size_t> bar_columns(const std::string& line) {
  std::vector<size_t> columns;
  size_t shown = 0;
  for (const char c : line) {
    if (c == '|') columns.push_back(shown);
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++shown;
  }
  return columns;
}

// `luz bench whitted`'s table in Spanish: its headers, the ray kinds under the scene and the
// notes, with the figures still under their headers where a Spanish header is the longer.
TEST(CliSpanish, TheWhittedBenchTableSpeaksSpanish) {
  const auto result = run_luz({"--lang", "es", "bench", "whitted", "--size", "8x6", "--repeats", "1",
                               "--depth", "1", "--scenes", "whitted"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(has_spanish_line(result.output,
                               "luz bench whitted: {}x{}, depth {}, {} spp, best of {}; {} threads on {}"))
      << result.output;
  std::string header, row;
  std::istringstream lines(result.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with(spanish("scene") + " ")) header = line;
    if (line.starts_with("whitted ")) row = line;
  }
  ASSERT_FALSE(header.empty()) << result.output;
  ASSERT_FALSE(row.empty()) << result.output;
  for (const char* id : {"render s", "rays", "Mrays/s", "bare s", "ratio"})
    EXPECT_TRUE(contains(header, spanish(id))) << id << "\n" << result.output;
  EXPECT_FALSE(contains(header, "ratio")) << header;
  EXPECT_EQ(bar_columns(header), bar_columns(row)) << header << "\n" << row;
  EXPECT_EQ(bar_columns(header).size(), 2u) << header;
  // At depth 1, 8 x 6 pixels, one sample each: 48 primary rays, named in Spanish.
  EXPECT_TRUE(std::regex_search(result.output, std::regex("  " + spanish("primary") + " +48 "))) << result.output;
  EXPECT_TRUE(has_spanish_line(result.output, "  {:<12} {:>10} rays, bare {:7.2f} Mrays/s")) << result.output;
  EXPECT_TRUE(has_spanish_line(result.output, "  render / bare of each round: best {:.2f}, median {:.2f}"))
      << result.output;
  EXPECT_TRUE(has_spanish_line(result.output, "  BVH build {:.3f} s")) << result.output;
}

// The tracer's counters printed after a Whitted render: rays of each kind, the ray-triangle
// tests of the brute-force intersector, time and rays per second, in Spanish.
TEST(CliSpanish, TheTracersCountersSpeakSpanish) {
  test::ScratchDir dir;
  const auto result = run_luz({"--lang", "es", "render", cornell(), "--model", "whitted", "--brute-force",
                               "--size", "16x12", "--out", (dir / "x.png").string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* id : {"rays: {} primary, {} shadow, {} reflected, {} transmitted ({} in all)",
                         "ray-triangle tests: {} ({:.1f} per ray)", "time: {:.3f} s, {:.2f} Mrays/s"})
    EXPECT_TRUE(has_spanish_line(result.output, id)) << id << "\n" << result.output;
  EXPECT_FALSE(contains(result.output, "in all")) << result.output;
  EXPECT_FALSE(contains(result.output, "per ray")) << result.output;
}

// ---- --exposure auto, and pictures far off their exposure --------------------------------------

// A triangle in z = 0 seen from +Z (the framing camera) under one point light at (0.3, 0.3, z) of
// `candela`, as `generator` wrote it.
std::string lit_triangle(const test::ScratchDir& dir, double candela, double z, const std::string& generator) {
  const fs::path path = dir / "lamp.gltf";
  std::ofstream(path) << nlohmann::json{
      {"asset", {{"version", "2.0"}, {"generator", generator}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes", {{{"mesh", 0}}, {{"translation", {0.3, 0.3, z}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", candela}}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                      {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
      {"buffers", {{{"byteLength", 36},
                    {"uri", "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}}}}};
  return path.string();
}

// A Spanish run names in Spanish what it names itself: the models of the summary and the camera
// it frames a scene without one with.
TEST(CliSpanish, TheNamesItGivesSpeakSpanish) {
  test::ScratchDir dir;
  const std::string scene = lit_triangle(dir, 10.0, 1.0, "test");
  const auto result = run_luz({"--lang", "es", "render", scene, "--model", "path", "--spp", "1", "--size", "8x6",
                               "--out", (dir / "x.png").string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ASSERT_NE(spanish("path tracer"), "path tracer");
  EXPECT_TRUE(contains(result.output, ": " + spanish("path tracer") + " 8x6, ")) << result.output;
  EXPECT_TRUE(contains(result.output, "\"" + spanish("framing") + "\"")) << result.output;
  EXPECT_FALSE(contains(result.output, "\"framing\"")) << result.output;
}

std::string fmt_ev(float ev) {
  std::ostringstream text;
  text << ev;
  return text.str();
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The "exposure ... EV" of the summary line, as a number.
float printed_exposure(const std::string& output) {
  std::smatch match;
  if (!std::regex_search(output, match, std::regex(R"(exposure ([-+][0-9.]+) EV)"))) return NAN;
  return std::stof(match[1]);
}

TEST(Cli, ABlenderLampReadAsWattsPerSteradianIsWarnedOfAndAutoFitsIt) {
  test::ScratchDir dir;
  // Blender's 100 W lamp 3 m away: 100 / 4 pi x 683 = 5435 cd.
  const std::string scene = lit_triangle(dir, 5435.14, 3.0, "Khronos glTF Blender I/O v3.4.50");
  const auto plain = run_luz({"render", scene, "--out", (dir / "plain.png").string(), "--size", "200x150"});
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_TRUE(contains(plain.output, "warning: " + (dir / "plain.png").string() +
                                         ": at +0 EV the picture is over-exposed: 100% of its lit pixels are white"))
      << plain.output;
  EXPECT_TRUE(contains(plain.output, "Blender I/O v3.4.50 writes lights in candela")) << plain.output;
  EXPECT_TRUE(contains(plain.output, "; --exposure auto fits it")) << plain.output;

  const auto fitted = run_luz({"render", scene, "--out", (dir / "auto.png").string(), "--size", "200x150",
                               "--exposure", "auto"});
  EXPECT_EQ(fitted.exit_code, 0) << fitted.output;
  EXPECT_FALSE(contains(fitted.output, "exposed")) << fitted.output;  // (the file has no camera: that is said)
  // The fit computed here from the radiance of the scene's key picture, the path tracer's 80 x 60
  // pixels of 64 samples (a 4:3 camera): log2(0.18 / exp(mean log Y)) over lit pixels.
  const auto exr = run_luz({"render", scene, "--out", (dir / "lamp.exr").string(), "--size", "80x60", "--model",
                            "path", "--spp", "64"});
  ASSERT_EQ(exr.exit_code, 0) << exr.output;
  EXPECT_FALSE(contains(exr.output, "over-exposed")) << "an EXR holds radiance: no exposure to warn of";
  double log_sum = 0.0;
  int lit = 0;
  for (const Rgb& c : io::read_image(dir / "lamp.exr").pixels)
    if (const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; y > 0.0) log_sum += std::log(y), ++lit;
  ASSERT_GT(lit, 500);
  const float ev = printed_exposure(fitted.output);
  EXPECT_NEAR(ev, std::log2(0.18 / std::exp(log_sum / lit)), 0.05 + 1e-4) << fitted.output;
  EXPECT_LT(ev, -8.0f);
  // The PNG is the one --exposure writes with that number.
  const auto typed = run_luz({"render", scene, "--out", (dir / "typed.png").string(), "--size", "200x150",
                              "--exposure", fmt_ev(ev)});
  ASSERT_EQ(typed.exit_code, 0) << typed.output;
  EXPECT_EQ(file_bytes(dir / "auto.png"), file_bytes(dir / "typed.png"));
  EXPECT_NE(file_bytes(dir / "auto.png"), file_bytes(dir / "plain.png"));

  // Side by side: one exposure for the sheet.
  const auto sheet = run_luz({"render", scene, "--out", (dir / "sheet.png").string(), "--size", "200x150",
                              "--model", "phong,whitted", "--exposure", "auto"});
  EXPECT_EQ(sheet.exit_code, 0) << sheet.output;
  EXPECT_EQ(printed_exposure(sheet.output), ev) << sheet.output;  // the same fit as the run alone
  const auto unfitted_sheet = run_luz({"render", scene, "--out", (dir / "sheet.png").string(), "--size", "200x150",
                                       "--model", "phong,whitted"});
  EXPECT_TRUE(contains(unfitted_sheet.output, "over-exposed")) << unfitted_sheet.output;
}

TEST(Cli, TheExposureWarningNamesNoBlenderForOtherFilesNorForAGivenExposure) {
  test::ScratchDir dir;
  const std::string scene = lit_triangle(dir, 5435.14, 3.0, "some exporter");
  const auto plain = run_luz({"render", scene, "--out", (dir / "x.png").string(), "--size", "100x75"});
  EXPECT_TRUE(contains(plain.output, "over-exposed")) << plain.output;
  EXPECT_FALSE(contains(plain.output, "candela")) << plain.output;
  // An exposure given is what the user wants: no warning about it.
  const auto given = run_luz({"render", scene, "--out", (dir / "x.png").string(), "--size", "100x75",
                              "--exposure", "1.5"});
  EXPECT_FALSE(contains(given.output, "exposed")) << given.output;
  EXPECT_EQ(printed_exposure(given.output), 1.5f) << given.output;
  const auto bad = run_luz({"render", scene, "--out", (dir / "x.png").string(), "--exposure", "bright"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(contains(bad.output, "bright: expected a finite number or auto")) << bad.output;
}

TEST(Cli, ExposureAutoKeepsTheScenesWhenNothingIsLit) {
  test::ScratchDir dir;
  // The lamp behind the triangle: the camera sees its unlit side.
  const std::string scene = lit_triangle(dir, 10.0, -3.0, "");
  const auto dark = run_luz({"render", scene, "--out", (dir / "x.png").string(), "--size", "100x75",
                             "--exposure", "auto"});
  EXPECT_EQ(dark.exit_code, 0) << dark.output;
  EXPECT_TRUE(contains(dark.output, "nothing in the picture is lit: --exposure auto keeps +0 EV")) << dark.output;
  EXPECT_EQ(printed_exposure(dark.output), 0.0f);
}

// The shipped scenes are exposed as they were made: no model's picture is far off.
TEST(Cli, NoShippedSceneIsFarOffItsExposure) {
  test::ScratchDir dir;
  for (const auto& entry : fs::directory_iterator(test::scene_dir())) {
    if (entry.path().extension() != ".gltf") continue;
    const auto r = run_luz({"render", entry.path().string(), "--out", (dir / "x.png").string(), "--size", "160x120",
                            "--model", "flat,phong,whitted,path", "--spp", "4"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_FALSE(contains(r.output, "exposed")) << entry.path() << ": " << r.output;
  }
}

}  // namespace
}  // namespace luz
