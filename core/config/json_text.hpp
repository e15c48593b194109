#pragma once
// Parsing JSON a user wrote (configs, JSON point files, --set values) so that every flaw is
// an InputError naming the file and line, and nothing crashes:
//   - a UTF-8 byte-order mark at the start is skipped;
//   - nesting deeper than kMaxJsonDepth is refused before nlohmann::json sees the text: its
//     parser is iterative, but copying, merging, comparing and dumping a value recurse once
//     per level (a config nested 10^6 levels deep overflowed the stack);
//   - a number beyond the range of a double ("1e400") is refused with its line (nlohmann
//     throws out_of_range 406 for it, without a position);
//   - syntax errors name the line; any other nlohmann exception becomes an InputError.
#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// Deepest nesting of arrays and objects accepted (a config uses fewer than 10 levels).
inline constexpr int kMaxJsonDepth = 200;

struct JsonTextFlaw {
  size_t offset = 0;    // byte offset in the text
  std::string message;  // what is wrong, e.g. "number '1e400' is beyond the range of a double"
};

// The first nesting or number flaw of `text`, skipping strings and, when `allow_comments`,
// comments ("//..." and "/*...*/") as nlohmann::json does. Syntax is left to the parser.
std::optional<JsonTextFlaw> find_json_text_flaw(const std::string& text, bool allow_comments);

// 1-based line of byte `offset` of `text`.
long line_of_offset(const std::string& text, size_t offset);

// Parses `text` read from `source`: skips a byte-order mark, refuses the flaws above and
// syntax errors with file_error(source, line, ...).
nlohmann::json parse_json_text(std::string text, const std::string& source, bool allow_comments);

// Whether `text` is valid UTF-8, as json::dump requires of every string (it throws
// type_error 316 otherwise).
bool is_utf8(const std::string& text);

// `text` as a JSON string whose bytes that are not UTF-8 (a file name may hold any) are each
// replaced by U+FFFD, as nlohmann's replace handler does, so that a report that names the file
// can always be written. Only where the name is shown: a name read back (a run's config)
// must be refused instead, with first_non_utf8.
nlohmann::json shown_text(const std::string& text);

// The key path ("exemplar", "method.init.file", "runs[2]") of the first string or key of
// `value` that is not UTF-8; nullopt when there is none.
std::optional<std::string> first_non_utf8(const nlohmann::json& value, const std::string& path = "");

}  // namespace ppsynth
