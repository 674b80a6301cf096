#pragma once
// The fixed-width tables of `luz bench whitted` and `luz bench local`, and their figures'
// summary. Each column is as wide as its default or as its header in the current language,
// whichever is wider, so that a Spanish header longer than the English one keeps the figures
// under it. Widths count the characters shown, not the bytes: "proporción" is 10 wide in UTF-8's
// 11 bytes.
#include <string>
#include <string_view>
#include <vector>

namespace luz::app {

// The best (least) and the median of some timings: what every bench prints.
struct Timing {
  double best = 0.0, median = 0.0;
};
Timing best_and_median(std::vector<double> times);

// The processor's name, from /proc/cpuinfo: every bench says which machine its figures are from.
std::string cpu_model();

// The characters a UTF-8 text shows: every byte starts one but the continuation bytes 10xxxxxx.
size_t shown_width(std::string_view utf8);

struct BenchColumn {
  std::string header;      // as printed (already translated)
  size_t width = 0;        // at least this many characters
  bool left = false;       // text (names) to the left, figures to the right
  bool bar_after = false;  // " | " after it, between groups of columns
};

class BenchTable {
public:
  explicit BenchTable(std::vector<BenchColumn> columns);
  // Widens column `index` to hold `text`, a row label known before the table is printed.
  void fit(size_t index, std::string_view text);
  std::string header() const;                               // one line, with its '\n'
  std::string row(const std::vector<std::string>& cells) const;  // one cell per column

private:
  std::vector<BenchColumn> columns_;
};

}  // namespace luz::app
