// libFuzzer target: the checkpoint reader (core/checkpoint_file.hpp) and the key comparison a
// resume makes. Each input is read as it is (its checksum rarely matches: the checksum's
// refusal) and with its checksum mended (the checks behind it: header, shapes, sizes, finite
// values). What is accepted must write back and read back the same. Contract: fuzz_common.hpp.
#include <cstring>

#include "core/checkpoint_file.hpp"
#include "core/content_hash.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

namespace {

std::string mended(std::string bytes) {
  if (bytes.size() < 8) return bytes;
  const uint64_t h = fnv1a64(bytes.data(), bytes.size() - 8);
  std::memcpy(&bytes[bytes.size() - 8], &h, 8);
  return bytes;
}

bool same(const CheckpointFile& a, const CheckpointFile& b) {
  if (a.key != b.key || a.meta != b.meta || a.names() != b.names()) return false;
  for (const auto& n : a.names()) {
    const CheckpointArray &x = a.raw(n), &y = b.raw(n);
    if (x.type != y.type || x.shape != y.shape || x.bytes != y.bytes) return false;
  }
  return true;
}

const nlohmann::json kKey = {{"method", "gabor"}, {"method_version", 1}, {"seed", 95}, {"quick", false},
                             {"exemplar", "0123456789abcdef"}, {"config_hash", "fedcba9876543210"},
                             {"config", {{"seed", 95}, {"method", {{"type", "gabor"}}}}}};

}  // namespace

PPSYNTH_FUZZ_TEXT_TARGET {
  const std::string& raw = text;
  for (const std::string& bytes : {raw, mended(raw)}) {
    CheckpointFile f;
    if (!fuzz::accepts([&] { f = decode_checkpoint(bytes, "fuzz.bin"); })) continue;
    CheckpointFile back;
    if (!fuzz::accepts([&] { back = decode_checkpoint(encode_checkpoint(f), "fuzz.bin"); }))
      fuzz::fail("an accepted checkpoint does not read back once written");
    if (!same(f, back)) fuzz::fail("an accepted checkpoint reads back other contents once written");
    for (const auto& name : f.names()) {  // every typed read either works or is an InputError
      fuzz::accepts([&] { (void)f.doubles(name); });
      fuzz::accepts([&] { (void)f.ints(name); });
      fuzz::accepts([&] { (void)f.bytes(name); });
    }
    if (!checkpoint_key_difference(f.key, f.key).empty()) fuzz::fail("a key differs from itself");
    (void)checkpoint_key_difference(kKey, f.key);
    (void)checkpoint_key_difference(f.key, kKey);
  }
  return 0;
}
