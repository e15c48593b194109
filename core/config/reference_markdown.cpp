#include "core/config/reference_markdown.hpp"

#include <sstream>

#include "core/config/param_docs.hpp"

namespace ppsynth {

namespace {

// A table cell: the value as compact JSON, pipes escaped so that the table keeps its columns.
std::string cell(const nlohmann::json& v) {
  std::string s = v.dump();
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return "`" + out + "`";
}

// One row per leaf key, dotted; a component spec ({"type": ...}) is one value, since its keys
// belong to the part its "type" names (documented under that kind). `docs` (nested like the
// defaults) gives a fourth column, when the part declares its keys' lines
// (core/config/param_docs.hpp).
void rows(const nlohmann::json& defaults, const nlohmann::json& bounds, const nlohmann::json* docs, const std::string& prefix,
          std::ostringstream& out) {
  for (auto it = defaults.begin(); it != defaults.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    const nlohmann::json* b = bounds.is_object() && bounds.contains(it.key()) ? &bounds[it.key()] : nullptr;
    const nlohmann::json* d = docs && docs->is_object() && docs->contains(it.key()) ? &(*docs)[it.key()] : nullptr;
    if (it->is_object() && !it->empty() && !it->contains("type")) {
      const nlohmann::json none = nlohmann::json::object();
      rows(*it, b ? *b : nlohmann::json::object(), docs ? (d ? d : &none) : nullptr, key, out);
      continue;
    }
    out << "| `" << key << "` | " << cell(*it) << " | " << (b && b->is_string() ? "`" + b->get<std::string>() + "`" : "")
        << " |";
    if (docs) {
      const std::string line = d && d->is_string() ? d->get<std::string>() : "";
      std::string escaped;
      for (char c : line) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
      out << " " << escaped << " |";
    }
    out << "\n";
  }
}

}  // namespace

std::string config_reference_markdown(const nlohmann::json& catalog) {
  std::ostringstream out;
  for (auto kind = catalog.begin(); kind != catalog.end(); ++kind) {
    out << "### " << kind.key() << "\n\n";
    for (auto part = kind->begin(); part != kind->end(); ++part) {
      const nlohmann::json& p = *part;
      out << "#### `" << kind.key() << "` " << part.key() << "\n\n";
      if (p.contains("description") && p["description"].is_string() && !p["description"].get<std::string>().empty())
        out << p["description"].get<std::string>() << "\n\n";
      if (p.contains("defaults") && p["defaults"].is_object()) {
        if (p["defaults"].empty()) {
          out << "No parameters.\n\n";
          continue;
        }
        const nlohmann::json docs = param_docs(kind.key(), part.key());
        out << (docs.empty() ? "| key | default | bound |\n| --- | --- | --- |\n"
                             : "| key | default | bound | what |\n| --- | --- | --- | --- |\n");
        rows(p["defaults"], p.value("bounds", nlohmann::json::object()), docs.empty() ? nullptr : &docs, "", out);
        out << "\n";
      } else {  // a config fragment (a preset): shown as it is merged
        nlohmann::json shown = p;
        shown.erase("description");
        out << "```json\n" << shown.dump(2) << "\n```\n\n";
      }
    }
  }
  return out.str();
}

}  // namespace ppsynth
