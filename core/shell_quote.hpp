#pragma once
// A string as one word for a POSIX shell: unchanged when it holds only safe characters, else
// in single quotes ('\'' for a quote). For the commands ppsynth prints (the resume command)
// and writes (SLURM job scripts).
#include <string>

namespace ppsynth {

inline std::string shell_quoted(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%") ==
                        std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace ppsynth
