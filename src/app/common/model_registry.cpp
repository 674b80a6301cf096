// Lookups over the registry's table (models(), models/model_catalogue.cpp).
#include "app/common/model_registry.h"

#include "app/common/i18n.h"

namespace luz::app {

const ModelEntry* find_model(std::string_view name) {
  for (const ModelEntry& m : models())
    if (name == m.name) return &m;
  return nullptr;
}

std::string model_label(const std::string& name) {
  const ModelEntry* m = find_model(name);
  return m ? std::string(tr(m->label)) : name;
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
