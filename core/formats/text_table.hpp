#pragma once
// Line-oriented parsing shared by the text formats: split a file into numbered,
// whitespace-separated rows and parse fields strictly, so every error can name "file:line".
#include <string>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

// One non-blank line of a text file: its 1-based line number, its text (trailing CR and
// surrounding whitespace removed) and its whitespace-separated fields.
struct TextRow {
  long line = 0;
  std::string text;
  std::vector<std::string> fields;
  bool is_comment() const { return !text.empty() && text[0] == '#'; }
};

// The whole file as a string, byte for byte; InputError "path: cannot open" when it cannot
// be read, "path: is a directory" for a directory.
std::string read_file_text(const std::string& path);

// Removes a UTF-8 byte-order mark (EF BB BF) at the start of `text`; true when there was one.
// Point and config readers accept one (editors on Windows write it); elsewhere it is a flaw.
bool strip_utf8_bom(std::string& text);

// Non-blank lines of `text`, numbered from 1 (blank lines are skipped but counted); at most
// `max_rows` of them (detection looks at the first lines only).
std::vector<TextRow> split_rows(const std::string& text, size_t max_rows = static_cast<size_t>(-1));

// Strict field parsers: the whole field must be a number. Non-numeric text, NaN and
// infinities throw file_error(source, line, ...) naming the field.
double parse_real_field(const std::string& field, const std::string& source, long line);
long long parse_integer_field(const std::string& field, const std::string& source, long line);
// A real that must hold an integer value (e.g. "3" or "3.0"); Point-Synthesis categories.
long long parse_integral_real_field(const std::string& field, const std::string& source, long line);

// `value` as the int a PointSet stores for a class label or id; values beyond 32 bits throw
// file_error(source, line, "<what> <value> is out of range ...") instead of being truncated.
int checked_int(long long value, const std::string& what, const std::string& source, long line);

// An empty point set on `domain` with these attribute columns, in order; a name given twice
// (by the file or by ReadOptions::attribute_names) throws file_error(source, line, ...).
PointSet point_set_with_attributes(const Domain& domain, const std::vector<std::string>& names,
                                   const std::string& source, long line);

// Shortest-safe text for a double that reads back to the same bits ("%.17g").
std::string format_real(double v);

}  // namespace ppsynth
