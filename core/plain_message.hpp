#pragma once
// A library's exception text as a user may read it: without nlohmann::json's tag
// ("[json.exception.type_error.302] ") and without LibTorch's C++ backtrace (c10::Error's
// "Exception raised from ... frame #0 ..." lines). Messages of ppsynth never show either.
#include <string>

namespace ppsynth {

std::string plain_message(const std::string& what);

}  // namespace ppsynth
