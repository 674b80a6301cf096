#include "app/common/json_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/atomic_file.h"

namespace luz::app {

bool write_text(const std::string& path, const std::string& text, std::string_view what, std::string& error) {
  if (io::write_atomically(path, [&] { return text; }).empty()) return true;
  error = fmt::format("{}: cannot write {}", path, what);
  return false;
}

bool write_json(const std::string& path, const nlohmann::json& json) {
  return io::write_atomically(path, [&] { return json.dump(2) + '\n'; }).empty();
}

bool write_json(const std::string& path, const nlohmann::json& json, std::string_view what, std::string& error) {
  if (write_json(path, json)) return true;
  error = fmt::format("{}: cannot write {}", path, what);
  return false;
}

}  // namespace luz::app
