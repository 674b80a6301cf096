#include "app/common/option_row.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cstring>

#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/common/numbers.h"

namespace luz::app {
namespace {

std::string number_text(double v) { return fmt::format("{:g}", v); }

// An end of a row's range: a whole number in full (a seed's 4294967295).
std::string bound_text(const OptionRow& row, double v) {
  return row.kind == OptionKind::integer ? std::to_string((long long)(v)) : number_text(v);
}

// A whole number, as wide as a seed (uint32_t) needs.
bool is_whole(const std::string& text) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

const OptionRow* find_row(const OptionTable& table, std::string_view name) {
  for (const OptionRow& row : table.rows)
    if (name == row.name) return &row;
  return nullptr;
}

std::string value_text(const OptionRow& row, const void* options) {
  if (row.kind == OptionKind::file) return row.get_text(options);
  const double v = row.get(options);
  switch (row.kind) {
    case OptionKind::on_off: return v != 0.0 ? "on" : "off";
    case OptionKind::choice: return row.choices[size_t(v)];
    case OptionKind::integer: return bound_text(row, v);
    case OptionKind::real:
    case OptionKind::file: break;
  }
  return number_text(v);
}

std::string default_text(const OptionTable& table, const OptionRow& row) { return value_text(row, table.defaults()); }

std::string accepted_text(const OptionRow& row, Wording wording) {
  const auto say = [wording](const char* id) { return wording == Wording::translated ? tr(id) : id; };
  switch (row.kind) {
    case OptionKind::on_off: return say(N_("on or off"));
    case OptionKind::choice: {
      std::string names;
      for (const char* c : row.choices) names += (names.empty() ? "" : ", ") + std::string(c);
      return fmt::format(fmt::runtime(say(N_("one of {}"))), names);
    }
    case OptionKind::file: return say(N_("a file name, given to luz render"));
    default: break;
  }
  const bool whole = row.kind == OptionKind::integer;
  std::string text =
      row.high == kUnbounded
          ? fmt::format(fmt::runtime(say(whole ? N_("a whole number >= {}") : N_("a finite number >= {}"))),
                        bound_text(row, row.low))
          : fmt::format(fmt::runtime(say(whole ? N_("a whole number in {} .. {}") : N_("a finite number in {} .. {}"))),
                        bound_text(row, row.low), bound_text(row, row.high));
  if (row.rule_text) text += fmt::format(", {}", say(row.rule_text));
  return text;
}

std::optional<double> parse_value(const OptionRow& row, const std::string& text, bool with_rule) {
  switch (row.kind) {
    case OptionKind::on_off:
      if (text == "on") return 1.0;
      if (text == "off") return 0.0;
      return std::nullopt;
    case OptionKind::choice:  // in any case: --fog Exponential
      for (size_t i = 0; i < row.choices.size(); ++i)
        if (std::equal(text.begin(), text.end(), row.choices[i], row.choices[i] + std::strlen(row.choices[i]),
                       [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; }))
          return double(i);
      return std::nullopt;
    case OptionKind::integer:
      if (!is_whole(text)) return std::nullopt;
      break;
    case OptionKind::real:
      if (!is_number(text)) return std::nullopt;  // finite: nan and inf are refused
      break;
    case OptionKind::file: return std::nullopt;  // no number: `luz render`'s flag writes its text
  }
  const double v = std::stod(text);
  if (!(v >= row.low && v <= row.high)) return std::nullopt;
  if (with_rule && row.rule && !row.rule(v)) return std::nullopt;
  return v;
}

SliderRange slider_range(const OptionRow& row, double cap) {
  return {float(row.low), float(row.high == kUnbounded ? cap : row.high)};
}

SliderRange slider_range(const OptionTable& table, std::string_view name, double cap) {
  const OptionRow* row = find_row(table, name);
  return row ? slider_range(*row, cap) : SliderRange{0.0f, 1.0f};
}

}  // namespace luz::app
