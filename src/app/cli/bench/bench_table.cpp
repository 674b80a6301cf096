#include "app/cli/bench/bench_table.h"

#include <algorithm>
#include <fstream>
#include <utility>

#include "app/common/i18n.h"

namespace luz::app {

Timing best_and_median(std::vector<double> times) {
  if (times.empty()) return {};
  std::sort(times.begin(), times.end());
  const size_t half = times.size() / 2;
  const double median = times.size() % 2 ? times[half] : 0.5 * (times[half - 1] + times[half]);
  return {times.front(), median};
}

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return tr("unknown CPU");
}

size_t shown_width(std::string_view utf8) {
  return size_t(std::count_if(utf8.begin(), utf8.end(),
                              [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

BenchTable::BenchTable(std::vector<BenchColumn> columns) : columns_(std::move(columns)) {
  for (size_t i = 0; i < columns_.size(); ++i) fit(i, columns_[i].header);
}

void BenchTable::fit(size_t index, std::string_view text) {
  columns_[index].width = std::max(columns_[index].width, shown_width(text));
}

std::string BenchTable::header() const {
  std::vector<std::string> headers;
  for (const BenchColumn& column : columns_) headers.push_back(column.header);
  return row(headers);
}

std::string BenchTable::row(const std::vector<std::string>& cells) const {
  std::string line;
  for (size_t i = 0; i < columns_.size() && i < cells.size(); ++i) {
    if (i > 0) line += columns_[i - 1].bar_after ? " | " : " ";
    const std::string& cell = cells[i];
    const std::string padding(columns_[i].width - std::min(columns_[i].width, shown_width(cell)), ' ');
    line += columns_[i].left ? cell + padding : padding + cell;
  }
  return line + "\n";
}

}  // namespace luz::app
