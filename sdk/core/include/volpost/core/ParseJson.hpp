// SPDX-License-Identifier: MIT
// JSON text a user wrote (state files, transfer functions, presets), parsed with the
// library's error in the user's words: "WHAT: parse error at line 1, column 88: ..." or
// "WHAT: number overflow parsing '1e999'", without the library's
// "[json.exception.parse_error.101]" tag. Nesting is bounded: the library parses without
// recursion, but copying or printing a value recurses, so a file nested 100,000 deep would
// overflow the stack later; no volpost file nests more than a few levels.
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace volpost {

inline constexpr int kMaxJsonDepth = 64;

inline nlohmann::json parseJson(const std::string& text, const std::string& what) {
  using Json = nlohmann::json;
  std::vector<std::string> keys;  // the key being read at each depth, to say where
  const auto bounded = [&](int depth, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::key) {
      keys.resize(std::size_t(depth) + 1);
      keys[std::size_t(depth)] = parsed.get<std::string>();
    }
    if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) &&
        depth >= kMaxJsonDepth) {
      std::string where;
      for (std::size_t d = 0; d < keys.size() && d <= std::size_t(depth); ++d)
        if (!keys[d].empty()) where += (where.empty() ? "" : ".") + keys[d];
      throw std::runtime_error(what + ": lists and objects nested more than " + std::to_string(kMaxJsonDepth) +
                               " deep" + (where.empty() ? "" : " under \"" + where + "\"") +
                               "; a volpost file nests a few levels");
    }
    return true;
  };
  try {
    return Json::parse(text, bounded);
  } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers beyond a double
    std::string message = e.what();
    if (!message.empty() && message.front() == '[')
      if (const auto end = message.find("] "); end != std::string::npos) message.erase(0, end + 2);
    throw std::runtime_error(what + ": " + message);
  }
}

}  // namespace volpost
