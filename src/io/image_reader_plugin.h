#pragma once
// The boundary between Luz and OpenImageIO, which reads every image Luz reads (textures,
// --environment maps, reference pictures). OpenImageIO brings some 260 shared libraries whose
// loading took 0.16-0.19 s of every start of `luz` (docs/performance.md), so it lives in a plugin
// (luz_image_reader, a module beside the program) opened on the first image read: a C interface,
// so that nothing but these plain types crosses it, and no exception.
#include <cstddef>

extern "C" {

struct LuzImageHeader {
  int width = 0, height = 0, channels = 0;
  int bytes_per_channel = 0;  // 1 or 2: the file's own 8 or 16-bit values; 4: floats
  int png_or_jpeg = 0;        // 1 when the file is a PNG or a JPEG
};

// Every function writes a message of at most `error_size` bytes into `error` when it fails.
struct LuzImageReader {
  // An image file, or encoded bytes of `format` ("png", "jpeg"), which must outlive the handle.
  // Null on failure.
  void* (*open_file)(const char* path, char* error, size_t error_size);
  void* (*open_memory)(const unsigned char* bytes, size_t size, const char* format, char* error,
                       size_t error_size);
  void (*header)(void* handle, LuzImageHeader* out);
  // Every pixel, channel after channel, in the header's type: width * height * channels *
  // bytes_per_channel bytes. 0 on failure.
  int (*read)(void* handle, void* pixels, char* error, size_t error_size);
  void (*close)(void* handle);
};

// The plugin's one exported symbol.
const LuzImageReader* luz_image_reader(void);
typedef const LuzImageReader* (*LuzImageReaderEntry)(void);

}  // extern "C"
