#include "core/config/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "core/plain_message.hpp"

namespace ppsynth {

namespace {

bool number_char(char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'; }

std::string shortened(const std::string& token) {
  return token.size() <= 40 ? token : token.substr(0, 20) + "..." + token.substr(token.size() - 10);
}

}  // namespace

long line_of_offset(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
}

std::optional<JsonTextFlaw> find_json_text_flaw(const std::string& text, bool allow_comments) {
  int depth = 0;
  const size_t n = text.size();
  for (size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '"') {  // skip the string (an unterminated one is the parser's to report)
      for (++i; i < n && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      continue;
    }
    if (allow_comments && c == '/' && i + 1 < n && (text[i + 1] == '/' || text[i + 1] == '*')) {
      if (text[i + 1] == '/') {
        while (i < n && text[i] != '\n') ++i;
      } else {
        const auto end = text.find("*/", i + 2);
        if (end == std::string::npos) return std::nullopt;  // the parser reports it
        i = end + 1;
      }
      continue;
    }
    if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        return JsonTextFlaw{i, "arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"};
    } else if (c == ']' || c == '}') {
      depth = std::max(depth - 1, 0);
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      size_t e = i;
      while (e < n && number_char(text[e])) ++e;
      const std::string token = text.substr(i, e - i);
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end == token.c_str() + token.size() && std::isinf(v))
        return JsonTextFlaw{i, "number '" + shortened(token) + "' is beyond the range of a double"};
      i = e - 1;
    }
  }
  return std::nullopt;
}

nlohmann::json parse_json_text(std::string text, const std::string& source, bool allow_comments) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // UTF-8 byte-order mark
  if (const auto flaw = find_json_text_flaw(text, allow_comments))
    throw file_error(source, line_of_offset(text, flaw->offset), flaw->message);
  try {
    return nlohmann::json::parse(text, nullptr, true, allow_comments);
  } catch (const nlohmann::json::parse_error& e) {
    throw file_error(source, line_of_offset(text, e.byte > 0 ? e.byte - 1 : 0),
                     "invalid JSON: " + plain_message(e.what()));
  } catch (const nlohmann::json::exception& e) {  // out_of_range 406 and the like
    throw file_error(source, 0, "invalid JSON: " + plain_message(e.what()));
  }
}

bool is_utf8(const std::string& text) {
  try {
    (void)nlohmann::json(text).dump();  // nlohmann's own decoder: the one json::dump applies
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

nlohmann::json shown_text(const std::string& text) {
  if (is_utf8(text)) return text;
  const std::string quoted = nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(quoted);
}

std::optional<std::string> first_non_utf8(const nlohmann::json& value, const std::string& path) {
  if (value.is_string()) return is_utf8(value.get_ref<const std::string&>()) ? std::nullopt : std::optional(path);
  if (value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i)
      if (auto p = first_non_utf8(value[i], path + "[" + std::to_string(i) + "]")) return p;
  } else if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) {
      const std::string key = path.empty() ? it.key() : path + "." + it.key();
      if (!is_utf8(it.key())) return key;
      if (auto p = first_non_utf8(it.value(), key)) return p;
    }
  }
  return std::nullopt;
}

}  // namespace ppsynth
