#include "toy_model/toy_model.h"

#include <fmt/format.h>

#include "app/cli/render_command.h"
#include "app/common/model_registry.h"

namespace luz::test {
namespace {

using app::OptionKind;

const app::OptionRow rows[] = {
    {"bounces", "--toy-bounces", "toy", OptionKind::integer, "toy: how many times", 1, 8,
     LUZ_OPTION_FIELD(ToyOptions, bounces)},
    {"gain", "--toy-gain", "toy", OptionKind::real, "toy: how bright", 0, 4, LUZ_OPTION_FIELD(ToyOptions, gain)},
    {"glow", "--toy-glow", "toy", OptionKind::on_off, "toy: glow", 0, 1, LUZ_OPTION_FIELD(ToyOptions, glow)},
    app::file_row("log", "--toy-log", "toy", "toy: write a log to this file", LUZ_OPTION_TEXT(ToyOptions, log)),
};

app::Rendered render_toy(const Scene&, const Camera&, int width, int height, const app::RenderSettings& settings) {
  const ToyOptions& o = settings.model_options.get<ToyOptions>(toy_table());
  return {Image(width, height, Rgb(float(o.bounces) * o.gain)), fmt::format("toy: {} bounces, gain {}, glow {}\n", o.bounces, o.gain, o.glow), std::nullopt};
}

constexpr const char* toy_flags[] = {"toy"};
constexpr app::OptionTableOf toy_options[] = {toy_table};

// Its line: the registry's entry, registered beside the catalogue's.
const app::ModelRegistration toy{
    {"toy", "toy", 8, "a model of the tests", toy_flags, toy_options, render_toy, nullptr, {}, nullptr}};

}  // namespace

const app::OptionTable& toy_table() {
  static const app::OptionTable table = app::option_table<ToyOptions>("toy", rows);
  return table;
}

}  // namespace luz::test
