#pragma once
// The lesson as a handout: A4 pages written through Cairo's PDF surface, kStepsPerPage steps on
// each, every step its slide and step number, its title, its picture and its text.
#include <filesystem>
#include <memory>
#include <string>

#include "core/image.h"

namespace luz::app {

inline constexpr int kStepsPerPage = 2;

struct HandoutStep {
  std::string heading;  // "Diapositiva 17 · paso 3 de 59"
  std::string title;
  std::string text;
  bool heat_map = false;  // the picture is radiosity's heat map: its fixed scale goes under it
};

class HandoutPdf {
public:
  // Opens `path` for writing (the caller writes it beside the final name and renames it).
  // Throws luz::Error (output) naming the file when it cannot be created.
  HandoutPdf(const std::filesystem::path& path, std::string lesson_title);
  ~HandoutPdf();
  HandoutPdf(const HandoutPdf&) = delete;
  HandoutPdf& operator=(const HandoutPdf&) = delete;

  // The step's picture is `picture` x 2^exposure through the sRGB curve, as its PNG.
  void add(const HandoutStep& step, const Image& picture, float exposure);
  // Ends the last page and writes the file; throws luz::Error (output) when Cairo could not.
  void finish();
  int pages() const { return pages_; }

private:
  struct Cairo;
  void footer();
  double heat_map_legend(double y);
  std::unique_ptr<Cairo> cairo_;
  std::filesystem::path path_;
  std::string lesson_title_;
  int on_page_ = 0;  // steps on the page being laid out
  int pages_ = 0;
};

}  // namespace luz::app
