#include "core/metrics/evaluation_text.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/metrics/class_match.hpp"
#include "core/metrics/eval_protocol.hpp"
#include "core/metrics/verdict.hpp"

namespace ppsynth {

using json = nlohmann::json;

namespace {

// Why the note: on lemon_4c_v2 (classes of 3-13 points) the exemplar itself, tiled at random
// offsets, scores worse per class than a Poisson-disk pattern (docs/lab/method_measurements.md,
// "What the per-class criterion measures"); 64-point classes are judged reliably.
constexpr size_t kFewPoints = 16;

// A number as `fmt` prints it; "-" for a missing one (a metric that could not be computed).
std::string cell(const json& v, const char* fmt = "%.4f") {
  if (!v.is_number()) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v.get<double>());
  return buf;
}

// printf into a line of the table.
template <class... Args>
std::string line(const char* fmt, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

std::string row_name(const json& row) {
  const std::string kind = row["row"].get<std::string>();
  if (kind == "all") return "all classes";
  if (kind == "class") return "class " + std::to_string(row["class"].get<int>());
  return "pair " + std::to_string(row["ci"].get<int>()) + "-" + std::to_string(row["cj"].get<int>());
}

// Counts, spacing and the border band, exemplar beside output.
void write_summaries(std::ostream& os, const json& r) {
  os << "                    exemplar      output\n";
  os << line("points          %12zu %12zu\n", r["exemplar"]["count"].get<size_t>(), r["output"]["count"].get<size_t>());
  for (const char* key : {"d_min", "d_min_square", "mean_nn", "relative_radius", "border_fraction"})
    os << line("%-16s%12s %12s\n", key, cell(r["exemplar"][key]).c_str(), cell(r["output"][key]).c_str());
  // What uniform points on each domain put in the border band: the value to compare with.
  if (r["output"].contains("border_fraction_uniform"))
    os << line("%-16s%12s %12s\n", "  if uniform", cell(r["exemplar"]["border_fraction_uniform"]).c_str(),
               cell(r["output"]["border_fraction_uniform"]).c_str());
  // The density near the border over uniform's, band by band (border.hpp: a pile reads > 1
  // in the narrow bands, a thin seam < 1).
  if (r["output"].contains("border_profile")) {
    const json& bands = r["output"]["border_profile"]["band"];
    for (size_t i = 0; i < bands.size(); ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "  within %g %%", 100 * bands[i].get<double>());
      os << line("%-16s%12s %12s  (over uniform)\n", name, cell(r["exemplar"]["border_profile"]["over_uniform"][i], "%.2f").c_str(),
                 cell(r["output"]["border_profile"]["over_uniform"][i], "%.2f").c_str());
    }
  }
  os << "upscale (per axis) " << cell(r["upscale"], "%.3f") << "\n";
  if (r.contains("classes_matched")) {
    const std::string w = class_match_warning(r["classes_matched"]);
    if (!w.empty()) os << "note: " << w << "\n";
  }
  os << "\n";
}

// PCF MSE, Wasserstein and Chamfer per row under the protocol, the spread over crops, and
// the notes that say when a row's numbers are estimates or depend on where the cuts fall.
void write_metrics(std::ostream& os, const json& r) {
  const bool crops = r.contains("protocol") && r["protocol"].value("name", std::string()) == "crops";
  if (r.contains("protocol")) os << protocol_line(r["protocol"]) << "\n";
  os << (crops ? "crop means       " : "quadrant metrics ") << "  pcf_mse  wasserstein  chamfer  exemplar points\n";
  size_t fewest = r["all"].value("exemplar_points", size_t(0));
  size_t sample_a = 0, sample_b = 0;  // largest Wasserstein subsamples of the rows
  auto row = [&](const std::string& name, const json& m) {
    const size_t n = m.value("exemplar_points", size_t(0));
    fewest = std::min(fewest, n);
    std::string w = cell(m["wasserstein"]);
    if (m.value("wasserstein_method", std::string("exact")) == "subsample") {
      w = "~" + cell(m["wasserstein_estimate"]);
      sample_a = std::max(sample_a, m["wasserstein_sample"][0].get<size_t>());
      sample_b = std::max(sample_b, m["wasserstein_sample"][1].get<size_t>());
    }
    os << line("%-16s %9s %12s %8s %16zu\n", name.c_str(), cell(m["pcf_mse"], "%.5f").c_str(), w.c_str(), cell(m["chamfer"]).c_str(), n);
  };
  row("all classes", r["all"]);
  for (const auto& c : r["classes"]) row("class " + std::to_string(c["label"].get<int>()), c);
  for (const auto& c : r["cross"])
    os << line("cross %d-%d        %9s\n", c["ci"].get<int>(), c["cj"].get<int>(), cell(c["pcf_mse"], "%.5f").c_str());
  // Crops: how the pcf_mse spreads over the crops (a mean hides one bad region).
  if (crops) {
    os << "pcf_mse over the " << r["protocol"].value("patches", size_t(0)) << " crops:\n";
    os << line("%-16s %12s %10s %10s\n", "", "q1", "median", "q3");
    auto spread = [&](const std::string& name, const json& m) {
      if (!m.contains("pcf_mse_quartiles")) return;
      const json& q = m["pcf_mse_quartiles"];
      os << line("%-16s %12s %10s %10s\n", name.c_str(), cell(q[0], "%.5f").c_str(), cell(q[1], "%.5f").c_str(),
                 cell(q[2], "%.5f").c_str());
    };
    spread("all classes", r["all"]);
    for (const auto& c : r["classes"]) spread("class " + std::to_string(c["label"].get<int>()), c);
    for (const auto& c : r["cross"]) spread("cross " + std::to_string(c["ci"].get<int>()) + "-" + std::to_string(c["cj"].get<int>()), c);
  }
  if (sample_a > 0)
    os << "~ Wasserstein estimated: exact assignment between random subsamples (up to " << sample_a << " exemplar x "
       << sample_b << " patch points),\n  as a " << (crops ? "crop" : "quadrant") << " exceeds "
       << r["options"].value("wasserstein_exact_pairs", size_t(0))
       << " point pairs (exact: O(n^2 m)); comparable only with estimates of the same sample sizes\n";
  if (r.contains("cross_skipped")) os << "note: " << r["cross_skipped"].get<std::string>() << "\n";
  if (fewest > 0 && fewest < kFewPoints)
    os << "note: with fewer than " << kFewPoints << " exemplar points, a row's pcf_mse depends on where the "
       << (crops ? "crops" : "quadrants") << "\n"
       << "      cut the pattern as much as on its structure (docs/lab/per_class_floor/per_class_floor.sh measures it)\n";
}

// Overlap is the method's known weakness on disks (paper Fig. 15): every class pair is shown,
// with the output's share of overlapping pairs and of points that overlap another.
void write_overlaps(std::ostream& os, const json& overlap) {
  os << "\noverlapping disks  exemplar pairs  output pairs  pair fraction  points overlapping\n";
  const auto& ex = overlap["exemplar"];
  const auto& out = overlap["output"];
  for (size_t i = 0; i < out.size() && i < ex.size(); ++i) {
    const int ci = out[i]["ci"].get<int>(), cj = out[i]["cj"].get<int>();
    if (ci >= 0 && out.size() == 2) continue;  // one class: its pair row repeats the "all" row
    const std::string name = ci < 0 ? "all classes" : "classes " + std::to_string(ci) + "-" + std::to_string(cj);
    os << line("  %-16s %14zu %13zu %14s %19s\n", name.c_str(), ex[i]["pairs"].get<size_t>(), out[i]["pairs"].get<size_t>(),
               cell(out[i]["pair_fraction"], "%.2e").c_str(), cell(out[i]["point_fraction"], "%.4f").c_str());
  }
}

// The L-function's largest gap per row, and the mark correlations' (second_order_report.hpp).
void write_second_order(std::ostream& os, const json& so) {
  os << "\nK, L, g (spatstat's estimators, translation correction, exemplar units; zoom " << cell(so["zoom"], "%.4g") << ")\n";
  os << "                  sup |L_out - L_ex|   in mean spacings\n";
  for (const auto& row : so["rows"])
    os << line("  %-16s %18s %19s\n", row_name(row).c_str(), cell(row["l_sup"], "%.5f").c_str(),
               cell(row["l_sup_spacings"], "%.4f").c_str());
  if (so.contains("pairs_skipped")) os << "  note: " << so["pairs_skipped"].get<std::string>() << "\n";
  for (const auto& m : so["mark_correlation"]) {
    os << "  mark correlation of '" << m["attribute"].get<std::string>() << "': ";
    if (m.contains("skipped"))
      os << m["skipped"].get<std::string>() << "\n";
    else
      os << "sup |k_mm difference| " << cell(m["sup"], "%.4f") << "\n";
  }
}

// One novelty-kind line (novelty.hpp): the share of matched neighbourhoods and what it means.
void write_match(std::ostream& os, const char* name, const json& m, const char* against) {
  os << line("  %-10s ", name);
  if (!m["share"].is_number()) {
    os << "cannot judge: no output point has " << m["k"].get<int>() << " neighbours inside the output's window\n";
    return;
  }
  os << cell(m["share"], "%.3f") << " of " << m["scored"].get<size_t>() << " points' " << m["k"].get<int>()
     << "-neighbourhoods are a translate of " << against << "'s within " << cell(m["tolerance"], "%g")
     << " mean NN distances: " << (m["copy"].get<bool>() ? "COPY" : "new") << " (a copy from "
     << cell(m["copy_share"], "%g") << ")\n";
}

// The periodicity line (periodicity.hpp): the ratio at the exemplar's period and its flag.
void write_periodicity(std::ostream& os, const json& p) {
  os << "  periodicity " << cell(p["ratio"], "%.3g") << ": median periodogram at the exemplar's period ("
     << cell(p["period"][0], "%.4g") << " x " << cell(p["period"][1], "%.4g") << ") and harmonics up to "
     << p["harmonics"].get<int>() << " over the median between them: ";
  if (p["periodic"].is_boolean())
    os << (p["periodic"].get<bool>() ? "PERIODIC" : "no repeat") << " (periodic from " << cell(p["periodic_ratio"], "%g")
       << ")\n";
  else
    os << "cannot judge (fewer than 2 output points)\n";
}

// The border line (border.hpp): the output's density near the border over uniform's, per band.
void write_border(std::ostream& os, const json& b) {
  os << "  border      over uniform within";
  const json& bands = b["band"];
  for (size_t i = 0; i < bands.size(); ++i)
    os << (i ? ", " : " ") << cell(bands[i].is_number() ? json(100 * bands[i].get<double>()) : json(), "%g");
  os << " % of the shorter side: output";
  for (const auto& v : b["output"]) os << " " << cell(v, "%.2f");
  os << ", exemplar";
  for (const auto& v : b["exemplar"]) os << " " << cell(v, "%.2f");
  os << " (> 1 points piled on the edge, < 1 a thin seam)\n";
}

// The fidelity rows (fidelity.hpp): each distance in spreads against its band, the
// permutation verdict's p beside it.
void write_fidelity(std::ostream& os, const json& f) {
  os << "  fidelity: L (sup, mean spacings) and g (rms) distances in spreads, the median distance independent\n"
        "  realizations of the output's size show (from "
     << f["windows"].get<int>() << " random exemplar sub-windows of " << cell(f["side"], "%g")
     << " its sides); within band: up to " << cell(f["band"], "%g")
     << " spreads times the row's clustering^(1/4) (1 + a point's extra neighbours within r_max; 1 if regular)";
  if (f.contains("nominal_rate") && f["nominal_rate"].is_number())
    os << ", which " << cell(json(100 * f["nominal_rate"].get<double>()), "%g")
       << " % of independent realizations exceed per distance";
  os << "\n";
  os << "                     L distance  spreads   band   g distance  spreads   band  reading       verdict p\n";
  for (const auto& row : f["rows"]) {
    const std::string name = row.value("name", std::string("?"));
    const std::string reading = row["within"].is_null() ? "cannot judge" : row["within"].get<bool>() ? "within band" : "OUT OF BAND";
    std::string p = "-";
    if (row.contains("verdict_p") && row["verdict_p"].is_number())
      p = cell(row["verdict_p"], "%.4f") + " " + (row.value("verdict_outcome", std::string()) == "pass" ? "pass" : "FAIL");
    else if (row.contains("verdict_outcome"))
      p = row["verdict_outcome"].get<std::string>();
    auto part = [&](const char* key) {
      if (!row.contains(key)) return line("%11s %8s %6s", "-", "-", "-");
      const json& m = row[key];
      return line("%11s %8s %6s", cell(m["distance"], "%.4f").c_str(), cell(m["spreads"], "%.2f").c_str(), cell(m["band"], "%.2f").c_str());
    };
    const char* first = row["row"] == "mark" ? "kmm" : "l";
    os << line("  %-18s %s %s  %-12s  %s\n", name.c_str(), part(first).c_str(), part("g").c_str(), reading.c_str(), p.c_str());
    if (row.contains("reason")) os << "      " << row["reason"].get<std::string>() << "\n";
  }
  const size_t n = f["rows"].size();
  if (f["within"].is_null())
    os << "  fidelity: cannot judge (" << f.value("cannot_judge", size_t(0)) << " of " << n << " rows; none out of band)\n";
  else if (f["within"].get<bool>())
    os << "  fidelity: within band (every row)\n";
  else
    os << "  fidelity: OUT OF BAND (" << f.value("out_of_band", size_t(0)) << " of " << n << " rows)\n";
}

// The scorecard: novelty (and diversity), fidelity, periodicity, border, then the close pairs per row.
void write_scorecard(std::ostream& os, const json& sc) {
  os << "\nscorecard (docs/explanation/scorecard.md: what each line measures, its false-alarm rate)\n";
  if (sc.contains("novelty")) write_match(os, "novelty", sc["novelty"], "the periodic exemplar");
  if (sc.contains("diversity")) write_match(os, "diversity", sc["diversity"], "the other output");
  if (sc.contains("fidelity")) write_fidelity(os, sc["fidelity"]);
  if (sc.contains("periodicity")) write_periodicity(os, sc["periodicity"]);
  if (sc.contains("border")) write_border(os, sc["border"]);
  if (!sc.contains("close_pairs")) return;
  os << "  close pairs (plane, exemplar units): output pairs closer than the exemplar's closest, the share of points in one;\n"
        "  normalized min distance = closest pair / the largest possible at the row's density (paper's Table 1)\n";
  os << "                   exemplar min  pairs below  share of points  normalized: exemplar  output\n";
  for (const auto& row : sc["close_pairs"]["rows"])
    os << line("  %-16s %12s %12s %16s %21s %7s\n", row_name(row).c_str(), cell(row["exemplar_min"], "%.4g").c_str(),
               row["pairs_below"].is_number() ? std::to_string(row["pairs_below"].get<size_t>()).c_str() : "-",
               cell(row["share_below"], "%.4f").c_str(), cell(row["exemplar_normalized"], "%.3f").c_str(),
               cell(row["output_normalized"], "%.3f").c_str());
}

}  // namespace

std::string format_evaluation(const json& r) {
  std::ostringstream os;
  write_summaries(os, r);
  write_metrics(os, r);
  if (r.contains("overlap")) write_overlaps(os, r["overlap"]);
  if (r.contains("second_order")) write_second_order(os, r["second_order"]);
  if (r.contains("scorecard")) write_scorecard(os, r["scorecard"]);
  if (r.contains("verdict")) os << "\n" << format_verdict(r["verdict"]);
  return os.str();
}

}  // namespace ppsynth
