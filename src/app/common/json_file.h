#pragma once
// The files the script's dump verbs and the command line's --csv and --ray-tree write: whole or
// not at all (io/atomic_file.h), and a failure said as "PATH: cannot write WHAT".
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace luz::app {

// `json` indented by two, with a newline at the end; false when not written.
bool write_json(const std::string& path, const nlohmann::json& json);
// The same, with `error` set when not written.
bool write_json(const std::string& path, const nlohmann::json& json, std::string_view what, std::string& error);
// `text` as it is.
bool write_text(const std::string& path, const std::string& text, std::string_view what, std::string& error);

}  // namespace luz::app
