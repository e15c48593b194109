#pragma once
// One page over a folder of reproduction reports (scripts/reproduce_all.sh's OUT, one report
// per paper item in OUT/NAME): OUT/index.html and OUT/index.md. First a table of every item
// with its verdict by rule, then per item the paper's claim, the rule and its checks with the
// numbers that decided them, our numbers (median [min - max] over the seeds) beside the
// published code's output where the item's exemplar has one, the paper's own numbers, and the
// report's overview picture (linked, the reports stay beside the page). Everything comes from
// each report's report.json; the page writes nothing else and replaces only a page of its own.
#include <cstddef>
#include <string>

namespace ppsynth {

// Returns the number of reports on the page; InputError when DIR holds none, or when
// DIR/index.html exists and is not such a page.
size_t write_reproduce_page(const std::string& dir);

}  // namespace ppsynth
