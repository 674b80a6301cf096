#include "io/gltf_uris.h"

#include <cctype>

#include "core/i18n.h"

namespace luz::io::gltf {

namespace fs = std::filesystem;
using i18n::N_;

bool is_data_uri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

std::string uri_path(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  for (char& c : out)
    if (c == '\\') c = '/';
  return out;
}

bool inside(const fs::path& folder, const fs::path& path) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(path, ec);
  if (ec) return false;
  const fs::path relative = resolved.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

// Refused: any scheme (file://, http://, ...) or drive (D:), absolute paths, `..` components,
// and relative paths that a symbolic link leads out of the folder.
const char* why_outside(const fs::path& folder, const std::string& uri) {
  const std::string path = uri_path(uri);
  const size_t colon = path.find(':');
  const size_t slash = path.find('/');
  if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
    return N_("has a scheme or drive");
  if (!path.empty() && path[0] == '/') return N_("is absolute");
  std::string component;
  for (char c : path + "/") {
    if (c != '/') {
      component += c;
      continue;
    }
    if (component == "..") return N_("goes up with ..");
    component.clear();
  }
  if (!inside(folder, folder / path)) return N_("leads out of the folder");
  return nullptr;
}

fs::path beside_the_scene(const fs::path& folder, const std::string& uri) {
  const std::string path = uri_path(uri);
  return folder / path.substr(path.find_last_of('/') + 1);  // npos + 1 == 0: the whole path
}

}  // namespace luz::io::gltf
