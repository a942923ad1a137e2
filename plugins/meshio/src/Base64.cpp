// SPDX-License-Identifier: MIT
#include "Base64.hpp"

#include <array>

namespace volpost::meshio {
namespace {

constexpr std::array<std::int8_t, 256> makeTable() {
  std::array<std::int8_t, 256> t{};
  for (auto& v : t) v = -1;
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(alphabet[i])] = std::int8_t(i);
  return t;
}
constexpr auto kTable = makeTable();

}  // namespace

std::optional<std::vector<std::uint8_t>> decodeBase64(std::string_view text, std::size_t* error) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size() * 3 / 4);
  std::uint32_t quantum[4];
  int filled = 0, padding = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (c == '=') {
      quantum[filled++] = 0;
      ++padding;
    } else {
      if (kTable[c] < 0 || padding > 0) {
        if (error) *error = i;
        return std::nullopt;
      }
      quantum[filled++] = std::uint32_t(kTable[c]);
    }
    if (filled == 4) {
      const std::uint32_t v = (quantum[0] << 18) | (quantum[1] << 12) | (quantum[2] << 6) | quantum[3];
      out.push_back(std::uint8_t(v >> 16));
      if (padding < 2) out.push_back(std::uint8_t(v >> 8));
      if (padding < 1) out.push_back(std::uint8_t(v));
      filled = padding = 0;
    }
  }
  if (filled != 0) {
    if (error) *error = text.size();
    return std::nullopt;
  }
  return out;
}

}  // namespace volpost::meshio
