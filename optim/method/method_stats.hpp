#pragma once
// A method's stats (run.json's method_stats, less the run layer's stages) are typed as stage
// records are (optim/method/stage_record.hpp): each method keeps a struct of its own with one
// field per key (GaborStats, pcf2017::Pcf2017Stats, roveri2015::Roveri2015Stats), written
// with to_json and read back with a from_json that refuses a missing or wrong-typed key by its
// path. The run layer carries them as JSON, since it does not know the method.
//
// Here: what those structs share, the reader of one stats object and a rectangle output's fields.
// Torch-free, as optim/method/method.hpp.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

// One object of a method's stats, read key by key. Each reader throws std::invalid_argument
// naming the key's path ("'windows.nx' is not an integer"); the reader that calls it names its file.
class StatsFields {
 public:
  // `path`: where `j` sits in the stats ("" at the top, "windows", "classes[1]").
  StatsFields(const nlohmann::json& j, std::string path);

  bool has(const std::string& key) const;
  int integer(const std::string& key) const;
  size_t count(const std::string& key) const;   // an integer >= 0
  double number(const std::string& key) const;  // finite
  bool flag(const std::string& key) const;
  std::string text(const std::string& key) const;
  std::vector<int> integers(const std::string& key) const;
  std::vector<double> numbers(const std::string& key) const;
  std::array<double, 4> box(const std::string& key) const;               // {x0, y0, x1, y1}
  std::map<std::string, double> weights(const std::string& key) const;   // numbers by name
  const nlohmann::json& value(const std::string& key) const;  // any JSON: a record another part owns
  StatsFields object(const std::string& key) const;
  std::vector<StatsFields> objects(const std::string& key) const;  // a list of objects

  // The keys outside `known`, in key order.
  std::vector<std::string> others(const std::vector<std::string>& known) const;
  // Refuses the first of them: a key no field reads belongs to some other record.
  void refuse_others(const std::vector<std::string>& known) const;

 private:
  const nlohmann::json& at(const std::string& key) const;  // refuses a missing key
  std::string path(const std::string& key) const;
  [[noreturn]] void refuse(const std::string& key, const std::string& what) const;

  const nlohmann::json& j_;
  std::string path_;
};

// A rectangle output's fields (core/output_shape.hpp), flat in the stats beside the method's own.
struct RectangleStats {
  std::string output;             // OutputShape::describe()
  std::array<double, 4> canvas{}; // where it was synthesized: {x0, y0, x1, y1} in exemplar units
  size_t canvas_points = 0;       // there, before the crop to the rectangle
};

// Writes its keys into the object `stats`.
void add_to(nlohmann::json& stats, const RectangleStats& r);
RectangleStats rectangle_stats_from(const StatsFields& f);
inline const std::vector<std::string> kRectangleStatsKeys = {"output", "canvas", "canvas_points"};

}  // namespace ppsynth
