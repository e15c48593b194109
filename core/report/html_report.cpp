#include "core/report/html_report.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace ppsynth {
namespace {

const char* kCss = R"css(
:root { color-scheme: light; }
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
       max-width: 1100px; margin: 2rem auto; padding: 0 1.2rem; color: #222; line-height: 1.5; background: #fff; }
h1 { font-size: 1.7rem; border-bottom: 2px solid #1f77b4; padding-bottom: .3rem; }
h2 { font-size: 1.35rem; margin-top: 2.2rem; border-bottom: 1px solid #ddd; padding-bottom: .2rem; }
h3, h4, h5, h6 { margin-top: 1.6rem; }
figure { margin: 1.2rem 0; display: inline-block; vertical-align: top; max-width: 100%; }
figure img { max-width: 100%; height: auto; border: 1px solid #e3e3e3; }
figcaption { font-size: .9rem; color: #555; margin-top: .3rem; }
.row { display: flex; flex-wrap: wrap; gap: 1rem; align-items: flex-start; }
.row figure { flex: 1 1 250px; margin: .5rem 0; }
table { border-collapse: collapse; margin: 1rem 0; font-size: .92rem; font-variant-numeric: tabular-nums; }
th, td { border: 1px solid #ddd; padding: .3rem .65rem; text-align: left; }
th { background: #f2f4f7; font-weight: 600; }
tbody tr:nth-child(even) { background: #fafbfc; }
table caption { caption-side: top; text-align: left; font-size: .9rem; color: #555; padding-bottom: .3rem; }
table.kv th { background: none; font-weight: 600; color: #444; }
details { margin: 1rem 0; border: 1px solid #e3e3e3; border-radius: 4px; padding: .4rem .8rem; }
summary { cursor: pointer; font-weight: 600; }
pre { background: #f6f8fa; padding: .8rem; overflow-x: auto; font-size: .85rem; }
code, pre { font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; }
)css";

std::string read_binary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw file_error(path, 0, "cannot read image for the report");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string mime_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  if (ext == ".gif") return "image/gif";
  throw file_error(path, 0, "cannot embed image with extension '" + ext + "' (use .png, .svg, .jpg or .gif)");
}

// Width / height of a PNG from its IHDR chunk (bytes 16..23, big-endian); 0 when unknown.
double png_aspect(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return 0;
  auto be32 = [&](size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  const uint32_t w = be32(16), h = be32(20);
  return w > 0 && h > 0 ? static_cast<double>(w) / h : 0;
}

// In a row, a figure's share of the width follows its aspect (flex grow and basis
// proportional to width / height), so the figures of a row end up equally tall: a 4 x 1
// strip beside a square gets 4 times its width instead of being shrunk to a sliver.
std::string figure(const std::string& path, const std::string& caption, int width_px, bool in_row = false) {
  const std::string bytes = read_binary(path);
  const std::string uri = "data:" + mime_for(path) + ";base64," + base64_encode(bytes);
  std::string f = "<figure";
  if (const double aspect = in_row ? png_aspect(bytes) : 0; aspect > 0) {
    char style[96];
    std::snprintf(style, sizeof style, " style=\"flex: %.3f 1 %.0fpx\"", aspect, 250 * aspect);
    f += style;
  }
  f += "><img src=\"" + uri + "\" alt=\"" + html_escape(caption) + "\"";
  if (width_px > 0) f += " width=\"" + std::to_string(width_px) + "\"";
  f += ">";
  if (!caption.empty()) f += "<figcaption>" + html_escape(caption) + "</figcaption>";
  return f + "</figure>\n";
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string md_cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "\\|";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out;
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64_encode(const std::string& bytes) {
  static const char* tbl = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += tbl[(v >> 18) & 63], out += tbl[(v >> 12) & 63], out += tbl[(v >> 6) & 63], out += tbl[v & 63];
  }
  const size_t rest = bytes.size() - i;
  if (rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += tbl[(v >> 18) & 63], out += tbl[(v >> 12) & 63];
    out += rest == 2 ? tbl[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {
  if (!title_.empty()) body_ += "<h1>" + html_escape(title_) + "</h1>\n";
}

void HtmlReport::add_heading(const std::string& text, int level) {
  const std::string h = "h" + std::to_string(std::clamp(level, 1, 6));
  body_ += "<" + h + ">" + html_escape(text) + "</" + h + ">\n";
}

void HtmlReport::add_paragraph(const std::string& text) { body_ += "<p>" + html_escape(text) + "</p>\n"; }

void HtmlReport::add_html(const std::string& raw) { body_ += raw + "\n"; }

void HtmlReport::add_image(const std::string& png_path, const std::string& caption, int width_px) {
  body_ += "<div>" + figure(png_path, caption, width_px) + "</div>\n";
}

void HtmlReport::add_image_row(const std::vector<std::pair<std::string, std::string>>& images_captions) {
  std::string row = "<div class=\"row\">\n";
  for (const auto& [path, caption] : images_captions) row += figure(path, caption, 0, true);
  body_ += row + "</div>\n";
}

void HtmlReport::add_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                           const std::string& caption) {
  std::string t = "<table>\n";
  if (!caption.empty()) t += "<caption>" + html_escape(caption) + "</caption>\n";
  if (!header.empty()) {
    t += "<thead><tr>";
    for (const auto& h : header) t += "<th>" + html_escape(h) + "</th>";
    t += "</tr></thead>\n";
  }
  t += "<tbody>\n";
  for (const auto& r : rows) {
    t += "<tr>";
    for (const auto& c : r) t += "<td>" + html_escape(c) + "</td>";
    t += "</tr>\n";
  }
  body_ += t + "</tbody>\n</table>\n";
}

void HtmlReport::add_code_block(const std::string& text, const std::string& summary) {
  body_ += "<details><summary>" + html_escape(summary) + "</summary>\n<pre><code>" + html_escape(text) +
           "</code></pre></details>\n";
}

void HtmlReport::add_key_values(const std::vector<std::pair<std::string, std::string>>& kv) {
  std::string t = "<table class=\"kv\"><tbody>\n";
  for (const auto& [k, v] : kv) t += "<tr><th>" + html_escape(k) + "</th><td>" + html_escape(v) + "</td></tr>\n";
  body_ += t + "</tbody></table>\n";
}

std::string HtmlReport::html() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         html_escape(title_) + "</title>\n<style>" + kCss + "</style>\n</head>\n<body>\n" + body_ +
         "</body>\n</html>\n";
}

void HtmlReport::write(const std::string& path) const { write_text_atomic(path, html()); }

std::string table_csv(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string out;
  auto line = [&](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + csv_field(cells[i]);
    out += "\n";
  };
  line(header);
  for (const auto& r : rows) line(r);
  return out;
}

void write_table_csv(const std::string& path, const std::vector<std::string>& header,
                     const std::vector<std::vector<std::string>>& rows) {
  write_text_atomic(path, table_csv(header, rows));
}

std::string table_markdown(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string s = "|";
    for (const auto& c : cells) s += " " + md_cell(c) + " |";
    return s + "\n";
  };
  std::string out = line(header) + "|";
  for (size_t i = 0; i < header.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& r : rows) out += line(r);
  return out;
}

}  // namespace ppsynth
