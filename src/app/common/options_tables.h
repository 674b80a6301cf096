#pragma once
// One table per options struct (LocalOptions, rt::WhittedOptions, RadiosityOptions): each row
// names an option once, with its script name, its `luz render` flag, its range and its help.
// The defaults are never written here: they are read from a default-constructed struct, which
// is where they live (STYLE.md 2). `luz render`'s flags and --help, the script's `set` verb and
// the panel's slider ranges all come from these rows.
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "local/local_options.h"
#include "radiosity/radiosity_options.h"
#include "raytracing/whitted_options.h"

namespace luz::app {

enum class OptionKind {
  on_off,   // a switch; its flag turns it away from its default (--no-ambient, --shadows)
  integer,  // a whole number in [low, high] (and `rule`, when there is one)
  real,     // a finite number in [low, high]
  choice,   // one of `choices`, by name; stored as its index
};

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

template <class Options>
struct OptionRow {
  const char* name;   // the script's `set NAME`, and how the panel finds the row
  const char* flag;   // `luz render`'s flag, or nullptr (the viewer's only)
  const char* group;  // the flag group (model_registry.h): which models take the flag
  OptionKind kind;
  const char* help;   // an N_() message id: shown through tr()
  double low, high;   // integer, real: the accepted range (kUnbounded: no upper end)
  double (*get)(const Options&);
  void (*set)(Options&, double);
  std::span<const char* const> choices = {};
  bool (*rule)(double) = nullptr;  // a further condition (even, a square)
  const char* rule_text = nullptr; // what it says: "even"
};

using LocalRow = OptionRow<LocalOptions>;
using WhittedRow = OptionRow<rt::WhittedOptions>;
using RadiosityRow = OptionRow<RadiosityOptions>;

std::span<const LocalRow> local_rows();
std::span<const WhittedRow> whitted_rows();
std::span<const RadiosityRow> radiosity_rows();

// The row of that script name in a table; nullptr when there is none.
template <class Options>
const OptionRow<Options>* find_row(std::span<const OptionRow<Options>> rows, std::string_view name) {
  for (const OptionRow<Options>& row : rows)
    if (name == row.name) return &row;
  return nullptr;
}

// The default of a row, as its struct has it, in words: "5", "0.002", "on", "linear".
template <class Options>
std::string default_text(const OptionRow<Options>& row);

// "a whole number in 0 .. 64" / "a finite number >= 0": what a row accepts. In English for the
// script's messages (written for the teacher preparing a demo), translated for `luz render`.
enum class Wording { english, translated };
template <class Options>
std::string accepted_text(const OptionRow<Options>& row, Wording wording = Wording::english);

// Parses `text` for the row ("on"/"off" for a switch, a choice's name, a number in range and,
// `with_rule`, meeting the row's rule); nullopt when it is not accepted.
template <class Options>
std::optional<double> parse_value(const OptionRow<Options>& row, const std::string& text, bool with_rule = true);

// The panel's slider range of a numeric row: its low and high (high capped at `cap` when
// unbounded).
struct SliderRange {
  float low, high;
};
template <class Options>
SliderRange slider_range(const OptionRow<Options>& row, double cap = 1000.0) {
  return {float(row.low), float(row.high == kUnbounded ? cap : row.high)};
}
// By name, for the panel: the range of the row of that name in the local, Whitted or
// radiosity table (an unknown name is a programmer's error).
SliderRange local_range(std::string_view name);
SliderRange whitted_range(std::string_view name);
SliderRange radiosity_range(std::string_view name);

}  // namespace luz::app
