#include "core/checkpoint_file.hpp"

#include <cmath>
#include <cstring>
#include <set>

#include "core/config/json_text.hpp"
#include "core/content_hash.hpp"
#include "core/error.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "checkpoint files are little-endian; this host is not"
#endif

namespace ppsynth {

namespace {

const char kMagic[] = "ppsynth-checkpoint\n";
const size_t kMagicSize = sizeof kMagic - 1;
const int kFormat = 1;
// Bounds that no synthesis comes near (10^8 points is past any memory) and that keep every
// size computation below far from overflow.
const size_t kMaxArrays = 4096;
const size_t kMaxRank = 4;
const int64_t kMaxDimension = int64_t{1} << 40;

void append_u64(std::string& out, uint64_t v) {
  char b[8];
  std::memcpy(b, &v, 8);
  out.append(b, 8);
}

uint64_t read_u64(const std::string& in, size_t at) {
  uint64_t v = 0;
  std::memcpy(&v, in.data() + at, 8);
  return v;
}

bool parse_type(const std::string& name, ArrayType& t) {
  for (ArrayType c : {ArrayType::F64, ArrayType::F32, ArrayType::I64, ArrayType::U8})
    if (name == array_type_name(c)) return t = c, true;
  return false;
}

template <class T>
bool all_finite(const std::string& bytes) {
  const size_t n = bytes.size() / sizeof(T);
  for (size_t i = 0; i < n; ++i) {
    T v;
    std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
    if (!std::isfinite(v)) return false;
  }
  return true;
}

// The element count of `shape`, or -1 when a dimension is negative or too large.
int64_t element_count(const std::vector<int64_t>& shape) {
  int64_t n = 1;
  for (int64_t d : shape) {
    if (d < 0 || d > kMaxDimension) return -1;
    if (d != 0 && n > kMaxDimension / d) return -1;
    n *= d;
  }
  return n;
}

std::string shown(const nlohmann::json& v) {
  std::string s = v.is_null() ? std::string("absent") : v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

}  // namespace

CheckpointError checkpoint_error(const std::string& source, const std::string& what) {
  return CheckpointError(file_error(source, 0, what).what());
}

const char* array_type_name(ArrayType t) {
  switch (t) {
    case ArrayType::F64: return "f64";
    case ArrayType::F32: return "f32";
    case ArrayType::I64: return "i64";
    case ArrayType::U8: return "u8";
  }
  return "?";
}

size_t array_type_size(ArrayType t) {
  switch (t) {
    case ArrayType::F64: return 8;
    case ArrayType::F32: return 4;
    case ArrayType::I64: return 8;
    case ArrayType::U8: return 1;
  }
  return 1;
}

size_t CheckpointArray::count() const { return bytes.size() / array_type_size(type); }

void CheckpointFile::put(const std::string& name, CheckpointArray a) {
  const int64_t n = element_count(a.shape);
  if (n < 0 || static_cast<uint64_t>(n) * array_type_size(a.type) != a.bytes.size())
    throw std::logic_error("checkpoint array '" + name + "': its bytes do not match its shape");
  if (!arrays_.count(name)) order_.push_back(name);
  arrays_[name] = std::move(a);
}

void CheckpointFile::put_doubles(const std::string& name, const std::vector<double>& v, std::vector<int64_t> shape) {
  if (shape.empty()) shape = {static_cast<int64_t>(v.size())};
  put(name, {ArrayType::F64, std::move(shape), std::string(reinterpret_cast<const char*>(v.data()), v.size() * 8)});
}

void CheckpointFile::put_ints(const std::string& name, const std::vector<int64_t>& v) {
  put(name, {ArrayType::I64, {static_cast<int64_t>(v.size())}, std::string(reinterpret_cast<const char*>(v.data()), v.size() * 8)});
}

void CheckpointFile::put_bytes(const std::string& name, const std::vector<uint8_t>& v) {
  put(name, {ArrayType::U8, {static_cast<int64_t>(v.size())}, std::string(reinterpret_cast<const char*>(v.data()), v.size())});
}

const CheckpointArray& CheckpointFile::get(const std::string& name, ArrayType type, int rank) const {
  const auto it = arrays_.find(name);
  if (it == arrays_.end()) throw checkpoint_error(source, "no array '" + name + "' (not a checkpoint of this kind of synthesis)");
  const CheckpointArray& a = it->second;
  if (a.type != type || (rank >= 0 && a.shape.size() != static_cast<size_t>(rank)))
    throw checkpoint_error(source, "array '" + name + "': " + array_type_name(a.type) + " of rank " +
                                    std::to_string(a.shape.size()) + ", expected " + array_type_name(type) +
                                    (rank >= 0 ? " of rank " + std::to_string(rank) : std::string()));
  return a;
}

std::vector<double> CheckpointFile::doubles(const std::string& name) const {
  const CheckpointArray& a = get(name, ArrayType::F64, 1);
  std::vector<double> v(a.count());
  if (!v.empty()) std::memcpy(v.data(), a.bytes.data(), a.bytes.size());
  return v;
}

std::vector<int64_t> CheckpointFile::ints(const std::string& name) const {
  const CheckpointArray& a = get(name, ArrayType::I64, 1);
  std::vector<int64_t> v(a.count());
  if (!v.empty()) std::memcpy(v.data(), a.bytes.data(), a.bytes.size());
  return v;
}

std::vector<uint8_t> CheckpointFile::bytes(const std::string& name) const {
  const CheckpointArray& a = get(name, ArrayType::U8, 1);
  return std::vector<uint8_t>(a.bytes.begin(), a.bytes.end());
}

std::string encode_checkpoint(const CheckpointFile& f) {
  nlohmann::json arrays = nlohmann::json::array();
  for (const auto& name : f.names()) {
    const CheckpointArray& a = f.raw(name);
    arrays.push_back({{"name", name}, {"type", array_type_name(a.type)}, {"shape", a.shape}});
  }
  const std::string header =
      nlohmann::json{{"format", kFormat}, {"key", f.key}, {"meta", f.meta}, {"arrays", arrays}}.dump();
  std::string out(kMagic, kMagicSize);
  append_u64(out, header.size());
  out += header;
  for (const auto& name : f.names()) out += f.raw(name).bytes;
  append_u64(out, fnv1a64(out));
  return out;
}

CheckpointFile decode_checkpoint(const std::string& in, const std::string& source) {
  auto refuse = [&](const std::string& what) { return checkpoint_error(source, what); };
  if (in.size() < kMagicSize + 16 || in.compare(0, kMagicSize, kMagic) != 0)
    throw refuse("not a checkpoint of ppsynth (no ppsynth-checkpoint header; a checkpoint of an earlier version, or another file)");
  const size_t body = in.size() - 8;
  if (read_u64(in, body) != fnv1a64(in.data(), body))
    throw refuse("damaged: its checksum does not match its contents (a changed or truncated byte)");
  const uint64_t header_size = read_u64(in, kMagicSize);
  const size_t header_at = kMagicSize + 8;
  if (header_size > body - header_at) throw refuse("damaged: its header is longer than the file");
  nlohmann::json h;
  try {
    h = parse_json_text(in.substr(header_at, header_size), source + " (header)", false);
  } catch (const InputError& e) {
    throw CheckpointError(e.what());
  }
  if (!h.is_object() || !h.contains("format") || !h["format"].is_number_integer())
    throw refuse("damaged: its header has no format");
  if (h["format"] != kFormat)
    throw refuse("a checkpoint of another ppsynth version (format " + h["format"].dump() + ", this one reads " +
                 std::to_string(kFormat) + ")");
  for (const char* k : {"key", "meta"})
    if (!h.contains(k) || !h[k].is_object()) throw refuse(std::string("damaged: its header's '") + k + "' is not an object");
  if (!h.contains("arrays") || !h["arrays"].is_array() || h["arrays"].size() > kMaxArrays)
    throw refuse("damaged: its header's 'arrays' is not a list of at most " + std::to_string(kMaxArrays) + " arrays");
  CheckpointFile f;
  f.source = source;
  f.key = h["key"];
  f.meta = h["meta"];
  size_t at = header_at + header_size;
  std::set<std::string> seen;
  for (size_t i = 0; i < h["arrays"].size(); ++i) {
    const nlohmann::json& e = h["arrays"][i];
    const std::string where = "array " + std::to_string(i);
    if (!e.is_object() || !e.contains("name") || !e["name"].is_string() || !e.contains("type") || !e["type"].is_string() ||
        !e.contains("shape") || !e["shape"].is_array())
      throw refuse("damaged: " + where + " is not {\"name\", \"type\", \"shape\"}");
    const std::string name = e["name"];
    if (name.empty() || name.size() > 64 || !seen.insert(name).second)
      throw refuse("damaged: " + where + " has an empty, overlong or repeated name");
    CheckpointArray a;
    if (!parse_type(e["type"], a.type)) throw refuse("damaged: array '" + name + "' has an unknown type " + shown(e["type"]));
    if (e["shape"].size() > kMaxRank) throw refuse("damaged: array '" + name + "' has more than 4 dimensions");
    for (const auto& d : e["shape"]) {
      if (!d.is_number_integer()) throw refuse("damaged: array '" + name + "' has a shape that is not whole numbers");
      a.shape.push_back(d.get<int64_t>());
    }
    const int64_t n = element_count(a.shape);
    if (n < 0) throw refuse("damaged: array '" + name + "' has an impossible shape " + shown(e["shape"]));
    const uint64_t size = static_cast<uint64_t>(n) * array_type_size(a.type);
    if (size > body - at) throw refuse("damaged: array '" + name + "' runs past the end of the file");
    a.bytes = in.substr(at, size);
    at += size;
    if ((a.type == ArrayType::F64 && !all_finite<double>(a.bytes)) || (a.type == ArrayType::F32 && !all_finite<float>(a.bytes)))
      throw refuse("array '" + name + "' holds a value that is not finite (NaN or infinite)");
    f.put(name, std::move(a));
  }
  if (at != body) throw refuse("damaged: " + std::to_string(body - at) + " bytes after its last array");
  return f;
}

std::string checkpoint_key_difference(const nlohmann::json& expected, const nlohmann::json& found) {
  if (!found.is_object()) return "no key (not made for any synthesis)";
  std::string out;
  auto add = [&](const std::string& what) { out += (out.empty() ? "" : "; ") + what; };
  auto field = [](const nlohmann::json& j, const char* k) { return j.is_object() && j.contains(k) ? j[k] : nlohmann::json(); };
  for (const char* k : {"method", "method_version", "seed", "quick"})
    if (field(expected, k) != field(found, k))
      add(std::string(k) + " " + shown(field(expected, k)) + " (the checkpoint's: " + shown(field(found, k)) + ")");
  if (field(expected, "exemplar") != field(found, "exemplar"))
    add("the exemplar's points (they differ from those the checkpoint was made from)");
  if (field(expected, "config_hash") != field(found, "config_hash")) {
    const nlohmann::json a = field(expected, "config"), b = field(found, "config");
    size_t differing = 0;
    if (a.is_object() && b.is_object()) {
      const nlohmann::json fa = a.flatten(), fb = b.flatten();
      std::set<std::string> paths;
      for (auto it = fa.begin(); it != fa.end(); ++it) paths.insert(it.key());
      for (auto it = fb.begin(); it != fb.end(); ++it) paths.insert(it.key());
      for (const auto& p : paths) {
        const nlohmann::json va = fa.contains(p) ? fa[p] : nlohmann::json(), vb = fb.contains(p) ? fb[p] : nlohmann::json();
        if (va == vb || p == "/seed") continue;  // the seed is named above
        ++differing;
        if (differing > 3) continue;
        std::string dotted = p.substr(1);
        for (char& c : dotted)
          if (c == '/') c = '.';
        add("config key '" + dotted + "' = " + shown(va) + " (the checkpoint's: " + shown(vb) + ")");
      }
      if (differing > 3) add("and " + std::to_string(differing - 3) + " more config keys");
    }
    if (differing == 0 && out.empty()) add("the resolved config (its hash differs)");
  }
  return out;
}

}  // namespace ppsynth
