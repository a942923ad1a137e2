// SPDX-License-Identifier: MIT
#include "ProbeTable.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace volpost::app {

std::vector<std::string> allQuantityKeys(const ModelSession& session) {
  std::vector<std::string> keys;
  for (const Quantity& q : session.quantities()) keys.push_back(q.key());
  return keys;
}

std::string exactNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

namespace {
std::atomic<int> g_displayDigits{6};
}  // namespace

int displayDigits() { return g_displayDigits.load(); }
void setDisplayDigits(int digits) { g_displayDigits.store(std::clamp(digits, 2, 17)); }

std::string displayNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", displayDigits(), value);
  return text;
}

namespace {

// A header cell: quoted when it holds the separator, a quote or a line break (field
// names come from files and may hold anything).
std::string cell(const std::string& text, char separator) {
  if (text.find_first_of(std::string{separator, '"', '\n', '\r'}) == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

std::string probeTableHeader(const std::vector<std::string>& keys, char separator) {
  std::string out = "x";
  for (const char* column : {"y", "z", "element", "element_type", "node"}) out += separator + std::string(column);
  for (const std::string& key : keys) out += separator + cell(key, separator);
  out += '\n';
  return out;
}

std::string probeTableRows(const std::vector<ProbeResult>& rows, const std::vector<std::string>& keys, char separator) {
  std::string out;
  for (const ProbeResult& r : rows) {
    out += exactNumber(r.point.x) + separator + exactNumber(r.point.y) + separator + exactNumber(r.point.z);
    if (r.inside()) {
      out += separator + std::to_string(r.cellId) + separator + std::string(cellTypeName(r.cellType)) + separator +
             (r.nodeId ? std::to_string(*r.nodeId) : std::string());
    } else {
      out += std::string(3, separator);
    }
    for (const std::string& key : keys) {
      const auto v = r.inside() ? r.value(key) : std::nullopt;
      out += separator + exactNumber(v ? *v : NAN);
    }
    out += '\n';
  }
  return out;
}

std::string probeTable(const std::vector<ProbeResult>& rows, const std::vector<std::string>& keys, char separator) {
  return probeTableHeader(keys, separator) + probeTableRows(rows, keys, separator);
}

}  // namespace volpost::app
