// SPDX-License-Identifier: MIT
// JSON text a user wrote (transfer functions, presets), parsed with the library's error in
// the user's words: "WHAT: parse error at line 1, column 88: ..." or "WHAT: number overflow
// parsing '1e999'", without the library's "[json.exception.parse_error.101]" tag.
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace volpost {

inline nlohmann::json parseJson(const std::string& text, const std::string& what) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers beyond a double
    std::string message = e.what();
    if (!message.empty() && message.front() == '[')
      if (const auto end = message.find("] "); end != std::string::npos) message.erase(0, end + 2);
    throw std::runtime_error(what + ": " + message);
  }
}

}  // namespace volpost
