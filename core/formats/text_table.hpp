#pragma once
// Line-oriented parsing shared by the text formats: split a file into numbered,
// whitespace-separated rows and parse fields strictly, so every error can name "file:line".
#include <string>
#include <vector>

namespace ppsynth {

// One non-blank line of a text file: its 1-based line number, its text (trailing CR and
// surrounding whitespace removed) and its whitespace-separated fields.
struct TextRow {
  long line = 0;
  std::string text;
  std::vector<std::string> fields;
  bool is_comment() const { return !text.empty() && text[0] == '#'; }
};

// The whole file as a string; InputError "path: cannot open" when it cannot be read.
std::string read_file_text(const std::string& path);

// Non-blank lines of `text`, numbered from 1 (blank lines are skipped but counted).
std::vector<TextRow> split_rows(const std::string& text);

// Strict field parsers: the whole field must be a number. Non-numeric text, NaN and
// infinities throw file_error(source, line, ...) naming the field.
double parse_real_field(const std::string& field, const std::string& source, long line);
long long parse_integer_field(const std::string& field, const std::string& source, long line);
// A real that must hold an integer value (e.g. "3" or "3.0"); Point-Synthesis categories.
long long parse_integral_real_field(const std::string& field, const std::string& source, long line);

// Shortest-safe text for a double that reads back to the same bits ("%.17g").
std::string format_real(double v);

}  // namespace ppsynth
