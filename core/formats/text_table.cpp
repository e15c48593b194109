#include "core/formats/text_table.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"

namespace ppsynth {

namespace {

// What a path that is not a regular file is: "a character device", "a FIFO (named pipe)", ...
const char* kind_of(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

InputError not_regular(const std::string& path, mode_t mode, const std::string& what) {
  if (S_ISDIR(mode)) return file_error(path, 0, "is a directory, not a " + what);
  return file_error(path, 0, std::string("is ") + kind_of(mode) + ", not a regular file; name a " + what + " to read");
}

InputError too_large(const std::string& path) {
  return file_error(path, 0, "larger than the " + std::to_string(kMaxInputFileBytes >> 30) +
                                 " GiB an input file may hold; name the file you meant");
}

// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void check_input_file(const std::string& path, const std::string& what) {
  // stat, never open: opening a FIFO for reading waits for a writer, forever.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw_open_error(path, what);
  if (!S_ISREG(st.st_mode)) throw not_regular(path, st.st_mode, what);
  if (static_cast<unsigned long long>(st.st_size) > kMaxInputFileBytes) throw too_large(path);
}

std::string read_file_text(const std::string& path, const std::string& what) {
  check_input_file(path, what);
  // O_NONBLOCK: should the path become a FIFO between stat and open, the open returns at once
  // and fstat refuses it; on a regular file the flag changes nothing.
  Fd in{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (in.fd < 0) throw_open_error(path, what);
  struct stat st {};
  if (::fstat(in.fd, &st) != 0) throw file_error(path, 0, "read error");
  if (!S_ISREG(st.st_mode)) throw not_regular(path, st.st_mode, what);
  std::string text;
  text.reserve(static_cast<size_t>(st.st_size));
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(in.fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw file_error(path, 0, "read error");
    }
    if (text.size() + static_cast<size_t>(n) > kMaxInputFileBytes) throw too_large(path);  // grew while read
    text.append(buf, static_cast<size_t>(n));
  }
  return text;
}

bool strip_utf8_bom(std::string& text) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") != 0) return false;
  text.erase(0, 3);
  return true;
}

std::vector<TextRow> split_rows(const std::string& text, size_t max_rows) {
  std::vector<TextRow> rows;
  std::string raw;
  long n = 0;
  for (size_t pos = 0; rows.size() < max_rows && pos < text.size();) {  // as std::getline
    const size_t eol = std::min(text.find('\n', pos), text.size());
    raw.assign(text, pos, eol - pos);
    pos = eol + 1;
    ++n;
    const auto b = raw.find_first_not_of(" \t\r\f\v");
    if (b == std::string::npos) continue;
    const auto e = raw.find_last_not_of(" \t\r\f\v");
    TextRow r;
    r.line = n;
    r.text = raw.substr(b, e - b + 1);
    std::istringstream f(r.text);
    for (std::string tok; f >> tok;) r.fields.push_back(tok);
    rows.push_back(std::move(r));
  }
  return rows;
}

double parse_real_field(const std::string& field, const std::string& source, long line) {
  double v = 0;
  const char* b = field.data();
  const char* e = b + field.size();
  if (b != e && *b == '+') ++b;  // from_chars rejects a leading '+'
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range)
    throw file_error(source, line, "number '" + field + "' is out of range");
  if (ec != std::errc() || p != e) throw file_error(source, line, "'" + field + "' is not a number");
  if (!std::isfinite(v)) throw file_error(source, line, "'" + field + "' is not a finite number");
  return v;
}

long long parse_integer_field(const std::string& field, const std::string& source, long line) {
  long long v = 0;
  const char* b = field.data();
  const char* e = b + field.size();
  if (b != e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range)
    throw file_error(source, line, "integer '" + field + "' is out of range");
  if (ec != std::errc() || p != e) {
    // Say "not a finite number" for nan/inf so the message is the same in every format.
    double d = 0;
    auto [q, ec2] = std::from_chars(b, e, d);
    if (ec2 == std::errc() && q == e && !std::isfinite(d))
      throw file_error(source, line, "'" + field + "' is not a finite number");
    throw file_error(source, line, "'" + field + "' is not an integer");
  }
  return v;
}

long long parse_integral_real_field(const std::string& field, const std::string& source, long line) {
  const double v = parse_real_field(field, source, line);
  if (v != std::floor(v) || std::abs(v) > 9.0e15)
    throw file_error(source, line, "'" + field + "' is not an integer category id");
  return static_cast<long long>(v);
}

int checked_int(long long value, const std::string& what, const std::string& source, long line) {
  constexpr long long lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
  if (value < lo || value > hi)
    throw file_error(source, line, what + " " + std::to_string(value) + " is out of range (it must lie in " +
                                       std::to_string(lo) + ".." + std::to_string(hi) + ")");
  return static_cast<int>(value);
}

std::string format_real(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

PointSet point_set_with_attributes(const Domain& domain, const std::vector<std::string>& names,
                                   const std::string& source, long line) {
  PointSet ps(domain);
  for (const auto& n : names) {
    try {
      ps.add_attribute(n);
    } catch (const std::invalid_argument& e) {
      throw file_error(source, line, e.what());
    }
  }
  return ps;
}

}  // namespace ppsynth
