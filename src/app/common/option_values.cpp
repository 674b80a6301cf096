#include "app/common/option_values.h"

#include <algorithm>

namespace luz::app {

OptionValues::OptionValues(const OptionValues& other) : start_(other.start_) {
  for (const auto& [table, options] : other.values_) values_.emplace_back(table, table->copy(options.get()));
}

OptionValues& OptionValues::operator=(const OptionValues& other) {
  if (this != &other) *this = OptionValues(other);
  return *this;
}

void* OptionValues::made(const OptionTable& table) const {
  const auto found = std::find_if(values_.begin(), values_.end(), [&](const auto& v) { return v.first == &table; });
  if (found != values_.end()) return found->second.get();
  std::shared_ptr<void> made = table.copy(table.defaults());
  if (start_ == Start::viewer && table.in_viewer) table.in_viewer(made.get());
  values_.emplace_back(&table, made);
  return made.get();
}

}  // namespace luz::app
