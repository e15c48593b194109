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

// The most an input file may hold (2 GiB, about 50 million points of text): past it the file
// is not one a user meant to give (a sparse image, a log still growing), and reading it whole
// would take the machine's memory first.
inline constexpr unsigned long long kMaxInputFileBytes = 2ull << 30;

// The whole regular file `path` as a string, byte for byte: the one way every point file,
// config and run record is read. It is looked at before it is opened, so a FIFO never blocks
// and a device is never read: InputError "path: is a directory, not a file", "path: is a
// character device, not a regular file" (block device, FIFO, socket likewise), MissingFileError
// "path: no such file", "path: cannot open WHAT (unreadable)" (`what`: "file", "config file"); and
// "path: larger than the 2 GiB an input file may hold" for a file past kMaxInputFileBytes, or
// one that grows past it while it is read.
std::string read_file_text(const std::string& path, const std::string& what = "file");
// The checks read_file_text makes before it opens `path`, with the same errors: for a reader
// of its own (the Python package's NumPy files).
void check_input_file(const std::string& path, const std::string& what = "file");

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
