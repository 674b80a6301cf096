// libFuzzer target: the texture decoder (PNG / JPEG bytes as glTF embeds them) on arbitrary
// bytes. std::nullopt with a message is the expected answer to bad input; a crash, an exception
// or a sanitizer report is a finding, and so is an allocation beyond the documented image cap
// (libFuzzer's -rss_limit_mb catches it).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<unsigned char> bytes(data, data + size);
  std::string error;
  (void)luz::io::decode_texture(bytes, "fuzz", error);
  return 0;
}
