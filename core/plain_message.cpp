#include "core/plain_message.hpp"

namespace ppsynth {

std::string plain_message(const std::string& what) {
  std::string s = what;
  if (s.rfind("[json.exception.", 0) == 0) {
    const auto e = s.find("] ");
    if (e != std::string::npos) s = s.substr(e + 2);
  }
  for (const char* backtrace : {"\nException raised from ", "Exception raised from ", "\nframe #0"})
    if (const auto at = s.find(backtrace); at != std::string::npos) s.erase(at);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace ppsynth
