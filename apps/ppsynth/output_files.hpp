#pragma once
// What a command may write over, checked before it reads or computes anything (the project's
// rule: a command never replaces what it did not create unless the user names it and says
// --force). Every command that writes a file names its outputs and inputs here:
//   an output that is one of the inputs (the same file by any spelling or link)  -> refused,
//                                                              even with --force
//   two outputs that are the same file                                          -> refused
//   an output that is an existing regular file (or a link to one)               -> refused
//                                                              unless --force
// A device or FIFO (/dev/stdout, /dev/null) is written through, never replaced
// (core/atomic_file.hpp), so it is not checked; a directory is refused when written.
// Options not given (empty paths) are skipped. Inputs may be "shared:..." paths.
#include <string>
#include <vector>

namespace ppsynth::app {

// A path as the user gave it, with the option (or argument name) that gave it.
struct NamedPath {
  std::string option, path;
};

// InputError naming the option and path; "Nothing was written."
void check_output_files(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs, bool force);

// A directory that --force empties (a run, a report, a gather) must not hold an input:
// InputError naming both, even with --force. Absent directories and empty paths pass.
void check_inputs_outside(const NamedPath& directory, const std::vector<NamedPath>& inputs);

}  // namespace ppsynth::app
