#include "app/common/numbers.h"

#include <charconv>
#include <cmath>

namespace luz::app {

bool is_int(const std::string& text) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

bool is_number(const std::string& text) {
  try {
    size_t used = 0;
    const float value = std::stof(text, &used);
    return used == text.size() && std::isfinite(value);
  } catch (...) {
    return false;
  }
}

}  // namespace luz::app
