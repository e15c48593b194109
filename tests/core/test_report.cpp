// HTML report: escaping, embedded images, atomic write; CSV and Markdown tables.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/render/plot_points.hpp"
#include "core/report/html_report.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

TEST_CASE("base64 matches RFC 4648 test vectors", "[report]") {
  CHECK(base64_encode("") == "");
  CHECK(base64_encode("f") == "Zg==");
  CHECK(base64_encode("fo") == "Zm8=");
  CHECK(base64_encode("foo") == "Zm9v");
  CHECK(base64_encode("foob") == "Zm9vYg==");
  CHECK(base64_encode("fooba") == "Zm9vYmE=");
  CHECK(base64_encode("foobar") == "Zm9vYmFy");
  CHECK(base64_encode(std::string("\xff\x00\xfe", 3)) == "/wD+");
}

TEST_CASE("HTML report embeds images as data URIs and escapes text", "[report]") {
  const fs::path dir = fs::temp_directory_path() / "ppsynth_test_report";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path png = dir / "pts.png";
  PointSet ps;
  ps.add({0.3, 0.4});
  plot_points(png.string(), ps, PointStyle{}, 120);
  std::ifstream in(png, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();

  HtmlReport r("Run <1> & co");
  r.add_heading("Results \"quoted\"");
  r.add_paragraph("a < b && c > d");
  r.add_image(png.string(), "exemplar <left>");
  r.add_table({"metric", "value"}, {{"pcf<mse>", "0.5"}}, "cap & tion");
  r.add_code_block("{\"k\": <v>}", "config");
  r.add_key_values({{"seed", "42"}});
  r.add_html("<hr class=\"raw\">");
  const fs::path out = dir / "report.html";
  r.write(out.string());
  std::ifstream hin(out);
  std::stringstream hs;
  hs << hin.rdbuf();
  const std::string html = hs.str();
  CHECK(html == r.html());
  CHECK(html.find("<!DOCTYPE html>") == 0);
  CHECK(html.find("<title>Run &lt;1&gt; &amp; co</title>") != std::string::npos);
  CHECK(html.find("<h2>Results &quot;quoted&quot;</h2>") != std::string::npos);
  CHECK(html.find("<p>a &lt; b &amp;&amp; c &gt; d</p>") != std::string::npos);
  CHECK(html.find("src=\"data:image/png;base64," + base64_encode(bytes.str()) + "\"") != std::string::npos);
  CHECK(html.find("<figcaption>exemplar &lt;left&gt;</figcaption>") != std::string::npos);
  CHECK(html.find("<td>pcf&lt;mse&gt;</td>") != std::string::npos);
  CHECK(html.find("<summary>config</summary>") != std::string::npos);
  CHECK(html.find("{&quot;k&quot;: &lt;v&gt;}") != std::string::npos);
  CHECK(html.find("<hr class=\"raw\">") != std::string::npos);
  CHECK(html.find("pts.png") == std::string::npos);  // self-contained: no file reference

  CHECK_THROWS_WITH(r.add_image((dir / "missing.png").string(), ""), Catch::Contains("missing.png"));
  fs::remove_all(dir);
}

TEST_CASE("tables as CSV and Markdown are exact", "[report]") {
  const std::vector<std::string> header{"method", "pcf mse", "note"};
  const std::vector<std::vector<std::string>> rows{{"gabor", "0.012", "ok"}, {"a,b", "say \"hi\"", "x|y"}};
  CHECK(table_csv(header, rows) == "method,pcf mse,note\ngabor,0.012,ok\n\"a,b\",\"say \"\"hi\"\"\",x|y\n");
  CHECK(table_markdown(header, rows) ==
        "| method | pcf mse | note |\n|---|---|---|\n| gabor | 0.012 | ok |\n| a,b | say \"hi\" | x\\|y |\n");
  const fs::path p = fs::temp_directory_path() / "ppsynth_test_table.csv";
  write_table_csv(p.string(), header, rows);
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str() == table_csv(header, rows));
  fs::remove(p);
}

TEST_CASE("a row of figures gives each a width share by its aspect (a 4 x 1 strip beside a square)", "[report]") {
  const fs::path dir = fs::temp_directory_path() / "ppsynth_test_report_rect";
  fs::remove_all(dir);
  fs::create_directories(dir);
  PointSet square, strip(Domain{0, 0, 4, 1});
  square.add({0.3, 0.4});
  strip.add({2.5, 0.4});
  plot_points((dir / "square.png").string(), square, PointStyle{}, 300);
  plot_points((dir / "strip.png").string(), strip, PointStyle{}, 300);
  HtmlReport r("rect");
  r.add_image_row({{(dir / "square.png").string(), "square"}, {(dir / "strip.png").string(), "strip"}});
  const std::string html = r.html();
  // flex: <grow = width / height> 1 <basis> for each figure, in order.
  const size_t a = html.find("<figure style=\"flex: "), b = html.find("<figure style=\"flex: ", a + 1);
  REQUIRE(a != std::string::npos);
  REQUIRE(b != std::string::npos);
  const double grow_square = std::stod(html.substr(a + 21)), grow_strip = std::stod(html.substr(b + 21));
  CHECK(grow_square == Approx(1.0).epsilon(0.2));
  CHECK(grow_strip > 2.5 * grow_square);
  // A single image keeps its plain figure.
  HtmlReport one("one");
  one.add_image((dir / "strip.png").string(), "strip");
  CHECK(one.html().find("<figure style=") == std::string::npos);
  fs::remove_all(dir);
}
