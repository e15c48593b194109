// The checkpoint file (core/checkpoint_file.hpp): what it holds reads back bit for bit, and
// whatever else is on disk -- one flipped byte anywhere, a truncation, a NaN, sizes that do
// not add up, another synthesis's key -- is a CheckpointError naming the file and what differs.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/checkpoint_file.hpp"
#include "core/content_hash.hpp"

using namespace ppsynth;

namespace {

CheckpointFile sample() {
  CheckpointFile f;
  f.key = {{"seed", 95}, {"method", "gabor"}};
  f.meta = {{"stage", 3}};
  f.put_doubles("positions", {0.25, 0.5, 0.75, 1.0}, {2, 2});
  f.put_ints("group", {0, 1});
  f.put_bytes("final", {1, 0});
  const float moving[] = {0.1f, 0.2f};
  f.put("moving", {ArrayType::F32, {1, 2}, std::string(reinterpret_cast<const char*>(moving), sizeof moving)});
  return f;
}

const size_t kMagic = std::string("ppsynth-checkpoint\n").size();

// Replaces the file's trailing checksum by the one of its (edited) contents: what a crafted
// file would do, so that the checks behind the checksum are reached.
std::string with_checksum(std::string bytes) {
  const uint64_t h = fnv1a64(bytes.data(), bytes.size() - 8);
  std::memcpy(&bytes[bytes.size() - 8], &h, 8);
  return bytes;
}

std::string header_of(const std::string& bytes) {
  uint64_t n = 0;
  std::memcpy(&n, bytes.data() + kMagic, 8);
  return bytes.substr(kMagic + 8, n);
}

// The header's JSON replaced by `header` (its length field rewritten), checksum fixed.
std::string with_header(const std::string& bytes, const std::string& header) {
  const std::string old = header_of(bytes);
  std::string out = bytes.substr(0, kMagic);
  const uint64_t n = header.size();
  out.append(reinterpret_cast<const char*>(&n), 8);
  out += header + bytes.substr(kMagic + 8 + old.size());
  return with_checksum(out);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("a checkpoint file reads back what was written, bit for bit", "[checkpoint_file]") {
  const std::string bytes = encode_checkpoint(sample());
  const CheckpointFile back = decode_checkpoint(bytes, "run/checkpoint.bin");
  CHECK(back.key == sample().key);
  CHECK(back.meta == sample().meta);
  CHECK(back.names() == sample().names());
  CHECK(back.raw("positions").shape == std::vector<int64_t>{2, 2});
  CHECK(back.raw("positions").bytes == sample().raw("positions").bytes);
  CHECK(back.ints("group") == std::vector<int64_t>{0, 1});
  CHECK(back.bytes("final") == std::vector<uint8_t>{1, 0});
  CHECK(back.raw("moving").bytes == sample().raw("moving").bytes);
  CHECK(encode_checkpoint(back) == bytes);
  // Asked for another type or rank, or an array it does not hold: an error naming both.
  CHECK_THROWS_WITH(back.ints("positions"), Catch::Contains("run/checkpoint.bin") && Catch::Contains("'positions'"));
  CHECK_THROWS_AS(back.doubles("nothing"), CheckpointError);
}

TEST_CASE("every flipped byte and every truncation of a checkpoint is refused", "[checkpoint_file]") {
  const std::string bytes = encode_checkpoint(sample());
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = static_cast<char>(bad[i] ^ 0x10);
    INFO("byte " << i);
    CHECK_THROWS_AS(decode_checkpoint(bad, "c.bin"), CheckpointError);
  }
  for (size_t n : {size_t{0}, size_t{5}, size_t{30}, bytes.size() / 2, bytes.size() - 1})
    CHECK_THROWS_AS(decode_checkpoint(bytes.substr(0, n), "c.bin"), CheckpointError);
  const std::string flipped = [&] {
    std::string b = bytes;
    b[b.size() / 2] ^= 1;
    return b;
  }();
  CHECK_THROWS_WITH(decode_checkpoint(flipped, "run/checkpoint.bin"),
                    Catch::Contains("run/checkpoint.bin") && Catch::Contains("checksum"));
  // The checkpoint of an earlier version (a torch archive) is named as such.
  CHECK_THROWS_WITH(decode_checkpoint("PK\x03\x04 an old archive", "c.bin"), Catch::Contains("earlier version"));
}

TEST_CASE("a crafted checkpoint with a valid checksum is still checked", "[checkpoint_file]") {
  const std::string bytes = encode_checkpoint(sample());
  const std::string h = header_of(bytes);
  struct Case {
    std::string header, says;
  };
  for (const Case& c : {Case{replaced(h, "\"shape\":[2,2]", "\"shape\":[2,3]"), "past the end"},
                        Case{replaced(h, "\"shape\":[2,2]", "\"shape\":[2,1]"), "after its last array"},
                        Case{replaced(h, "\"shape\":[2,2]", "\"shape\":[-2,-2]"), "impossible shape"},
                        Case{replaced(h, "\"shape\":[2,2]", "\"shape\":[4294967296,4294967296]"), "impossible shape"},
                        Case{replaced(h, "\"shape\":[2,2]", "\"shape\":[1,1,1,1,4]"), "more than 4"},
                        Case{replaced(h, "\"type\":\"f64\"", "\"type\":\"c128\""), "unknown type"},
                        Case{replaced(h, "\"name\":\"group\"", "\"name\":\"positions\""), "repeated name"},
                        Case{replaced(h, "\"format\":1", "\"format\":7"), "another ppsynth version"},
                        Case{replaced(h, "\"key\":{", "\"key\":[{"), "invalid JSON"},
                        Case{"[1, 2]", "no format"},
                        Case{replaced(h, "\"meta\":{\"stage\":3}", "\"meta\":7"), "'meta'"}}) {
    INFO(c.header);
    CHECK_THROWS_WITH(decode_checkpoint(with_header(bytes, c.header), "run/checkpoint.bin"),
                      Catch::Contains("run/checkpoint.bin") && Catch::Contains(c.says));
  }
  // A NaN or an infinity in a float array, checksum and all.
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    CheckpointFile f = sample();
    f.put_doubles("positions", {0.25, bad, 0.75, 1.0}, {2, 2});
    CHECK_THROWS_WITH(decode_checkpoint(encode_checkpoint(f), "c.bin"), Catch::Contains("'positions'") && Catch::Contains("not finite"));
  }
  CheckpointFile f = sample();
  const float nan = std::nanf("");
  f.put("moving", {ArrayType::F32, {1, 1}, std::string(reinterpret_cast<const char*>(&nan), 4)});
  CHECK_THROWS_WITH(decode_checkpoint(encode_checkpoint(f), "c.bin"), Catch::Contains("'moving'"));
}

TEST_CASE("a checkpoint's key says what differs from the synthesis resumed", "[checkpoint_file]") {
  const nlohmann::json config = {{"seed", 95}, {"method", {{"type", "gabor"}, {"c2", 1.0}}}, {"name", "lines"}};
  auto key = [](const nlohmann::json& c, const std::string& exemplar) {
    return nlohmann::json{{"method", "gabor"},       {"method_version", 1},
                          {"seed", c["seed"]},       {"quick", false},
                          {"exemplar", exemplar},    {"config_hash", content_hash(c.dump())},
                          {"config", c}};
  };
  const nlohmann::json mine = key(config, "aaaa");
  CHECK(checkpoint_key_difference(mine, mine).empty());
  nlohmann::json seed = config;
  seed["seed"] = 96;
  CHECK(checkpoint_key_difference(key(seed, "aaaa"), mine) == "seed 96 (the checkpoint's: 95)");
  nlohmann::json c2 = config;
  c2["method"]["c2"] = 2.0;
  CHECK(checkpoint_key_difference(key(c2, "aaaa"), mine) == "config key 'method.c2' = 2.0 (the checkpoint's: 1.0)");
  nlohmann::json unknown = config;
  unknown["color"] = "red";
  CHECK_THAT(checkpoint_key_difference(key(unknown, "aaaa"), mine), Catch::Contains("'color'") && Catch::Contains("absent"));
  CHECK_THAT(checkpoint_key_difference(key(config, "bbbb"), mine), Catch::Contains("exemplar"));
  nlohmann::json quick = mine;
  quick["quick"] = true;
  CHECK(checkpoint_key_difference(quick, mine) == "quick true (the checkpoint's: false)");
  CHECK_THAT(checkpoint_key_difference(mine, nlohmann::json::object()), Catch::Contains("seed 95 (the checkpoint's: absent)"));
  CHECK_FALSE(checkpoint_key_difference(mine, nullptr).empty());
  // Many keys: three named, the rest counted.
  nlohmann::json many = config;
  for (const char* k : {"a", "b", "c", "d", "e"}) many[k] = 1;
  CHECK_THAT(checkpoint_key_difference(key(many, "aaaa"), mine), Catch::Contains("and 2 more config keys"));
}
