#pragma once
// Self-contained HTML reports: one file with inline CSS and images embedded as base64
// data URIs, so a report can be mailed, archived or cited without its folder.
// Text passed to add_heading/add_paragraph/add_table/... is HTML-escaped; add_html is the
// only raw entry point. write() is atomic (core/atomic_file.hpp).
// Tables can also be written as CSV (RFC 4180 quoting) or rendered as Markdown.
#include <string>
#include <utility>
#include <vector>

namespace ppsynth {

class HtmlReport {
 public:
  explicit HtmlReport(std::string title);

  void add_heading(const std::string& text, int level = 2);  // level clamped to 1..6
  void add_paragraph(const std::string& text);               // escaped
  void add_html(const std::string& raw);                     // inserted verbatim
  // Embeds the image file (png/svg/jpg/gif by extension) as a data URI. A missing file is
  // an InputError naming it. width_px = 0 keeps the natural width (capped by the layout).
  void add_image(const std::string& png_path, const std::string& caption, int width_px = 0);
  // Several figures in one row (wrapping on narrow screens).
  void add_image_row(const std::vector<std::pair<std::string, std::string>>& images_captions);
  void add_table(const std::vector<std::string>& header,
                 const std::vector<std::vector<std::string>>& rows,
                 const std::string& caption = "");
  // Preformatted text in a collapsible <details> block titled `summary` (configs, logs).
  void add_code_block(const std::string& text, const std::string& summary);
  // A two-column definition table (run metadata: revision, seed, config path...).
  void add_key_values(const std::vector<std::pair<std::string, std::string>>& kv);

  std::string html() const;                // the complete document
  void write(const std::string& path) const;  // atomic

 private:
  std::string title_;
  std::string body_;
};

// &, <, >, ", ' -> entities.
std::string html_escape(const std::string& text);
// Standard base64 (RFC 4648, with '=' padding).
std::string base64_encode(const std::string& bytes);

// CSV with a header line; fields containing , " or newlines are quoted ("" for quotes).
// Lines end with "\n". Atomic write.
std::string table_csv(const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows);
void write_table_csv(const std::string& path, const std::vector<std::string>& header,
                     const std::vector<std::vector<std::string>>& rows);
// GitHub-flavored Markdown table: "| a | b |\n|---|---|\n| 1 | 2 |\n"; '|' in cells is
// escaped as "\|", newlines become spaces.
std::string table_markdown(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows);

}  // namespace ppsynth
