#pragma once
// The options structs of the tables a program takes, one of each, made from the table's defaults
// the first time a table is asked for. `luz render`'s settings and the viewer's state each hold
// one: a flag, a `set` line and a lesson's step write a row's field in it, and the model that
// owns the table reads its struct from it. Copies are deep (a sheet's panes each get their own).
// A struct stays where it was made while its OptionValues lives and is not assigned to, so a
// view may keep a reference to its own (the path tracer's does).
#include <cassert>
#include <memory>
#include <utility>
#include <vector>

#include "app/common/option_row.h"

namespace luz::app {

class OptionValues {
public:
  enum class Start { render, viewer };  // the viewer's start may differ (OptionTable::in_viewer)
  explicit OptionValues(Start start = Start::render) : start_(start) {}
  OptionValues(const OptionValues& other);
  OptionValues& operator=(const OptionValues& other);
  OptionValues(OptionValues&&) = default;
  OptionValues& operator=(OptionValues&&) = default;

  void* of(const OptionTable& table) { return made(table); }
  const void* of(const OptionTable& table) const { return made(table); }

  template <class Options>
  Options& get(const OptionTable& table) {
    assert(*table.type == typeid(Options));
    return *static_cast<Options*>(of(table));
  }
  template <class Options>
  const Options& get(const OptionTable& table) const {
    assert(*table.type == typeid(Options));
    return *static_cast<const Options*>(of(table));
  }

private:
  void* made(const OptionTable& table) const;

  Start start_;
  // Made on first use, reading too: a table's struct is there from the first look on.
  mutable std::vector<std::pair<const OptionTable*, std::shared_ptr<void>>> values_;
};

}  // namespace luz::app
