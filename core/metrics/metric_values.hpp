#pragma once
// The numbers of one evaluation (a run's metrics.json, evaluate()'s JSON) as
// "<scope>/<metric>" -> value: "all/pcf_mse", "class 1/wasserstein", "classes 0-1/pcf_mse",
// "all/border_density_0.5%", "all/l_sup", "class 0/verdict_p", "all/verdict_pass" (1 pass,
// 0 fail), "all/verdict_cannot_judge" (1 for a row that cannot judge: never a pass),
// "all/novelty_share", "all/copy" (1 flagged a copy, 0 not), "all/periodicity_ratio",
// "all/periodic" (1 flagged periodic, 0 not), "class 1/close_pair_share",
// "classes 0-1/min_distance_normalized", "class 0/fidelity_l_spreads", "all/fidelity_g_spreads",
// "classes 0-1/fidelity_within" (1 within band, 0 out), "all/fidelity_kmm_mark_spreads" (a mark
// row, by attribute) (the scorecard). What gather pools over seeds. A metrics.json that is not the evaluation's layout (edited, truncated, crafted) is an InputError naming `source` and the
// key; a metric that is null (undefined for that output) is left out.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

std::vector<std::pair<std::string, double>> metric_values(const nlohmann::json& metrics, const std::string& source);

}  // namespace ppsynth
