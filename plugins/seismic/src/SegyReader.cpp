// SPDX-License-Identifier: MIT
#include "SegyReader.hpp"

#include "SeismicAttributes.hpp"

#include <volpost/core/Error.hpp>
#include <volpost/core/ResourceLimits.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace volpost::seismic {
namespace {

constexpr std::uint64_t kTextHeaderBytes = 3200, kBinaryHeaderBytes = 400, kTraceHeaderBytes = 240;
// At most this many trace positions in the grid for each trace read (1 % filled).
constexpr std::size_t kMostTracePositionsPerTrace = 100;

struct TraceKey {
  std::int64_t inlineNumber = 0, crosslineNumber = 0, offset = 0;
  glm::dvec2 cdp{0.0};
  std::int64_t delayMs = 0;
  std::int64_t valueUnitCode = 0;  ///< bytes 203-204 (revision 1 and later)
};

class SegyFile {
 public:
  explicit SegyFile(std::string path) : path_(std::move(path)) {
    requireRegularFile(path_);
    in_.open(path_, std::ios::binary);
    if (!in_) throw ReadError(path_, "cannot open the file");
    size_ = std::filesystem::file_size(path_);
  }
  const std::string& path() const { return path_; }
  std::uint64_t size() const { return size_; }
  void readAt(std::uint64_t offset, unsigned char* out, std::size_t bytes) {
    in_.clear();
    in_.seekg(std::streamoff(offset));
    in_.read(reinterpret_cast<char*>(out), std::streamsize(bytes));
    if (std::size_t(in_.gcount()) != bytes) throw ReadError::atOffset(path_, offset, "the file ends here");
  }
  [[noreturn]] void fail(std::uint64_t offset, const std::string& message) const {
    throw ReadError::atOffset(path_, offset, message);
  }

 private:
  std::string path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
};

// Where the traces start: after the text and binary headers and the extended text headers
// (a counted number, or rev 2's variable count ended by the ((SEG: EndText)) stanza).
std::uint64_t firstTraceOffset(SegyFile& file, const BinaryHeader& b) {
  std::uint64_t offset = kTextHeaderBytes + kBinaryHeaderBytes;
  if (b.extendedTextHeaders > 0) return offset + std::uint64_t(b.extendedTextHeaders) * kTextHeaderBytes;
  if (b.extendedTextHeaders == -1) {
    std::vector<unsigned char> block(kTextHeaderBytes);
    for (int n = 0; n < 10000 && offset + kTextHeaderBytes <= file.size(); ++n) {
      file.readAt(offset, block.data(), block.size());
      offset += kTextHeaderBytes;
      const std::string text = textHeaderText({reinterpret_cast<const char*>(block.data()), block.size()});
      if (text.find("EndText") != std::string::npos) return offset;
    }
    file.fail(kTextHeaderBytes + 304, "the extended text headers (count -1 at bytes 3505-3506) never end with "
                                      "((SEG: EndText))");
  }
  if (b.extendedTextHeaders < -1)
    file.fail(kTextHeaderBytes + 304, "the number of extended text headers (bytes 3505-3506) is " +
                                          std::to_string(b.extendedTextHeaders));
  return offset;
}

// An index axis built from the numbers the traces carry (inline or crossline): the first,
// the step (their greatest common difference) and the count, gaps included.
struct LineAxis {
  std::int64_t first = 0, step = 1;
  std::size_t count = 0;
  std::size_t indexOf(std::int64_t number) const { return std::size_t((number - first) / step); }
};

LineAxis lineAxis(const std::set<std::int64_t>& numbers) {
  LineAxis axis;
  axis.first = *numbers.begin();
  std::int64_t step = 0;
  for (auto it = std::next(numbers.begin()); it != numbers.end(); ++it) step = std::gcd(step, *it - *std::prev(it));
  axis.step = step > 0 ? step : 1;
  axis.count = std::size_t((*numbers.rbegin() - axis.first) / axis.step) + 1;
  return axis;
}

double scaled(std::int64_t value, std::int64_t scalar) {
  if (scalar > 0) return double(value) * double(scalar);
  if (scalar < 0) return double(value) / double(-scalar);
  return double(value);
}

// Least-squares fit of the CDP coordinates: cdp = o + i a + j b. Nullopt when the
// coordinates do not span a plane (all zero, one line, or not in the file).
struct PlanFit {
  glm::dvec2 origin, alongInline, alongCrossline;
};
std::optional<PlanFit> fitPlan(const std::vector<TraceKey>& keys, const std::vector<std::size_t>& is,
                               const std::vector<std::size_t>& js) {
  glm::dmat3 normal(0.0);
  glm::dvec3 rx(0.0), ry(0.0);
  for (std::size_t t = 0; t < keys.size(); ++t) {
    const glm::dvec3 row(1.0, double(is[t]), double(js[t]));
    normal += glm::outerProduct(row, row);
    rx += row * keys[t].cdp.x;
    ry += row * keys[t].cdp.y;
  }
  if (!(std::abs(glm::determinant(normal)) > 1e-9)) return std::nullopt;
  const glm::dvec3 cx = glm::inverse(normal) * rx, cy = glm::inverse(normal) * ry;
  PlanFit fit{{cx[0], cy[0]}, {cx[1], cy[1]}, {cx[2], cy[2]}};
  const double cross = fit.alongInline.x * fit.alongCrossline.y - fit.alongInline.y * fit.alongCrossline.x;
  const double scale = glm::length(fit.alongInline) * glm::length(fit.alongCrossline);
  if (!(scale > 0.0) || !(std::abs(cross) > 1e-6 * scale) || !std::isfinite(cross)) return std::nullopt;
  return fit;
}

// The type a sample format's values are kept in: its own, IBM floats as 32-bit floats (a
// 24-bit fraction fits exactly while the exponent stays in range).
SampleType storedType(SampleFormat format) {
  switch (format) {
    case SampleFormat::Int8: return SampleType::Int8;
    case SampleFormat::UInt8: return SampleType::UInt8;
    case SampleFormat::Int16: return SampleType::Int16;
    case SampleFormat::UInt16: return SampleType::UInt16;
    case SampleFormat::Int32: return SampleType::Int32;
    case SampleFormat::UInt32: return SampleType::UInt32;
    case SampleFormat::IbmFloat32: case SampleFormat::IeeeFloat32: return SampleType::Float32;
    case SampleFormat::IeeeFloat64: return SampleType::Float64;
  }
  return SampleType::Float64;
}

std::string offsetList(const std::set<std::int64_t>& offsets) {
  std::string s;
  std::size_t n = 0;
  for (std::int64_t o : offsets) {
    if (n++ == 8) return s + ", ...";
    s += (s.empty() ? "" : ", ") + std::to_string(o);
  }
  return s;
}

// The unit the traces' values are in (bytes 203-204), when every chosen trace names the
// same one the standard lists; traces that disagree leave the values without units, said.
std::string valueUnits(const std::vector<TraceKey>& keys, const std::vector<std::uint64_t>& chosen,
                       std::uint64_t dataStart, std::uint64_t traceBytes, Model& model) {
  const std::int64_t first = keys[chosen.front()].valueUnitCode;
  for (std::uint64_t t : chosen) {
    if (keys[t].valueUnitCode == first) continue;
    model.diagnostics.push_back(
        {Severity::Warning,
         "trace-value-units",
         "traces name different units for their values (bytes 203-204 of the trace header: code " +
             std::to_string(first) + " in trace " + std::to_string(chosen.front() + 1) + ", " +
             std::to_string(keys[t].valueUnitCode) + " in trace " + std::to_string(t + 1) + ", at byte " +
             std::to_string(dataStart + t * traceBytes + kTraceValueUnitPosition - 1) +
             "): the amplitude is shown without units",
         {}});
    return {};
  }
  return traceValueUnits(first);
}

}  // namespace

int SegyReader::sniff(std::string_view head) const {
  if (head.size() < kTextHeaderBytes + kBinaryHeaderBytes) return 0;
  std::string error;
  const auto b = parseBinaryHeader(reinterpret_cast<const unsigned char*>(head.data()) + kTextHeaderBytes, error);
  if (!b || b->samplesPerTrace == 0) return 0;
  const unsigned char first = static_cast<unsigned char>(head[0]);
  return first == 0xC3 || first == 'C' ? 90 : 40;  // 'C' of "C 1 CLIENT..." in EBCDIC or ASCII
}

namespace {

// What the reader options say, by name: the header field each sets and its width in bytes.
struct PositionOption {
  const char* name;
  int TraceFieldPositions::*field;
  int bytes;
  const char* what;
};
constexpr PositionOption kPositionOptions[] = {
    {"inline-byte", &TraceFieldPositions::inlineNumber, 4, "inline number"},
    {"crossline-byte", &TraceFieldPositions::crosslineNumber, 4, "crossline number"},
    {"cdp-x-byte", &TraceFieldPositions::cdpX, 4, "CDP x coordinate"},
    {"cdp-y-byte", &TraceFieldPositions::cdpY, 4, "CDP y coordinate"},
    {"scalar-byte", &TraceFieldPositions::coordinateScalar, 2, "coordinate scalar"},
    {"offset-byte", &TraceFieldPositions::offset, 4, "source-receiver offset"},
};

}  // namespace

void checkPositions(const TraceFieldPositions& at) {
  const auto check = [](const char* what, int position, int bytes) {
    if (position < 1 || position + bytes - 1 > int(kTraceHeaderBytes))
      throw std::invalid_argument(std::string("the ") + what + " at byte " + std::to_string(position) + " of " +
                                  std::to_string(bytes) + " bytes lies outside the 240-byte trace header (1.." +
                                  std::to_string(int(kTraceHeaderBytes) - bytes + 1) + ")");
  };
  for (const PositionOption& o : kPositionOptions) check(o.what, at.*(o.field), o.bytes);
  check("delay", at.delayMs, 2);
  check("sample count", at.samples, 2);
}

std::vector<ReaderOption> SegyReader::options() const {
  const TraceFieldPositions defaults;
  std::vector<ReaderOption> list;
  for (const PositionOption& o : kPositionOptions)
    list.push_back({o.name, "BYTE",
                    std::string("first byte (1-based) of the trace header's ") + std::to_string(o.bytes) +
                        "-byte " + o.what + " (default " + std::to_string(defaults.*(o.field)) + ")"});
  list.push_back({"offset", "VALUE", "pre-stack files: the offset whose traces make the volume (default: refuse a "
                                     "file with several offsets, naming them)"});
  return list;
}

std::unique_ptr<Model> SegyReader::readWith(const std::string& path, const ReaderOptions& given,
                                            const Progress& progress) const {
  refuseUnknownOptions(*this, given);
  SegyOptions options;
  const auto integer = [](const std::string& name, const std::string& text) {
    std::size_t used = 0;
    long long v = 0;
    try {
      v = std::stoll(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size())
      throw ReaderOptionError("reader option " + name + "=" + text + " is not a whole number");
    return v;
  };
  for (const auto& [name, text] : given) {
    const long long v = integer(name, text);
    if (name == "offset") {
      options.offset = std::int64_t(v);
      continue;
    }
    for (const PositionOption& o : kPositionOptions)
      if (name == o.name) {
        if (v < 1 || v > static_cast<long long>(kTraceHeaderBytes) - o.bytes + 1)
          throw ReaderOptionError("reader option " + name + "=" + text + ": the " + std::to_string(o.bytes) +
                                      "-byte " + o.what + " must start at byte 1.." +
                                      std::to_string(int(kTraceHeaderBytes) - o.bytes + 1) + " of the trace header");
        options.positions.*(o.field) = int(v);
      }
  }
  return readSegy(path, options, progress);
}

std::unique_ptr<Model> readSegy(const std::string& path, const SegyOptions& options, const Progress& caller) {
  checkPositions(options.positions);
  Progress progress = caller;  // with this reader's stages
  SegyFile file(path);
  if (file.size() < kTextHeaderBytes + kBinaryHeaderBytes)
    file.fail(0, "only " + std::to_string(file.size()) + " bytes: a SEG-Y file starts with 3600 bytes of headers");
  std::vector<unsigned char> headers(kTextHeaderBytes + kBinaryHeaderBytes);
  file.readAt(0, headers.data(), headers.size());
  std::string error;
  const auto binary = parseBinaryHeader(headers.data() + kTextHeaderBytes, error);
  if (!binary) file.fail(kTextHeaderBytes + 24, error);
  const BinaryHeader& b = *binary;
  if (b.samplesPerTrace == 0) file.fail(kTextHeaderBytes + 20, "binary header: 0 samples per trace (bytes 3221-3222)");

  const std::uint64_t dataStart = firstTraceOffset(file, b);
  const std::uint64_t headerBytes = kTraceHeaderBytes * (1 + std::uint64_t(b.extraTraceHeaders));
  const std::uint64_t traceBytes =
      checkedSum(headerBytes, checkedProduct(b.samplesPerTrace, sampleBytes(b.format), path, "a trace"), path, "a trace");
  if (dataStart >= file.size()) file.fail(dataStart, "no traces: the file ends after its headers");
  const std::uint64_t traceCount = (file.size() - dataStart) / traceBytes;
  if ((file.size() - dataStart) % traceBytes != 0)
    file.fail(dataStart + traceCount * traceBytes,
              "the file ends inside trace " + std::to_string(traceCount + 1) + " (" +
                  std::to_string((file.size() - dataStart) % traceBytes) + " of its " + std::to_string(traceBytes) +
                  " bytes: " + std::to_string(b.samplesPerTrace) + " samples of " +
                  std::to_string(sampleBytes(b.format)) + " bytes and the header): truncated, or the samples per "
                  "trace (bytes 3221-3222) are wrong");
  if (traceCount == 0) file.fail(dataStart, "no traces: the file ends after its headers");
  requireMemory(double(traceCount) * sizeof(TraceKey), path, "the trace headers");

  // Pass 1: the headers only.
  progress.setStage("Reading trace headers");
  const TraceFieldPositions& at = options.positions;
  std::vector<TraceKey> keys(traceCount);
  std::vector<unsigned char> th(kTraceHeaderBytes);
  bool traceCountDiffers = false;
  std::string traceCountNote;
  for (std::uint64_t t = 0; t < traceCount; ++t) {
    const std::uint64_t offset = dataStart + t * traceBytes;
    file.readAt(offset, th.data(), th.size());
    const auto field = [&](int position, int bytes) { return headerInt(th.data(), position, bytes, b.order); };
    TraceKey& k = keys[t];
    k.inlineNumber = field(at.inlineNumber, 4);
    k.crosslineNumber = field(at.crosslineNumber, 4);
    k.offset = field(at.offset, 4);
    const std::int64_t scalar = field(at.coordinateScalar, 2);
    k.cdp = {scaled(field(at.cdpX, 4), scalar), scaled(field(at.cdpY, 4), scalar)};
    k.delayMs = field(at.delayMs, 2);
    // Revision 0 left bytes 203-204 unassigned: whatever they hold there is no unit.
    if (b.revisionMajor >= 1) k.valueUnitCode = field(kTraceValueUnitPosition, 2);
    // The binary header's count rules (it fits the file's size); trace headers copied from a
    // longer survey may still carry the old count: said once, not refused.
    const std::int64_t samples = headerInt(th.data(), at.samples, 2, b.order, false);
    if (samples != 0 && std::size_t(samples) != b.samplesPerTrace && !traceCountDiffers) {
      traceCountDiffers = true;
      traceCountNote = "trace " + std::to_string(t + 1) + " says it has " + std::to_string(samples) +
                       " samples (bytes " + std::to_string(at.samples) + "-" + std::to_string(at.samples + 1) +
                       "), the binary header " + std::to_string(b.samplesPerTrace) +
                       ", which fits the file's size: read as " + std::to_string(b.samplesPerTrace);
    }
    if (t % 4096 == 0) progress.report(0.3 * double(t) / double(traceCount));
  }

  // Pre-stack: several offsets at one trace position.
  std::set<std::int64_t> offsets;
  for (const TraceKey& k : keys) offsets.insert(k.offset);
  std::vector<std::uint64_t> chosen;  // the traces that make the volume
  for (std::uint64_t t = 0; t < traceCount; ++t)
    if (!options.offset || keys[t].offset == *options.offset) chosen.push_back(t);
  if (options.offset && chosen.empty())
    file.fail(dataStart + std::uint64_t(at.offset - 1),
              "no trace has offset " + std::to_string(*options.offset) + " (bytes " + std::to_string(at.offset) +
                  "-" + std::to_string(at.offset + 3) + "); its offsets are " + offsetList(offsets));

  std::set<std::int64_t> inlines, crosslines;
  for (std::uint64_t t : chosen) {
    inlines.insert(keys[t].inlineNumber);
    crosslines.insert(keys[t].crosslineNumber);
  }
  const LineAxis il = lineAxis(inlines), xl = lineAxis(crosslines);
  if (il.count < 2 || xl.count < 2)
    file.fail(dataStart + std::uint64_t(at.inlineNumber - 1),
              std::to_string(chosen.size()) + " traces in " + std::to_string(il.count) + " inline(s) and " +
                  std::to_string(xl.count) + " crossline(s) (inline number at bytes " +
                  std::to_string(at.inlineNumber) + ", crossline at " + std::to_string(at.crosslineNumber) +
                  "): a volume needs at least 2 of each; a 2D line or other header positions?");
  if (b.samplesPerTrace < 2) file.fail(kTextHeaderBytes + 20, "1 sample per trace: a volume needs at least 2");
  const std::size_t cells = checkedProduct(il.count, xl.count, path, "the grid");
  // A few traces whose numbers lie far apart would span a grid of missing traces (3 traces,
  // 250 million zero samples): refused before its memory is taken. A real survey's outline
  // leaves gaps, never 99 % of the rectangle.
  if (cells > kMostTracePositionsPerTrace * chosen.size() && cells > 10000)
    file.fail(dataStart + std::uint64_t(at.inlineNumber - 1),
              std::to_string(chosen.size()) + " traces span inlines " + std::to_string(il.first) + " .. " +
                  std::to_string(il.first + std::int64_t(il.count - 1) * il.step) + " and crosslines " +
                  std::to_string(xl.first) + " .. " + std::to_string(xl.first + std::int64_t(xl.count - 1) * xl.step) +
                  ": a grid of " + std::to_string(cells) + " trace positions, more than " +
                  std::to_string(kMostTracePositionsPerTrace) +
                  " for each trace. The inline and crossline numbers (bytes " + std::to_string(at.inlineNumber) +
                  " and " + std::to_string(at.crosslineNumber) +
                  ") may be elsewhere in this file's trace headers: set the reader options inline-byte=N and "
                  "crossline-byte=M (--reader-option inline-byte=N crossline-byte=M on the command line, File > "
                  "Reader Options... in the window, Inline Byte and Crossline Byte in ParaView)");
  const std::size_t points = checkedProduct(cells, b.samplesPerTrace, path, "the grid");
  // The samples as stored and a renderer's copy of them; the grid holds no cells until
  // something needs them (Model::mesh checks those).
  requireMemory(double(points) * (double(bytesPerSample(storedType(b.format))) + kGridDrawingBytesPerPoint), path,
                "a grid of " + std::to_string(points) + " samples (" + toString(storedType(b.format)) +
                    ") and a renderer's copy of them");

  std::vector<std::size_t> is(chosen.size()), js(chosen.size());
  std::vector<std::int64_t> traceAt(cells, -1);  // the trace at each (inline, crossline)
  for (std::size_t c = 0; c < chosen.size(); ++c) {
    const TraceKey& k = keys[chosen[c]];
    is[c] = il.indexOf(k.inlineNumber);
    js[c] = xl.indexOf(k.crosslineNumber);
    std::int64_t& slot = traceAt[is[c] + il.count * js[c]];
    if (slot >= 0) {
      if (!options.offset && offsets.size() > 1)
        file.fail(dataStart + chosen[c] * traceBytes + std::uint64_t(at.offset - 1),
                  "pre-stack data: " + std::to_string(offsets.size()) + " offsets (" + offsetList(offsets) +
                      ") at one trace position (inline " + std::to_string(k.inlineNumber) + ", crossline " +
                      std::to_string(k.crosslineNumber) +
                      "); volpost renders stacked volumes: choose one offset (reader option offset=N: "
                      "--reader-option offset=N on the command line, File > Reader Options... in the window, Offset in "
                      "ParaView)");
      file.fail(dataStart + chosen[c] * traceBytes,
                "trace " + std::to_string(chosen[c] + 1) + " repeats inline " + std::to_string(k.inlineNumber) +
                    ", crossline " + std::to_string(k.crosslineNumber) + " of trace " + std::to_string(slot + 1));
    }
    slot = std::int64_t(chosen[c]);
  }

  auto model = std::make_unique<Model>();
  model->sourcePath = path;
  model->formatName = "SEG-Y seismic volume (revision " + std::to_string(b.revisionMajor) + ", " +
                      (b.order == ByteOrder::Big ? "big" : "little") + "-endian)";
  {
    const std::string text = textHeaderText({reinterpret_cast<const char*>(headers.data()), 80});
    const auto first = text.find_first_not_of(' '), last = text.find_last_not_of(' ');
    model->title = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  }
  RegularGrid grid;
  grid.dims = {il.count, xl.count, b.samplesPerTrace};
  grid.sampleStorage = describe(b.format);
  grid.axisNames = {"inline", "crossline", "time (ms)"};
  grid.firstLabel = {double(il.first), double(xl.first), double(keys[chosen.front()].delayMs)};
  // Beyond ten seconds between samples is no recording: a corrupt or hostile header (rev 2's
  // extended interval of 1e300 would overflow every time).
  if (b.sampleIntervalMicroseconds > 1e7) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "binary header: the sample interval is %g microseconds (bytes %s), more than 10 s between samples",
                  b.sampleIntervalMicroseconds,
                  b.revisionMajor >= 2 ? "3273-3280, the extended interval" : "3217-3218");
    file.fail(kTextHeaderBytes + (b.revisionMajor >= 2 ? 72 : 16), text);
  }
  double dtMs = b.sampleIntervalMicroseconds / 1000.0;
  if (!(dtMs > 0.0)) {
    dtMs = 1.0;
    model->diagnostics.push_back({Severity::Warning, "no-sample-interval",
                                  "the sample interval (bytes 3217-3218) is 0: samples are drawn 1 ms apart", {}});
  }
  grid.labelStep = {double(il.step), double(xl.step), dtMs};
  const std::optional<PlanFit> plan = fitPlan([&] {
    std::vector<TraceKey> k;
    for (std::uint64_t t : chosen) k.push_back(keys[t]);
    return k;
  }(), is, js);
  if (plan) {
    grid.origin = glm::dvec3(plan->origin, -grid.firstLabel[2]);
    grid.axes = {glm::dvec3(plan->alongInline, 0.0), glm::dvec3(plan->alongCrossline, 0.0), glm::dvec3(0, 0, -dtMs)};
  } else {
    // Without coordinates, lines 25 units apart (a common bin size), time as above.
    grid.origin = glm::dvec3(0.0, 0.0, -grid.firstLabel[2]);
    grid.axes = {glm::dvec3(25.0, 0, 0), glm::dvec3(0, 25.0, 0), glm::dvec3(0, 0, -dtMs)};
    model->diagnostics.push_back({Severity::Warning, "no-coordinates",
                                  "the CDP coordinates (bytes " + std::to_string(at.cdpX) + " and " +
                                      std::to_string(at.cdpY) +
                                      ") do not place the traces on a plane: lines are drawn 25 units apart",
                                  {}});
  }
  if (const std::string d = grid.defect(); !d.empty()) file.fail(dataStart, d);

  // Pass 2: the samples, trace by trace, into the grid (time slowest).
  progress.setStage("Reading samples");
  // Samples stay in the file's type (2 bytes each for format 3); an IBM float outside a
  // 32-bit float's range widens the whole array to 64-bit floats.
  SampleArray values(storedType(b.format), points);
  std::vector<unsigned char> samples(b.samplesPerTrace * sampleBytes(b.format));
  const std::size_t bytesPer = sampleBytes(b.format);
  std::size_t missing = 0, nonFinite = 0, beyondFloat = 0;
  double largestBeyondFloat = 0.0;
  std::vector<std::size_t> missingItems;
  for (std::size_t c = 0; c < cells; ++c) {
    if (traceAt[c] < 0) {
      ++missing;
      if (missingItems.size() < 100) missingItems.push_back(c);
      continue;
    }
    file.readAt(dataStart + std::uint64_t(traceAt[c]) * traceBytes + headerBytes, samples.data(), samples.size());
    for (std::size_t s = 0; s < b.samplesPerTrace; ++s) {
      double v = decodeSample(samples.data() + s * bytesPer, b.format, b.order);
      if (!std::isfinite(v)) {
        ++nonFinite;
        v = 0.0;
      }
      if (std::abs(v) > double(std::numeric_limits<float>::max())) {
        ++beyondFloat;
        if (std::abs(v) > std::abs(largestBeyondFloat)) largestBeyondFloat = v;
      }
      if (!values.fitsExactly(v)) values = values.widenedTo(SampleType::Float64);
      values.set(c + cells * s, v);
    }
    if (c % 1024 == 0) progress.report(0.3 + 0.6 * double(c) / double(cells));
  }
  if (missing > 0)
    model->diagnostics.push_back(
        {Severity::Warning, "missing-traces",
         std::to_string(missing) + " of " + std::to_string(cells) +
             " trace positions have no trace (the survey is not a full rectangle): their samples are 0",
         missingItems});
  if (nonFinite > 0)
    model->diagnostics.push_back({Severity::Warning, "nan-values",
                                  std::to_string(nonFinite) + " samples are not finite numbers: read as 0", {}});
  if (beyondFloat > 0) {
    // IBM floats reach 7.2e75: a sample beyond an IEEE float's 3.4e38 is almost always junk
    // (a header or garbage read as samples); it stretches the color scale over everything.
    char text[240];
    std::snprintf(text, sizeof text,
                  "%zu sample%s beyond a 32-bit float's range (up to %g): kept, but such values are usually junk "
                  "and they stretch the color scale; give a --range to see the rest",
                  beyondFloat, beyondFloat == 1 ? "" : "s", largestBeyondFloat);
    model->diagnostics.push_back({Severity::Warning, "samples-beyond-float", text, {}});
  }
  if (traceCountDiffers) model->diagnostics.push_back({Severity::Info, "trace-sample-count", traceCountNote, {}});
  {
    // Traces recorded from different start times are drawn on the first trace's time axis:
    // said, with the range, so that times read off the picture are not trusted blindly.
    std::int64_t earliest = keys[chosen.front()].delayMs, latest = earliest;
    std::size_t differing = 0;
    for (std::uint64_t t : chosen) {
      earliest = std::min(earliest, keys[t].delayMs);
      latest = std::max(latest, keys[t].delayMs);
      differing += keys[t].delayMs != keys[chosen.front()].delayMs;
    }
    if (differing > 0)
      model->diagnostics.push_back(
          {Severity::Warning,
           "trace-start-times",
           std::to_string(differing) + " of " + std::to_string(chosen.size()) +
               " traces start at another time than the first (delay recording time, bytes " +
               std::to_string(at.delayMs) + "-" + std::to_string(at.delayMs + 1) + ": " + std::to_string(earliest) +
               " .. " + std::to_string(latest) + " ms): every trace is drawn from the first trace's start, " +
               std::to_string(keys[chosen.front()].delayMs) + " ms, so their times are off by up to " +
               std::to_string(latest - earliest) + " ms",
           {}});
  }
  if (offsets.size() > 1 && options.offset)
    model->diagnostics.push_back({Severity::Info, "offset-chosen",
                                  "pre-stack file: offset " + std::to_string(*options.offset) + " of " +
                                      offsetList(offsets),
                                  {}});

  model->grid = grid;
  auto amplitude = Field::fromSamples("amplitude", FieldLocation::Node, 1, std::move(values));
  amplitude->setUnits(valueUnits(keys, chosen, dataStart, traceBytes, *model));
  model->fields.push_back(std::move(amplitude));
  addSeismicAttributes(*model);
  progress.report(1.0);
  return model;
}

}  // namespace volpost::seismic
