#pragma once
// Whole words read as numbers, for the script's arguments and the options tables' values.
#include <string>

namespace luz::app {

bool is_int(const std::string& text);
bool is_number(const std::string& text);  // finite

}  // namespace luz::app
