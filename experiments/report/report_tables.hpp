#pragma once
// The tables of a reproduction report, each also written as <name>.csv and <name>.md:
//   metrics          (always) one row per panel x method column: points, PCF MSE, Wasserstein,
//                    Chamfer (4-quadrant protocol, method.md §6), relative radius, overlapping
//                    disk pairs, iterations, wall time
//   comparison       paper Table 2: per panel, the three metrics for every method column,
//                    plus a "(paper)" row from the panel's "paper" numbers
//   relative_radius  paper Table 1: rho of the exemplar and of every method's output, plus the
//                    table's "paper" row
//   runtime          paper Table 3: classes, points, attributes, iterations, wall time and s/iteration of
//                    "ours" per panel, beside the panel's published numbers
// Published numbers whose column we do not have (e.g. methods we did not implement) become
// extra columns: nothing in a config's "paper" object is dropped. Numbers are printed with 4
// significant decimals; a cell we cannot fill is "n/a".
#include <string>
#include <vector>

#include "experiments/plan/reproduce_config.hpp"
#include "experiments/report/reproduce_results.hpp"

namespace ppsynth {

struct ReportTable {
  std::string name, caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

ReportTable metrics_table(const ReproduceConfig& c, const ReproduceResult& r);
// One of the config's "tables" (comparison | relative_radius | runtime).
ReportTable build_table(const TableSpec& t, const ReproduceConfig& c, const ReproduceResult& r);

// <dir>/<name>.csv and <dir>/<name>.md (atomic).
void write_table_files(const ReportTable& t, const std::string& dir);

// "0.1235" / "n/a" for non-numbers; JSON strings are printed as they are.
std::string format_cell(const nlohmann::json& v, int decimals = 4);

}  // namespace ppsynth
