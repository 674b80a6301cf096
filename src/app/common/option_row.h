#pragma once
// An option, named once: its script name, its `luz render` flag, its range and its help, and the
// read and write of its field. A model's options are one table of rows over one options struct
// (OptionTable); the registry's entries name the tables they take (model_registry.h), and
// `luz render`'s flags and --help, the script's `set`, the panel's ranges, dump-state and the
// lessons all go through the rows. The defaults are never written in a row: they are read from
// the table's default-constructed struct, which is where they live (STYLE.md 2).
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>

namespace luz::app {

enum class OptionKind {
  on_off,   // a switch; its flag turns it away from its default (--no-ambient, --shadows)
  integer,  // a whole number in [low, high] (and `rule`, when there is one)
  real,     // a finite number in [low, high]
  choice,   // one of `choices`, by name; stored as its index
  file,     // a file `luz render` writes (--error-out): its text, read and written by get_text
            // and set_text; the viewer writes no file, so its `set`, dump-state and the lessons
            // leave such a row out (parse_value takes no value for it)
};

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct OptionRow {
  const char* name;   // the script's `set NAME`, and how the panel finds the row
  const char* flag;   // `luz render`'s flag, or nullptr (the viewer's only)
  const char* group;  // the flag group (model_registry.h): which models take the flag
  OptionKind kind;
  const char* help;   // an N_() message id: shown through tr()
  double low, high;   // integer, real: the accepted range (kUnbounded: no upper end)
  double (*get)(const void* options);  // of the table's struct
  void (*set)(void* options, double value);
  std::span<const char* const> choices = {};
  bool (*rule)(double) = nullptr;  // a further condition (even, a square)
  const char* rule_text = nullptr; // what it says: "even"
  std::string (*get_text)(const void* options) = nullptr;  // a file row's (its get and set are nullptr)
  void (*set_text)(void* options, const std::string& text) = nullptr;
};

// Whether the viewer takes a row (`set`, dump-state, the lessons): every row but a file's.
inline bool in_viewer(const OptionRow& row) { return row.kind != OptionKind::file; }

// A row's read and write of one field of its table's struct (a nested one too: fog.near).
#define LUZ_OPTION_FIELD(Options, field)                                                     \
  [](const void* o) { return double(static_cast<const Options*>(o)->field); },               \
  [](void* o, double v) {                                                                     \
    auto& f = static_cast<Options*>(o)->field;                                                \
    f = std::remove_reference_t<decltype(f)>(v);                                              \
  }

// The same for a field that is an enumeration (a choice row: the index of its name).
#define LUZ_OPTION_CHOICE(Options, field)                                                    \
  [](const void* o) { return double(int(static_cast<const Options*>(o)->field)); },          \
  [](void* o, double v) {                                                                     \
    auto& f = static_cast<Options*>(o)->field;                                                \
    f = std::remove_reference_t<decltype(f)>(int(v));                                         \
  }

// A file row over a std::string field (OptionKind::file).
#define LUZ_OPTION_TEXT(Options, field)                                                      \
  [](const void* o) { return static_cast<const Options*>(o)->field; },                        \
  [](void* o, const std::string& v) { static_cast<Options*>(o)->field = v; }

constexpr OptionRow file_row(const char* name, const char* flag, const char* group, const char* help,
                             std::string (*get_text)(const void*), void (*set_text)(void*, const std::string&)) {
  return {name, flag, group, OptionKind::file, help, 0, 0, nullptr, nullptr, {}, nullptr, nullptr, get_text, set_text};
}

// The rows over one options struct, and that struct's type: a copy of it is made for every
// program and picture that takes these options (option_values.h).
struct OptionTable {
  const char* name;  // dump-state's key, and `set NAME.ROW` when two tables have a ROW
  std::span<const OptionRow> rows;
  const std::type_info* type;                          // the struct's
  const void* (*defaults)();                           // a default-constructed one
  std::shared_ptr<void> (*copy)(const void* options);  // a new one, equal to `options`
  // The viewer's start, where it differs from `luz render`'s defaults (the path tracer's
  // target, which the window refines to); nullptr when it does not.
  void (*in_viewer)(void* options) = nullptr;
};

template <class Options>
const void* default_options() {
  static const Options defaults{};
  return &defaults;
}

template <class Options>
std::shared_ptr<void> copy_options(const void* options) {
  return std::make_shared<Options>(*static_cast<const Options*>(options));
}

// The table of `rows` over the struct Options.
template <class Options>
OptionTable option_table(const char* name, std::span<const OptionRow> rows, void (*in_viewer)(void*) = nullptr) {
  return {name, rows, &typeid(Options), default_options<Options>, copy_options<Options>, in_viewer};
}

// The row of that script name in a table; nullptr when there is none.
const OptionRow* find_row(const OptionTable& table, std::string_view name);

// The default of a row, as its table's struct has it, in words: "5", "0.002", "on", "linear".
std::string default_text(const OptionTable& table, const OptionRow& row);

// A row's value in `options`, in the words `set` takes: "5", "on", "linear".
std::string value_text(const OptionRow& row, const void* options);

// "a whole number in 0 .. 64" / "a finite number >= 0": what a row accepts. In English for the
// script's messages (written for the teacher preparing a demo), translated for `luz render`.
enum class Wording { english, translated };
std::string accepted_text(const OptionRow& row, Wording wording = Wording::english);

// The one check of a value: parses `text` for the row ("on"/"off" for a switch, a choice's name,
// a number in range and, `with_rule`, meeting the row's rule); nullopt when it is not accepted.
std::optional<double> parse_value(const OptionRow& row, const std::string& text, bool with_rule = true);

// The panel's slider range of a numeric row: its low and high (high capped at `cap` when
// unbounded).
struct SliderRange {
  float low, high;
};
SliderRange slider_range(const OptionRow& row, double cap = 1000.0);
// By name, for the panel: the range of the row of that name in the table (an unknown name is a
// programmer's error: 0 .. 1).
SliderRange slider_range(const OptionTable& table, std::string_view name, double cap = 1000.0);

}  // namespace luz::app
