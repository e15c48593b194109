#pragma once
// evaluate()'s result (evaluation.hpp) as the table `ppsynth eval` prints, section by section:
// the two patterns' summaries (counts, spacing, the border band), the metrics per row under
// the protocol (quadrants or crops), disk overlaps, the field's second-order summaries
// (second_order_report.hpp), the scorecard (novelty.hpp, close_pairs.hpp) and the verdict
// (verdict.hpp). A section whose key the result lacks is left out.
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

std::string format_evaluation(const nlohmann::json& result);

}  // namespace ppsynth
