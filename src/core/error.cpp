#include "core/error.h"

namespace luz {

const char* to_string(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::usage: return "usage";
    case ErrorKind::file_missing: return "file_missing";
    case ErrorKind::not_gltf: return "not_gltf";
    case ErrorKind::truncated_buffer: return "truncated_buffer";
    case ErrorKind::index_out_of_range: return "index_out_of_range";
    case ErrorKind::not_finite: return "not_finite";
    case ErrorKind::uri_outside_folder: return "uri_outside_folder";
    case ErrorKind::no_triangles: return "no_triangles";
    case ErrorKind::bad_value: return "bad_value";
    case ErrorKind::output: return "output";
    case ErrorKind::gl: return "gl";
  }
  return "?";
}

}  // namespace luz
