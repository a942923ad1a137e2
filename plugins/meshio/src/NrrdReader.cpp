// SPDX-License-Identifier: MIT
#include "NrrdReader.hpp"

#include "DiskFileStream.hpp"

#include <volpost/core/Error.hpp>
#include <volpost/core/ResourceLimits.hpp>

#include <glm/vec3.hpp>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace volpost::meshio {
namespace {

constexpr std::size_t kMaxHeaderBytes = 1 << 20;  // a header is a few hundred bytes; a megabyte is not one
constexpr int kMaxComponents = 9;

struct SampleType {
  int bytes = 0;
  bool isFloat = false, isSigned = false;
  std::string words;  ///< for `info`: "16-bit integer"
};

// The type names the format allows (its spec's table), to the sample they mean.
std::optional<SampleType> sampleType(std::string name) {
  static const std::map<std::string, SampleType> types = [] {
    std::map<std::string, SampleType> t;
    for (const char* n : {"signed char", "int8", "int8_t"}) t[n] = {1, false, true, "8-bit integer"};
    for (const char* n : {"uchar", "unsigned char", "uint8", "uint8_t"}) t[n] = {1, false, false, "8-bit unsigned integer"};
    for (const char* n : {"short", "short int", "signed short", "signed short int", "int16", "int16_t"})
      t[n] = {2, false, true, "16-bit integer"};
    for (const char* n : {"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"})
      t[n] = {2, false, false, "16-bit unsigned integer"};
    for (const char* n : {"int", "signed int", "int32", "int32_t"}) t[n] = {4, false, true, "32-bit integer"};
    for (const char* n : {"uint", "unsigned int", "uint32", "uint32_t"}) t[n] = {4, false, false, "32-bit unsigned integer"};
    for (const char* n : {"longlong", "long long", "long long int", "signed long long", "signed long long int", "int64", "int64_t"})
      t[n] = {8, false, true, "64-bit integer"};
    for (const char* n : {"ulonglong", "unsigned long long", "unsigned long long int", "uint64", "uint64_t"})
      t[n] = {8, false, false, "64-bit unsigned integer"};
    t["float"] = {4, true, true, "32-bit float"};
    t["double"] = {8, true, true, "64-bit float"};
    return t;
  }();
  const auto it = types.find(name);
  if (it == types.end()) return std::nullopt;
  return it->second;
}

enum class Encoding { Raw, Text, Hex, Gzip };

struct Header {
  int version = 0;
  SampleType type;
  std::string typeName;
  int dimension = 0;
  std::vector<std::uint64_t> sizes;
  Encoding encoding = Encoding::Raw;
  std::string encodingName;
  std::optional<bool> bigEndian;
  std::vector<std::optional<glm::dvec3>> directions;  ///< per axis; nullopt: "none"
  bool hasDirections = false;
  std::optional<glm::dvec3> origin;
  std::vector<double> spacings;  ///< per axis; NaN: not given
  std::vector<std::string> kinds;
  std::string content;
  std::string dataFile;  ///< empty: the data follows the header
  std::int64_t lineSkip = 0, byteSkip = 0;
  std::uint64_t dataOffset = 0;  ///< attached data: the byte after the header's blank line
};

std::string trim(std::string s) {
  const auto notSpace = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
  s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
  return s;
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

class HeaderParser {
 public:
  HeaderParser(const std::string& path, std::istream& in) : path_(path), in_(in) {}

  Header run() {
    Header h;
    std::string line;
    if (!next(line) || line.size() != 8 || line.rfind("NRRD000", 0) != 0 || line[7] < '1' || line[7] > '5')
      fail("not an NRRD file: its first line must be NRRD0001 to NRRD0005, found '" + line.substr(0, 40) + "'");
    h.version = line[7] - '0';
    std::map<std::string, std::string> fields;
    bool blank = false;
    while (next(line)) {
      if (line.empty()) {
        blank = true;
        break;
      }
      if (line[0] == '#') continue;
      if (line.find(":=") != std::string::npos) continue;  // key/value pairs: free text for other tools
      const auto colon = line.find(": ");
      if (colon == std::string::npos) fail("'" + line.substr(0, 60) + "' is not 'field: value'");
      std::string name = line.substr(0, colon);
      std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
      name.erase(std::remove(name.begin(), name.end(), ' '), name.end());  // "data file" = "datafile"
      if (!fields.emplace(name, trim(line.substr(colon + 2))).second) fail("the field '" + name + "' is given twice");
      lines_[name] = lineNumber_;
      if (name == "datafile" && fields[name].rfind("LIST", 0) == 0)  // the file names follow, one per line
        fail("data spread over several files (data file: LIST) is not read: join them into one", name);
    }
    h.dataOffset = consumed_;
    interpret(h, fields);
    if (h.dataFile.empty() && !blank) fail("the header ends without the blank line that starts the data, and names no data file");
    return h;
  }

 private:
  bool next(std::string& line) {
    line.clear();
    bool any = false;
    for (char c; in_.get(c);) {
      any = true;
      if (++consumed_ > kMaxHeaderBytes) fail("no end of the header in its first " + std::to_string(kMaxHeaderBytes) + " bytes");
      if (c == '\n') break;
      line += c;
    }
    if (!any) return false;
    ++lineNumber_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }

  [[noreturn]] void fail(const std::string& message, const std::string& field = {}) const {
    const auto it = lines_.find(field);
    throw ReadError::atLine(path_, it != lines_.end() ? it->second : lineNumber_, message);
  }

  double number(const std::string& text, const std::string& field) const {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') fail(field + ": '" + text.substr(0, 40) + "' is not a number", field);
    return v;
  }

  // "(x,y,z)" as NRRD writes a vector.
  glm::dvec3 vector(std::string text, const std::string& field) const {
    if (text.size() < 2 || text.front() != '(' || text.back() != ')')
      fail(field + ": '" + text.substr(0, 60) + "' is not a vector such as (1,0,0)", field);
    std::replace(text.begin(), text.end(), ',', ' ');
    const std::vector<std::string> parts = words(text.substr(1, text.size() - 2));
    if (parts.size() != 3)
      fail(field + ": '" + text.substr(0, 60) + "' has " + std::to_string(parts.size()) + " coordinates; volpost reads 3D space",
           field);
    glm::dvec3 v;
    for (int k = 0; k < 3; ++k) {
      v[k] = number(parts[std::size_t(k)], field);
      if (!std::isfinite(v[k])) fail(field + ": a coordinate is not finite", field);
    }
    return v;
  }

  void interpret(Header& h, const std::map<std::string, std::string>& f) {
    const auto get = [&](const char* name) -> const std::string* {
      const auto it = f.find(name);
      return it == f.end() ? nullptr : &it->second;
    };
    const auto required = [&](const char* name) -> const std::string& {
      const std::string* v = get(name);
      if (!v) fail(std::string("the header has no '") + name + ":' line");
      return *v;
    };
    h.typeName = required("type");
    const auto type = sampleType(h.typeName);
    if (!type) fail("type '" + h.typeName.substr(0, 40) + "' is not a sample type volpost reads (8- to 64-bit integers, float, double)", "type");
    h.type = *type;
    const double dimension = number(required("dimension"), "dimension");
    if (dimension != std::floor(dimension) || dimension < 1 || dimension > 16) fail("dimension must be a small whole number", "dimension");
    h.dimension = int(dimension);
    const std::vector<std::string> sizes = words(required("sizes"));
    if (int(sizes.size()) != h.dimension)
      fail("sizes lists " + std::to_string(sizes.size()) + " axes for dimension " + std::to_string(h.dimension), "sizes");
    for (const std::string& s : sizes) {
      const double v = number(s, "sizes");
      if (!(v >= 1.0 && v <= 1e15) || v != std::floor(v)) fail("sizes: '" + s + "' is not a positive whole number", "sizes");
      h.sizes.push_back(std::uint64_t(v));
    }
    h.encodingName = required("encoding");
    if (h.encodingName == "raw") h.encoding = Encoding::Raw;
    else if (h.encodingName == "txt" || h.encodingName == "text" || h.encodingName == "ascii") h.encoding = Encoding::Text;
    else if (h.encodingName == "hex") h.encoding = Encoding::Hex;
    else if (h.encodingName == "gz" || h.encodingName == "gzip") h.encoding = Encoding::Gzip;
    else if (h.encodingName == "bz2" || h.encodingName == "bzip2")
      fail("bzip2-compressed data is not read: decompress it (unu save -e raw, or bunzip2 a detached data file)", "encoding");
    else fail("encoding '" + h.encodingName.substr(0, 40) + "' is not raw, text, hex or gzip", "encoding");
    if (const std::string* e = get("endian")) {
      if (*e != "little" && *e != "big") fail("endian must be little or big, not '" + e->substr(0, 40) + "'", "endian");
      h.bigEndian = *e == "big";
    }
    if (h.type.bytes > 1 && h.encoding != Encoding::Text && !h.bigEndian)
      fail("the header has no 'endian:' line, which " + std::to_string(h.type.bytes) + "-byte samples need (little or big)");
    if (const std::string* d = get("spacedirections")) {
      const std::vector<std::string> parts = words(*d);
      if (int(parts.size()) != h.dimension)
        fail("space directions lists " + std::to_string(parts.size()) + " axes for dimension " + std::to_string(h.dimension),
             "spacedirections");
      for (const std::string& p : parts) {
        if (p == "none") h.directions.push_back(std::nullopt);
        else h.directions.push_back(vector(p, "spacedirections"));
      }
      h.hasDirections = true;
    }
    if (const std::string* o = get("spaceorigin")) h.origin = vector(*o, "spaceorigin");
    if (const std::string* s = get("spacedimension")) {
      if (number(*s, "spacedimension") != 3.0) fail("space dimension " + *s + ": volpost reads 3D space", "spacedimension");
    }
    for (const char* name : {"spacings", "axismins"}) {
      const std::string* s = get(name);
      if (!s) continue;
      const std::vector<std::string> parts = words(*s);
      if (int(parts.size()) != h.dimension) fail(std::string(name) + " lists the wrong number of axes", name);
      std::vector<double> values;
      for (const std::string& p : parts) values.push_back(p == "nan" || p == "NaN" ? NAN : number(p, name));
      if (std::string(name) == "spacings") h.spacings = values;
    }
    if (const std::string* k = get("kinds")) {
      h.kinds = words(*k);
      if (int(h.kinds.size()) != h.dimension) fail("kinds lists the wrong number of axes", "kinds");
    }
    if (const std::string* c = get("content")) h.content = *c;
    if (const std::string* d = get("datafile")) {
      h.dataFile = *d;
      if (h.dataFile.rfind("LIST", 0) == 0 || words(h.dataFile).size() != 1)
        fail("data spread over several files ('" + h.dataFile.substr(0, 60) + "') is not read: join them into one", "datafile");
    }
    for (const auto& [name, target] : {std::pair<const char*, std::int64_t*>{"lineskip", &h.lineSkip}, {"byteskip", &h.byteSkip}})
      if (const std::string* s = get(name)) {
        const double v = number(*s, name);
        if (v != std::floor(v) || v < -1 || v > 1e15) fail(std::string(name) + " must be a whole number", name);
        *target = std::int64_t(v);
      }
    if (h.lineSkip < 0) fail("line skip must not be negative", "lineskip");
    if (h.byteSkip == -1 && h.encoding != Encoding::Raw) fail("byte skip -1 (data at the end) is for raw data only", "byteskip");
  }

  const std::string& path_;
  std::istream& in_;
  std::uint64_t consumed_ = 0;
  std::int64_t lineNumber_ = 0;
  std::map<std::string, std::int64_t> lines_;
};

// ---- samples ------------------------------------------------------------------------

template <typename T>
T loadSample(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

double sampleValue(const unsigned char* p, const SampleType& t, bool swap) {
  if (t.isFloat) return t.bytes == 4 ? double(loadSample<float>(p, swap)) : loadSample<double>(p, swap);
  switch (t.bytes) {
    case 1: return t.isSigned ? double(std::int8_t(*p)) : double(*p);
    case 2: return t.isSigned ? double(loadSample<std::int16_t>(p, swap)) : double(loadSample<std::uint16_t>(p, swap));
    case 4: return t.isSigned ? double(loadSample<std::int32_t>(p, swap)) : double(loadSample<std::uint32_t>(p, swap));
    default: return t.isSigned ? double(loadSample<std::int64_t>(p, swap)) : double(loadSample<std::uint64_t>(p, swap));
  }
}

std::vector<double> decodeBytes(const std::string& bytes, std::size_t count, const Header& h) {
  const bool swap = h.bigEndian && *h.bigEndian != (std::endian::native == std::endian::big);
  std::vector<double> out(count);
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < count; ++i) out[i] = sampleValue(p + i * std::size_t(h.type.bytes), h.type, swap);
  return out;
}

// The samples in the file's own type (64-bit integers, which no texture or shader takes,
// as 64-bit floats): 1 or 2 bytes a voxel for the usual CT and seismic volumes.
SampleArray decodeSamples(const std::string& bytes, std::size_t count, const Header& h) {
  const bool swap = h.bigEndian && *h.bigEndian != (std::endian::native == std::endian::big);
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t size = std::size_t(h.type.bytes);
  const auto fill = [&](volpost::SampleType type, auto load) {
    SampleArray out(type, count);
    auto values = out.as<decltype(load(p))>();
    for (std::size_t i = 0; i < count; ++i) values[i] = load(p + i * size);
    return out;
  };
  using volpost::SampleType;
  if (h.type.isFloat) {
    if (size == 4) return fill(SampleType::Float32, [swap](const unsigned char* q) { return loadSample<float>(q, swap); });
    return fill(SampleType::Float64, [swap](const unsigned char* q) { return loadSample<double>(q, swap); });
  }
  const bool s = h.type.isSigned;
  switch (size) {
    case 1:
      if (s) return fill(SampleType::Int8, [](const unsigned char* q) { return std::int8_t(*q); });
      return fill(SampleType::UInt8, [](const unsigned char* q) { return std::uint8_t(*q); });
    case 2:
      if (s) return fill(SampleType::Int16, [swap](const unsigned char* q) { return loadSample<std::int16_t>(q, swap); });
      return fill(SampleType::UInt16, [swap](const unsigned char* q) { return loadSample<std::uint16_t>(q, swap); });
    case 4:
      if (s) return fill(SampleType::Int32, [swap](const unsigned char* q) { return loadSample<std::int32_t>(q, swap); });
      return fill(SampleType::UInt32, [swap](const unsigned char* q) { return loadSample<std::uint32_t>(q, swap); });
    default:
      return fill(SampleType::Float64, [&h, swap](const unsigned char* q) { return sampleValue(q, h.type, swap); });
  }
}

// Skips `lines` lines of the stream (the data's "line skip").
void skipLines(std::istream& in, std::int64_t lines, const std::string& path) {
  for (std::int64_t i = 0; i < lines; ++i) {
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    // Ended without the line's newline: nothing is left for the data.
    if (!in || in.eof())
      throw ReadError(path, "the data ends within the " + std::to_string(lines) + " line" + (lines == 1 ? "" : "s") +
                                " the header's line skip passes over (" + std::to_string(i) + " found)");
  }
}

struct DataSource {
  std::string path;        ///< the file holding the samples
  std::uint64_t offset;    ///< where the header or its skips leave off
};

// Deflate gives at most 1032 bytes for one (its longest match, 258 bytes, in two bits at
// best): more than that claimed from fewer compressed bytes is refused before the memory
// for it is taken.
constexpr double kMostDeflateExpansion = 1032.0;

// The samples from gzip data: concatenated gzip members are read one after the other, as
// gunzip does; `skip` decompressed bytes (the byte skip) are passed over first.
std::string gunzip(std::istream& in, std::uint64_t compressed, std::size_t needed, std::uint64_t skip,
                   const std::string& path) {
  if (double(compressed) * kMostDeflateExpansion < double(needed) + double(skip))
    throw ReadError(path, "its " + std::to_string(compressed) + " bytes of gzip data cannot hold the " +
                              std::to_string(needed) +
                              " bytes the header's sizes and type need (gzip compresses at "
                              "most 1032 to 1): the sizes are wrong or the data is cut short");
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) throw ReadError(path, "zlib could not start");
  std::string out(needed, '\0');
  std::vector<char> chunk(1 << 16), scratch(1 << 16);
  std::uint64_t toSkip = skip;
  std::size_t filled = 0;
  int status = Z_OK;
  while (filled < needed) {
    if (z.avail_in == 0) {
      in.read(chunk.data(), std::streamsize(chunk.size()));
      z.avail_in = uInt(in.gcount());
      z.next_in = reinterpret_cast<Bytef*>(chunk.data());
      if (z.avail_in == 0) break;
    }
    if (status == Z_STREAM_END) {  // another member follows the one that ended
      if (inflateReset(&z) != Z_OK) break;
      status = Z_OK;
    }
    char* target = toSkip > 0 ? scratch.data() : out.data() + filled;
    const std::size_t room = toSkip > 0 ? std::min<std::uint64_t>(scratch.size(), toSkip) : std::min<std::size_t>(needed - filled, 1u << 30);
    z.next_out = reinterpret_cast<Bytef*>(target);
    z.avail_out = uInt(room);
    status = inflate(&z, Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) {
      inflateEnd(&z);
      throw ReadError(path, std::string("the gzip data is damaged (") + (z.msg ? z.msg : "inflate failed") + ")");
    }
    const std::size_t produced = room - z.avail_out;
    if (toSkip > 0) toSkip -= produced;
    else filled += produced;
  }
  inflateEnd(&z);
  if (filled < needed)
    throw ReadError(path, "the gzip data ends after " + std::to_string(filled) + " of the " + std::to_string(needed) +
                              " bytes the header's sizes and type need");
  return out;
}

std::vector<double> readText(std::istream& in, std::size_t count, bool hex, const Header& h, const std::string& path) {
  std::vector<double> out;
  out.reserve(count);
  if (hex) {  // two hex digits per byte, whitespace anywhere
    std::string bytes;
    bytes.reserve(count * std::size_t(h.type.bytes));
    int high = -1;
    for (char c; bytes.size() < count * std::size_t(h.type.bytes) && in.get(c);) {
      if (std::isspace(static_cast<unsigned char>(c))) continue;
      if (!std::isxdigit(static_cast<unsigned char>(c))) throw ReadError(path, std::string("hex data holds '") + c + "'");
      const int v = std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : std::tolower(c) - 'a' + 10;
      if (high < 0) high = v;
      else {
        bytes += char(high * 16 + v);
        high = -1;
      }
    }
    if (bytes.size() < count * std::size_t(h.type.bytes))
      throw ReadError(path, "the hex data ends after " + std::to_string(bytes.size()) + " of " +
                                std::to_string(count * std::size_t(h.type.bytes)) + " bytes");
    return decodeBytes(bytes, count, h);
  }
  std::string word;
  while (out.size() < count && in >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (*end != '\0') throw ReadError(path, "text data holds '" + word.substr(0, 40) + "', which is not a number");
    out.push_back(v);
  }
  if (out.size() < count)
    throw ReadError(path, "the text data ends after " + std::to_string(out.size()) + " of the " + std::to_string(count) +
                              " values the header's sizes need");
  return out;
}

// The axes of the grid among the file's: the first axis holds components when there are 4.
struct Layout {
  int components = 1;
  std::array<int, 3> spatial{0, 1, 2};
};

Layout layoutOf(const Header& h, const std::string& path) {
  Layout l;
  if (h.dimension == 3) return l;
  if (h.dimension == 4) {
    const bool none = h.hasDirections && !h.directions[0];
    const bool kindSaysComponents = !h.kinds.empty() && h.kinds[0] != "domain" && h.kinds[0] != "space" && h.kinds[0] != "time";
    if ((none || kindSaysComponents || (!h.hasDirections && h.kinds.empty())) && h.sizes[0] >= 1 && h.sizes[0] <= kMaxComponents) {
      l.components = int(h.sizes[0]);
      l.spatial = {1, 2, 3};
      return l;
    }
    throw ReadError(path, "4 axes whose first is not up to " + std::to_string(kMaxComponents) +
                              " components of a value (a time series or a 4D image): volpost reads 3D volumes");
  }
  throw ReadError(path, "dimension " + std::to_string(h.dimension) +
                            (h.dimension < 3 ? ": an image or a line, not a volume" : ": volpost reads 3D volumes"));
}

RegularGrid gridOf(const Header& h, const Layout& l, const std::string& path) {
  RegularGrid grid;
  for (int a = 0; a < 3; ++a) {
    const int fa = l.spatial[std::size_t(a)];
    grid.dims[std::size_t(a)] = std::size_t(h.sizes[std::size_t(fa)]);
    if (h.hasDirections) {
      if (!h.directions[std::size_t(fa)])
        throw ReadError(path, "axis " + std::to_string(fa) + " holds samples in space but its space direction is 'none'");
      grid.axes[std::size_t(a)] = *h.directions[std::size_t(fa)];
    } else {
      double s = h.spacings.empty() ? 1.0 : h.spacings[std::size_t(fa)];
      if (std::isnan(s)) s = 1.0;
      if (!std::isfinite(s) || s == 0.0) throw ReadError(path, "axis " + std::to_string(fa) + " has spacing " + std::to_string(s));
      grid.axes[std::size_t(a)] = glm::dvec3(0.0);
      grid.axes[std::size_t(a)][a] = s;
    }
  }
  grid.origin = h.origin.value_or(glm::dvec3(0.0));
  grid.sampleStorage = h.type.words + " (NRRD " + h.encodingName +
                       (h.type.bytes > 1 && h.bigEndian ? (*h.bigEndian ? ", big-endian" : ", little-endian") : "") + ")";
  if (const std::string defect = grid.defect(); !defect.empty())
    throw ReadError(path, defect + " (sizes, space directions or spacings): volpost reads volumes");
  return grid;
}

std::string fieldName(const Header& h) {
  const std::string c = trim(h.content);
  if (!c.empty() && c.size() <= 60 && std::none_of(c.begin(), c.end(), [](char ch) { return ch == '\n'; })) return c;
  return "values";
}

}  // namespace

int NrrdReader::sniff(std::string_view head) const { return head.rfind("NRRD000", 0) == 0 ? 100 : 0; }

std::unique_ptr<Model> NrrdReader::read(const std::string& path, const Progress& progress) const {
  // Every byte is read through descriptors checked when opened (DiskFile): the data file is
  // never opened by name again, so the file read is the file checked.
  const auto headerFile = std::make_shared<const DiskFile>(path);
  DiskFileStream in(headerFile);
  const Header h = HeaderParser(path, in).run();
  const Layout layout = layoutOf(h, path);
  const RegularGrid grid = gridOf(h, layout, path);
  const std::size_t points = checkedProduct(checkedProduct(grid.dims[0], grid.dims[1], path, "the volume"), grid.dims[2], path, "the volume");
  const std::size_t count = checkedProduct(points, std::uint64_t(layout.components), path, "the volume's samples");
  const std::size_t bytes = checkedProduct(count, std::uint64_t(h.type.bytes), path, "the volume's data");
  // The samples (kept in their type; 64-bit integers as doubles) and a renderer's copy; the
  // grid holds no cells until something needs them (Model::mesh checks those).
  requireMemory(double(count) * double(std::max(h.type.bytes, 1)) + double(points) * kGridDrawingBytesPerPoint, path,
                "a volume of " + std::to_string(points) + " points and a renderer's copy of them");

  // Where the samples are: after the header, or in the data file beside the header.
  std::string dataPath = path;
  std::shared_ptr<const DiskFile> dataFile = headerFile;
  std::uint64_t start = h.dataOffset;
  if (!h.dataFile.empty()) {
    const std::filesystem::path named(h.dataFile);
    dataPath = (named.is_absolute() ? named : std::filesystem::path(path).parent_path() / named).string();
    try {
      dataFile = std::make_shared<const DiskFile>(dataPath);
    } catch (const ReadError& e) {
      throw ReadError(path, "its data file '" + h.dataFile + "': " + e.detail());
    }
    start = 0;
  }
  DiskFileStream data(dataFile, start);
  skipLines(data, h.lineSkip, dataPath);
  start = std::uint64_t(std::streamoff(data.tellg()));
  const std::uint64_t fileSize = dataFile->size();

  auto model = std::make_unique<Model>();
  model->title = trim(h.content);
  model->formatName = formatName();
  model->grid = grid;
  const int comps = layout.components;
  const std::string name = fieldName(h);
  if (h.encoding == Encoding::Raw) {
    // Checked now, read when first shown: a file too short for its header is refused at once.
    const std::uint64_t offset = h.byteSkip == -1 ? (fileSize >= bytes ? fileSize - bytes : 0) : start + std::uint64_t(h.byteSkip);
    if (fileSize < bytes || offset + bytes > fileSize)
      throw ReadError::atOffset(dataPath, fileSize, "the data ends after " + std::to_string(fileSize > offset ? fileSize - offset : 0) +
                                                        " of the " + std::to_string(bytes) + " bytes the header's sizes and type (" +
                                                        h.typeName + ") need");
    // Read from the descriptor opened now (DiskFile refuses a file changed since).
    SampleLoader loader = [dataFile, offset, bytes, count, h](std::size_t) {
      return decodeSamples(dataFile->readString(offset, bytes), count, h);
    };
    model->fields.push_back(Field::fromSamples(name, FieldLocation::Node, comps, points, std::vector<Step>{{"", 0.0}},
                                               std::move(loader)));
  } else {
    // Text, hex and gzip are decoded now: their length is known only by reading them.
    if (h.encoding == Encoding::Gzip) {
      const std::uint64_t compressed = fileSize - std::min(fileSize, start);
      SampleArray samples = decodeSamples(
          gunzip(data, compressed, bytes, std::uint64_t(std::max<std::int64_t>(h.byteSkip, 0)), dataPath), count, h);
      model->fields.push_back(Field::fromSamples(name, FieldLocation::Node, comps, std::move(samples)));
    } else {
      if (h.byteSkip > 0) data.seekg(std::streamoff(start + std::uint64_t(h.byteSkip)));
      std::vector<double> values = readText(data, count, h.encoding == Encoding::Hex, h, dataPath);
      std::vector<std::vector<double>> steps;
      steps.push_back(std::move(values));  // not {std::move(values)}: a braced list copies
      model->fields.push_back(Field::fromValues(name, FieldLocation::Node, comps, std::move(steps)));
    }
  }
  progress.report(1.0);
  return model;
}

}  // namespace volpost::meshio
