// The registry: the catalogue's models and those registered, and lookups over them.
#include "app/common/model_registry.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "app/common/i18n.h"

namespace luz::app {
namespace {

std::vector<ModelEntry>& registered() {
  static std::vector<ModelEntry> list;
  return list;
}

bool listed = false;  // models() has made its list: a registration now would come too late

[[noreturn]] void programmer_error(const std::string& what) {
  std::fprintf(stderr, "luz: %s\n", what.c_str());
  std::abort();
}

}  // namespace

ModelRegistration::ModelRegistration(const ModelEntry& entry) {
  if (listed) programmer_error(std::string("model ") + entry.name + " registered after the models were listed");
  registered().push_back(entry);
}

std::span<const ModelEntry> models() {
  static const std::vector<ModelEntry> all = [] {
    listed = true;
    std::vector<ModelEntry> list(catalogue().begin(), catalogue().end());
    for (const ModelEntry& m : registered()) {
      for (const ModelEntry& other : list)
        if (std::string_view(m.name) == other.name || m.key == other.key)
          programmer_error(std::string("model ") + m.name + ": its name or key is " + other.name + "'s");
      list.push_back(m);
    }
    return list;
  }();
  return all;
}

std::vector<const OptionTable*> option_tables() {
  std::vector<const OptionTable*> tables;
  for (const ModelEntry& m : models())
    for (OptionTableOf table_of : m.options)
      if (std::find(tables.begin(), tables.end(), &table_of()) == tables.end()) tables.push_back(&table_of());
  return tables;
}

std::optional<FoundOption> find_option(std::string_view name) {
  const size_t dot = name.find('.');
  const std::string_view table_name = dot == std::string_view::npos ? "" : name.substr(0, dot);
  const std::string_view row_name = dot == std::string_view::npos ? name : name.substr(dot + 1);
  for (const OptionTable* table : option_tables()) {
    if (!table_name.empty() && table_name != table->name) continue;
    if (const OptionRow* row = find_row(*table, row_name)) return FoundOption{table, row};
  }
  return std::nullopt;
}

const ModelEntry* find_model(std::string_view name) {
  for (const ModelEntry& m : models())
    if (name == m.name) return &m;
  return nullptr;
}

std::string model_label(const std::string& name) {
  const ModelEntry* m = find_model(name);
  return m ? std::string(tr(m->label)) : name;
}

std::string model_labels(const std::string& names) {
  std::string labels;
  size_t start = 0;
  while (start <= names.size()) {
    const size_t comma = std::min(names.find(',', start), names.size());
    if (!labels.empty()) labels += ", ";
    labels += model_label(names.substr(start, comma - start));
    start = comma + 1;
  }
  return labels;
}

const ModelEntry* model_on_key(int digit) {
  for (const ModelEntry& m : models())
    if (m.key == digit) return &m;
  return nullptr;
}

std::string models_accepting(std::string_view group) {
  std::vector<std::string> names;
  for (const ModelEntry& m : models())
    for (const char* g : m.flag_groups)
      if (group == g) names.push_back(m.name);
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    // TRANSLATORS: joins the last two names of a list of models: "flat, gouraud or phong".
    text += (i == 0 ? "" : i + 1 == names.size() ? tr(" or ") : ", ") + names[i];
  return text;
}

std::string model_names(const char* separator) {
  std::string text;
  for (const ModelEntry& m : models()) text += (text.empty() ? "" : separator) + std::string(m.name);
  return text;
}

}  // namespace luz::app
