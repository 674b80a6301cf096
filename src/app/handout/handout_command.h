#pragma once
// `luz lesson [LESSON] --handout lesson.pdf --png-dir DIR`: every step of a lesson rendered
// headless as the window's picture shows it (lesson_picture.h), with its slide, title and text in
// the chosen language, on A4 pages (handout_pdf.h) and/or one PNG per step.
#include <string>

#include <CLI/CLI.hpp>

namespace luz::app {

struct HandoutSettings {
  std::string lesson;    // empty: lessons/sintesis.json
  std::string pdf;       // --handout
  std::string png_dir;   // --png-dir
  int width = 0, height = 0;  // --size: each step's picture (0: luz render's default)
  std::string steps;     // --steps A-B (from 1); empty: all
  // --time: each step's radiosity solve and path tracing stop when it is up, as the class moves
  // on while the solver runs (a 5 cm mesh converges in minutes, not seconds).
  double seconds = 20.0;
  bool quiet = false;
};

void add_handout_flags(CLI::App& lesson, HandoutSettings& settings);

// Returns the exit code: 0, 1 (a bad lesson file, an output that cannot be written, a step that
// fails), 2 (usage); nothing is left at the outputs' paths unless every step succeeded.
int run_handout(const HandoutSettings& settings);

}  // namespace luz::app
