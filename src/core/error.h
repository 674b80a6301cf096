#pragma once
// User errors: a kind a test can match and a one-line message that names the input and the
// problem, e.g. `scene.gltf: material 3 "glass": ior is NaN`. The command prints the message
// and exits 1 (bad input) or 2 (usage). Programmer errors are asserts, not these.
#include <stdexcept>
#include <string>

namespace luz {

enum class ErrorKind {
  usage,               // a bad flag or value on the command line (exit 2)
  file_missing,        // the file does not exist or cannot be read
  not_gltf,            // not parseable as glTF 2.0
  truncated_buffer,    // a buffer or accessor reaches past the data it refers to
  index_out_of_range,  // an index (vertex, material, node, ...) points past its array
  not_finite,          // NaN or Inf in positions, normals, materials, lights, cameras
  uri_outside_folder,  // an external URI that leaves the scene's folder
  no_triangles,        // nothing to draw
  bad_value,           // a value outside its domain (negative ior, zero-size image, ...)
  output,              // the output file cannot be written
  gl,                  // no usable OpenGL context / shader failure
};

const char* to_string(ErrorKind kind);

struct Error : std::runtime_error {
  ErrorKind kind;
  Error(ErrorKind k, const std::string& message) : std::runtime_error(message), kind(k) {}
};

}  // namespace luz
