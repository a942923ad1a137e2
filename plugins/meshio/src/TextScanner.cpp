// SPDX-License-Identifier: MIT
#include "TextScanner.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

namespace volpost::meshio {

TextScanner::TextScanner(std::shared_ptr<const std::string> bytes, std::string path)
    : bytesPtr_(std::move(bytes)), b_(*bytesPtr_), path_(std::move(path)) {}

std::string_view TextScanner::nextLine() {
  if (pos_ >= b_.size()) return {};
  const std::size_t end = std::min(b_.find('\n', pos_), b_.size());
  std::string_view line(b_.data() + pos_, end - pos_);
  last_ = pos_;
  pos_ = std::min(end + 1, b_.size());
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

std::string_view TextScanner::nextToken() {
  while (pos_ < b_.size() && std::isspace(static_cast<unsigned char>(b_[pos_]))) ++pos_;
  const std::size_t start = pos_;
  last_ = pos_;
  while (pos_ < b_.size() && !std::isspace(static_cast<unsigned char>(b_[pos_]))) ++pos_;
  return std::string_view(b_.data() + start, pos_ - start);
}

std::string_view TextScanner::peekLine() const {
  if (pos_ >= b_.size()) return {};
  const std::size_t end = std::min(b_.find('\n', pos_), b_.size());
  std::string_view line(b_.data() + pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

void TextScanner::seek(std::size_t offset) {
  pos_ = std::min(offset, b_.size());
  last_ = pos_;
}

std::int64_t TextScanner::lineNumber() const {
  const std::size_t at = std::min(last_, b_.size());
  return 1 + std::count(b_.begin(), b_.begin() + std::ptrdiff_t(at), '\n');
}

void TextScanner::fail(const std::string& message) const {
  throw ReadError::atLine(path_, lineNumber(), message);
}

void TextScanner::failAtOffset(std::size_t offset, const std::string& message) const {
  throw ReadError::atOffset(path_, offset, message);
}

void TextScanner::report(const Progress& progress, double from, double to) const {
  progress.report(from + (to - from) * double(pos_) / double(std::max<std::size_t>(b_.size(), 1)));
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string toUpper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return out;
}

std::vector<std::string_view> splitFields(std::string_view line, bool commas) {
  std::vector<std::string_view> out;
  const auto separator = [commas](char c) {
    return std::isspace(static_cast<unsigned char>(c)) || (commas && c == ',');
  };
  std::size_t i = 0;
  while (i < line.size()) {
    if (commas && line[i] == ',') {  // "1,,2": an empty field between two commas
      ++i;
      const std::size_t start = i;
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i < line.size() && line[i] == ',') out.emplace_back(line.data() + start, 0);
      continue;
    }
    if (separator(line[i])) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < line.size() && !separator(line[i])) ++i;
    out.emplace_back(line.data() + start, i - start);
  }
  return out;
}

namespace {
std::string shown(std::string_view field) {
  if (field.empty()) return "nothing";
  std::string s(field.substr(0, 40));
  for (char& c : s)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return "'" + s + "'";
}
}  // namespace

std::int64_t parseInteger(const TextScanner& scanner, std::string_view field, const char* what) {
  field = trim(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  std::int64_t v = 0;
  const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
  if (field.empty() || r.ec != std::errc() || r.ptr != field.data() + field.size())
    scanner.fail(std::string("expected ") + what + " (an integer), found " + shown(field));
  return v;
}

double parseReal(const TextScanner& scanner, std::string_view field, const char* what) {
  field = trim(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
  if (r.ec == std::errc::result_out_of_range && r.ptr == field.data() + field.size())
    return field.front() == '-' ? -HUGE_VAL : HUGE_VAL;  // "1e999": overflow reads as inf (then flagged)
  if (field.empty() || r.ec != std::errc() || r.ptr != field.data() + field.size())
    scanner.fail(std::string("expected ") + what + " (a number), found " + shown(field));
  return v;
}

double parseFortranReal(const TextScanner& scanner, std::string_view field, const char* what) {
  field = trim(field);
  std::string s(field);
  for (char& c : s)
    if (c == 'D' || c == 'd') c = 'E';
  const std::string upper = toUpper(s);
  if (upper == "NAN" || upper == "-NAN" || upper == "+NAN") return std::numeric_limits<double>::quiet_NaN();
  if (upper == "INF" || upper == "+INF" || upper == "INFINITY") return HUGE_VAL;
  if (upper == "-INF" || upper == "-INFINITY") return -HUGE_VAL;
  return parseReal(scanner, s, what);
}

void TextScanner::requireMemory(double bytes, const std::string& what) const {
  try {
    volpost::requireMemory(bytes, path_, what);
  } catch (const ReadError& e) {
    fail(e.detail());
  }
}

void TextScanner::requirePlausibleCount(std::int64_t count, std::size_t minBytes, const std::string& what) const {
  const std::size_t left = b_.size() - std::min(pos_, b_.size());
  if (count < 0) fail(what + " " + std::to_string(count) + " is negative");
  if (minBytes > 0 && std::uint64_t(count) > left / minBytes + 1)
    fail(what + " " + std::to_string(count) + " is more than the " + std::to_string(left) +
         " bytes left in the file can hold (corrupt or truncated)");
}

}  // namespace volpost::meshio
