#pragma once
// A model that lives in the tests only, added the way docs/adding-a-model.md adds one: its folder
// (this one), its registration and its CMake line, and no line anywhere else. Its picture is a
// flat radiance of bounces x gain, so that a test sees what its options reached.
#include <string>

#include "app/common/option_row.h"

namespace luz::test {

struct ToyOptions {
  int bounces = 3;
  float gain = 0.5f;
  bool glow = false;
  std::string log;  // a file its render writes: `luz render`'s flag only
};

const app::OptionTable& toy_table();

}  // namespace luz::test
