#include "io/point_cloud_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <type_traits>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "io/atomic_output_file.h"
#include "io/las_io.h"
#include "io/pcd_io.h"

namespace lpd::io {
namespace {

using energy::Point3;
using energy::PointList;

[[noreturn]] void Fail(const std::string& path, long line, const std::string& reason) {
  if (line > 0) throw std::runtime_error(path + ":" + std::to_string(line) + ": " + reason);
  throw std::runtime_error(path + ": " + reason);
}

// Moves `in` past a UTF-8 byte-order mark (which Windows editors write); UTF-16 text is
// refused by name rather than as a malformed first line. Looks at one byte at a time without
// consuming it, so that pipes and devices, which cannot seek back, lose nothing.
void SkipByteOrderMark(const std::string& path, std::istream& in) {
  std::streambuf* buffer = in.rdbuf();
  const int first = buffer->sgetc();
  if (first == 0xEF) {
    buffer->sbumpc();
    if (buffer->sgetc() == 0xBB) {
      buffer->sbumpc();
      if (buffer->sgetc() == 0xBF) {
        buffer->sbumpc();
        return;
      }
    }
    Fail(path, 1, "starts with a broken UTF-8 byte-order mark (not a text point file?)");
  }
  if (first == 0xFF || first == 0xFE) {
    buffer->sbumpc();
    const int second = buffer->sgetc();
    if ((first == 0xFF && second == 0xFE) || (first == 0xFE && second == 0xFF)) {
      Fail(path, 1, "UTF-16 text is not supported (save the file as UTF-8 or ASCII)");
    }
    Fail(path, 1, "starts with a byte that no text or PLY file starts with");
  }
}

// Longer lines are refused rather than buffered: a text file has short lines, and a device
// or binary file read as text (/dev/zero, say) would otherwise fill the memory.
constexpr size_t kMaxLineBytes = 1 << 16;

// std::getline with that bound; `number` is the number of the line read.
bool ReadLine(const std::string& path, std::istream& in, std::string* line, long number) {
  line->clear();
  std::streambuf* buffer = in.rdbuf();
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      if (line->empty()) {
        in.setstate(std::ios::eofbit | std::ios::failbit);
        return false;
      }
      in.setstate(std::ios::eofbit);
      return true;
    }
    if (c == '\n') return true;
    if (line->size() == kMaxLineBytes) {
      Fail(path, number, "line longer than " + std::to_string(kMaxLineBytes) +
                             " bytes (not a text point file?)");
    }
    line->push_back(static_cast<char>(c));
  }
}

// The start of `line` for a message, with unprintable bytes shown as '?'.
std::string Excerpt(const std::string& line) {
  std::string excerpt = line.substr(0, 60);
  for (char& c : excerpt) {
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  }
  return excerpt;
}

// Moves `text` past blanks and at most one column separator (a comma or a semicolon, as CSV
// exports write them) with the blanks after it.
const char* SkipSeparator(const char* text) {
  while (*text == ' ' || *text == '\t' || *text == '\r') ++text;
  if (*text == ',' || *text == ';') {
    ++text;
    while (*text == ' ' || *text == '\t' || *text == '\r') ++text;
  }
  return text;
}

// Parses the first three numbers of `text` into `p`; false if there are fewer than three.
bool ParseThreeNumbers(const char* text, Point3* p, const char** rest = nullptr) {
  const char* cursor = text;
  for (int c = 0; c < 3; ++c) {
    cursor = SkipSeparator(cursor);
    char* end = nullptr;
    const double value = std::strtod(cursor, &end);
    if (end == cursor) return false;
    (*p)[c] = value;
    cursor = end;
  }
  if (rest) *rest = cursor;
  return true;
}

void CheckFinite(const std::string& path, long line, const Point3& p) {
  if (!p.allFinite()) Fail(path, line, "non-finite coordinate (NaN or infinity)");
}

bool IsBlankOrComment(const std::string& line) {
  for (char c : line) {
    if (c == '#') return true;
    if (!std::isspace(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

constexpr char kNoPoints[] = "the file contains no points";

// The extensions of point text files (x y z per line, ReadXyz).
bool IsXyz(const std::string& extension) {
  return extension == "xyz" || extension == "txt" || extension == "pts" || extension == "csv";
}

// The column names of a CSV-style header line ("x,y,z,intensity", "//X,Y,Z,R,G,B" as
// CloudCompare writes it, "\"X\",\"Y\",\"Z\"" as PDAL does): at least three fields of printable
// characters, each starting with a letter or an underscore once quotes and a leading "//"
// are taken off; other characters than letters, digits and underscores become underscores.
// False for any other line.
bool ParseHeaderLine(const std::string& line, std::vector<std::string>* names) {
  names->clear();
  std::string text = line;
  const size_t start = text.find_first_not_of(" \t");
  if (start != std::string::npos && text.compare(start, 2, "//") == 0) text.erase(0, start + 2);
  std::string field;
  auto finish = [&] {
    field.erase(std::remove(field.begin(), field.end(), '"'), field.end());
    if (field.empty()) return false;
    const unsigned char first = static_cast<unsigned char>(field[0]);
    if (!std::isalpha(first) && first != '_') return false;
    for (char& c : field) {  // a name that the PLY and PCD writers can carry
      if (!std::isprint(static_cast<unsigned char>(c))) return false;
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    names->push_back(field);
    field.clear();
    return true;
  };
  for (const char c : text) {
    if (c == ' ' || c == '\t' || c == '\r' || c == ',' || c == ';') {
      if (!field.empty() && !finish()) return false;
      continue;
    }
    field.push_back(c);
  }
  if (!field.empty() && !finish()) return false;
  return names->size() >= 3;
}

// Whether `line` holds one whole number and nothing else: the point count that Leica's PTS
// files start with.
bool IsPointCountLine(const std::string& line) {
  const size_t begin = line.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return false;
  const size_t end = line.find_last_not_of(" \t\r") + 1;
  return std::all_of(line.begin() + begin, line.begin() + end,
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// The next point line of an XYZ file (past blank and comment lines, `number` counting the
// lines read): its point p and `rest` pointing past x y z in *line; false at the end. With
// `header`, a first content line of column names is read into it, and a first line with a
// point count (PTS) skipped, instead of failing.
bool NextXyzPoint(const std::string& path, std::istream& in, std::string* line, long* number,
                  Point3* p, const char** rest, std::vector<std::string>* header = nullptr) {
  while (ReadLine(path, in, line, *number + 1)) {
    ++*number;
    if (IsBlankOrComment(*line)) continue;
    if (!ParseThreeNumbers(line->c_str(), p, rest)) {
      if (header && (IsPointCountLine(*line) || ParseHeaderLine(*line, header))) {
        header = nullptr;  // one line at most
        continue;
      }
      Fail(path, *number, "expected three numbers 'x y z', got '" + Excerpt(*line) + "'");
    }
    CheckFinite(path, *number, *p);
    return true;
  }
  return false;
}

// Calls visit(p, rest) for every point line of an XYZ file, `rest` pointing past x y z; the
// names of a header line before the first point go to `header` (empty without one).
template <class Visit>
void VisitXyz(const std::string& path, std::istream& in, Visit visit,
              std::vector<std::string>* header = nullptr) {
  std::string line;
  long number = 0;
  Point3 p;
  const char* rest = nullptr;
  std::vector<std::string> names;
  if (!NextXyzPoint(path, in, &line, &number, &p, &rest, &names)) return;
  if (header) *header = names;
  do {
    visit(p, rest);
  } while (NextXyzPoint(path, in, &line, &number, &p, &rest));
}

// The names of the `columns` columns of an XYZ file past x y z: the header's, when the
// header names every column once, else column_4, column_5, ... (counting x as 1).
std::vector<std::string> XyzColumnNames(const std::vector<std::string>& header,
                                        size_t columns) {
  std::vector<std::string> sorted = header;
  std::sort(sorted.begin(), sorted.end());
  if (header.size() == columns + 3 &&
      std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) {
    return std::vector<std::string>(header.begin() + 3, header.end());
  }
  std::vector<std::string> names;
  for (size_t c = 0; c < columns; ++c) names.push_back("column_" + std::to_string(c + 4));
  return names;
}

// The numbers of `text` (the columns after x y z); false if one is not a number.
bool ParseColumns(const char* text, std::vector<double>* columns) {
  columns->clear();
  for (;;) {
    text = SkipSeparator(text);
    if (*text == '\0' || *text == '#') return true;
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text) return false;
    columns->push_back(value);
    text = end;
  }
}

// Columns 4-6 are read as normals when every line has them and they are unit vectors (as
// "x y z nx ny nz" exports are). The other columns (all of them after x y z when they are no
// normals) become attributes when every line has the same number of them, all numbers
// (named by a header line, else column_4, column_5, ...); otherwise they are ignored.
PointCloud ReadXyz(const std::string& path, std::istream& in) {
  PointCloud cloud;
  bool normals_on_every_line = true;
  bool same_columns_on_every_line = true;
  std::vector<std::vector<double>> columns;  // per column, one value per point
  std::vector<double> line_columns;
  std::vector<std::string> header;
  VisitXyz(path, in, [&](const Point3& p, const char* rest) {
    cloud.points.push_back(p);
    if (normals_on_every_line) {
      Point3 n;
      normals_on_every_line =
          ParseThreeNumbers(rest, &n) && n.allFinite() && std::abs(n.norm() - 1.0) < 0.01;
      if (normals_on_every_line) cloud.normals.push_back(n);
    }
    if (!same_columns_on_every_line) return;
    if (!ParseColumns(rest, &line_columns) ||
        (cloud.points.size() > 1 && line_columns.size() != columns.size())) {
      same_columns_on_every_line = false;
      columns.clear();
      return;
    }
    if (cloud.points.size() == 1) columns.resize(line_columns.size());
    for (size_t c = 0; c < line_columns.size(); ++c) columns[c].push_back(line_columns[c]);
  }, &header);
  if (!normals_on_every_line) cloud.normals.clear();
  const size_t first = cloud.normals.empty() ? 0 : 3;  // normals are no attribute
  const std::vector<std::string> names = XyzColumnNames(header, columns.size());
  for (size_t c = first; c < columns.size(); ++c) {
    cloud.attributes.push_back({names[c], "double", std::move(columns[c])});
  }
  return cloud;
}

PointList ReadObj(const std::string& path, std::istream& in) {
  PointList points;
  std::string line;
  long number = 0;
  while (ReadLine(path, in, &line, number + 1)) {
    ++number;
    if (line.size() < 2 || line[0] != 'v' || !std::isspace(static_cast<unsigned char>(line[1]))) {
      continue;
    }
    Point3 p;
    if (!ParseThreeNumbers(line.c_str() + 1, &p)) Fail(path, number, "malformed vertex line");
    CheckFinite(path, number, p);
    points.push_back(p);
  }
  return points;
}

// Reads the next line that is not blank or a comment; false at end of file.
bool NextContentLine(const std::string& path, std::istream& in, std::string* line,
                     long* number) {
  while (ReadLine(path, in, line, *number + 1)) {
    ++*number;
    if (!IsBlankOrComment(*line)) return true;
  }
  return false;
}

// The numbers of `line`; false if a token is not one.
bool ParseNumbers(const std::string& line, std::vector<double>* numbers) {
  numbers->clear();
  std::istringstream tokens(line);
  std::string token;
  while (tokens >> token) {
    if (token[0] == '#') break;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (*end != '\0') return false;
    numbers->push_back(value);
  }
  return true;
}

// OFF and its variants by the header keyword [ST][C][N][4][n]OFF: ST adds 2 texture numbers
// to each vertex, C a colour (3 or 4 numbers), N a normal (3), 4 a homogeneous w that
// divides x y z, n a line with the dimension (only 3 is read). Each vertex line must hold
// exactly those numbers, so that a header claiming more vertices than the file has cannot
// read face lines ("3 0 1 2") as points. Binary OFF is refused.
PointList ReadOff(const std::string& path, std::istream& in) {
  std::string line;
  long number = 0;
  if (!NextContentLine(path, in, &line, &number)) Fail(path, 0, "empty file");
  std::istringstream header(line);
  std::string magic;
  header >> magic;
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) {
    Fail(path, number, "not an OFF file (first token '" + magic + "')");
  }
  std::string prefix = magic.substr(0, magic.size() - 3);
  auto take = [&prefix](const std::string& flag) {
    if (prefix.rfind(flag, 0) != 0) return false;
    prefix.erase(0, flag.size());
    return true;
  };
  const bool texture = take("ST");
  const bool colour = take("C");
  const bool normal = take("N");
  const bool homogeneous = take("4");
  const bool dimension_line = take("n");
  if (!prefix.empty()) Fail(path, number, "unknown OFF variant '" + magic + "'");
  if (line.find("BINARY") != std::string::npos) {
    Fail(path, number, "binary OFF is not supported");
  }
  if (dimension_line) {
    long dimension = 0;
    if (!(header >> dimension)) {
      if (!NextContentLine(path, in, &line, &number)) Fail(path, number, "missing dimension");
      header = std::istringstream(line);
      header >> dimension;
    }
    if (dimension != 3) {
      Fail(path, number, "nOFF of dimension " + std::to_string(dimension) +
                             " is not supported (3 is)");
    }
  }
  long num_vertices = -1;
  if (!(header >> num_vertices)) {
    if (!NextContentLine(path, in, &line, &number)) Fail(path, number, "missing vertex count");
    std::istringstream counts(line);
    counts >> num_vertices;
  }
  if (num_vertices < 0) Fail(path, number, "malformed vertex/face counts");
  const size_t coordinates = homogeneous ? 4 : 3;
  const size_t fixed = coordinates + (normal ? 3 : 0) + (texture ? 2 : 0);
  PointList points;
  // The header's count is a claim, not a size to allocate (found by the OFF fuzzer: a count
  // of 2.7e15 asked for 64 PB); past this, the list grows as vertices arrive.
  points.reserve(std::min<long>(num_vertices, 1 << 20));
  std::vector<double> numbers;
  for (long v = 0; v < num_vertices; ++v) {
    if (!NextContentLine(path, in, &line, &number)) {
      Fail(path, number, "file ends after " + std::to_string(v) + " of " +
                             std::to_string(num_vertices) + " vertices");
    }
    const bool counted = ParseNumbers(line, &numbers) &&
                         (numbers.size() == fixed ||
                          (colour && (numbers.size() == fixed + 3 || numbers.size() == fixed + 4)));
    if (!counted) {
      Fail(path, number, "vertex line with " + std::to_string(numbers.size()) +
                             " numbers where " + magic + " has " + std::to_string(fixed) +
                             (colour ? " plus a colour" : "") +
                             " (does the header claim more vertices than the file has?)");
    }
    Point3 p(numbers[0], numbers[1], numbers[2]);
    if (homogeneous) {
      if (numbers[3] == 0.0) Fail(path, number, "vertex at infinity (w = 0)");
      p /= numbers[3];
    }
    CheckFinite(path, number, p);
    points.push_back(p);
  }
  return points;
}

// ---- PLY ----

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

// PLY's scalar types, each under its two names (char / int8, ...).
enum class PlyScalar { kUnknown, kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32,
                       kFloat64 };

// Each type's names, its canonical one (what lpd writes) first.
constexpr std::pair<const char*, PlyScalar> kPlyScalarNames[] = {
    {"char", PlyScalar::kInt8},     {"int8", PlyScalar::kInt8},
    {"uchar", PlyScalar::kUInt8},   {"uint8", PlyScalar::kUInt8},
    {"short", PlyScalar::kInt16},   {"int16", PlyScalar::kInt16},
    {"ushort", PlyScalar::kUInt16}, {"uint16", PlyScalar::kUInt16},
    {"int", PlyScalar::kInt32},     {"int32", PlyScalar::kInt32},
    {"uint", PlyScalar::kUInt32},   {"uint32", PlyScalar::kUInt32},
    {"float", PlyScalar::kFloat32}, {"float32", PlyScalar::kFloat32},
    {"double", PlyScalar::kFloat64}, {"float64", PlyScalar::kFloat64}};

PlyScalar PlyScalarOf(const std::string& type) {
  for (const auto& [name, scalar] : kPlyScalarNames) {
    if (type == name) return scalar;
  }
  return PlyScalar::kUnknown;
}

int PlyScalarSize(PlyScalar scalar) {
  switch (scalar) {
    case PlyScalar::kInt8: case PlyScalar::kUInt8: return 1;
    case PlyScalar::kInt16: case PlyScalar::kUInt16: return 2;
    case PlyScalar::kInt32: case PlyScalar::kUInt32: case PlyScalar::kFloat32: return 4;
    case PlyScalar::kFloat64: return 8;
    case PlyScalar::kUnknown: break;
  }
  return 0;
}

struct PlyProperty {
  std::string name;
  std::string type;        // scalar type, or the item type of a list
  std::string count_type;  // list count type; empty for scalars
  // The two types parsed once, for the body's values.
  PlyScalar scalar = PlyScalar::kUnknown;
  PlyScalar count_scalar = PlyScalar::kUnknown;
};

struct PlyElement {
  std::string name;
  long count = 0;
  std::vector<PlyProperty> properties;
};

int PlyTypeSize(const std::string& type) { return PlyScalarSize(PlyScalarOf(type)); }

bool PlyTypeIsInteger(const std::string& type) {
  const PlyScalar scalar = PlyScalarOf(type);
  return scalar != PlyScalar::kUnknown && scalar != PlyScalar::kFloat32 &&
         scalar != PlyScalar::kFloat64;
}

// The value of type T in `bytes`.
template <typename T>
double FromBytes(const unsigned char* bytes) {
  T x;
  std::memcpy(&x, bytes, sizeof(T));
  return static_cast<double>(x);
}

// Reads one binary value of a known `scalar` type and returns it as a double.
double ReadBinaryValue(std::istream& in, PlyScalar scalar, bool swap) {
  unsigned char bytes[8];
  const int size = PlyScalarSize(scalar);
  if (!in.read(reinterpret_cast<char*>(bytes), size)) {
    throw std::runtime_error("truncated binary data");
  }
  if (swap) std::reverse(bytes, bytes + size);
  switch (scalar) {
    case PlyScalar::kInt8: return FromBytes<int8_t>(bytes);
    case PlyScalar::kUInt8: return FromBytes<uint8_t>(bytes);
    case PlyScalar::kInt16: return FromBytes<int16_t>(bytes);
    case PlyScalar::kUInt16: return FromBytes<uint16_t>(bytes);
    case PlyScalar::kInt32: return FromBytes<int32_t>(bytes);
    case PlyScalar::kUInt32: return FromBytes<uint32_t>(bytes);
    case PlyScalar::kFloat32: return FromBytes<float>(bytes);
    case PlyScalar::kFloat64: case PlyScalar::kUnknown: break;
  }
  return FromBytes<double>(bytes);
}

// The fewest bytes one item of `element` takes: its scalars and list counts in binary, a
// digit and a separator per scalar or list count in ascii (lists may be empty).
uint64_t SmallestItemBytes(const PlyElement& element, PlyFormat format) {
  uint64_t bytes = 0;
  for (const PlyProperty& property : element.properties) {
    if (format == PlyFormat::kAscii) {
      bytes += 2;
    } else {
      bytes += PlyTypeSize(property.count_type.empty() ? property.type : property.count_type);
    }
  }
  return std::max<uint64_t>(bytes, 1);
}

// Refuses a header whose element counts (up to the vertex element, the last one read) need
// more bytes than the body has, before anything is allocated for them.
void CheckPlyCountsFitBody(const std::string& path, PlyFormat format,
                           const std::vector<PlyElement>& elements, std::istream* in) {
  uint64_t body_bytes = 0;  // a header that ends the file leaves an empty body
  if (!in->eof()) {
    // A pipe or device cannot seek (and a failed seek would drop its buffered bytes): the
    // reads check as they go.
    const std::streampos body_start = in->tellg();
    if (body_start < 0) {
      in->clear();
      return;
    }
    in->seekg(0, std::ios::end);
    const std::streampos end = in->tellg();
    in->clear();
    in->seekg(body_start);
    if (end < body_start) return;
    body_bytes = static_cast<uint64_t>(end - body_start);
  }
  uint64_t needed = 0;
  for (const PlyElement& element : elements) {
    const uint64_t item = SmallestItemBytes(element, format);
    const uint64_t available = body_bytes > needed ? body_bytes - needed : 0;
    if (static_cast<uint64_t>(element.count) > available / item) {
      Fail(path, 0, "the header declares " + std::to_string(element.count) + " '" +
                        element.name + "' items but the remaining " +
                        std::to_string(available) + " bytes hold at most " +
                        std::to_string(available / item));
    }
    needed += static_cast<uint64_t>(element.count) * item;
    if (element.name == "vertex") break;
  }
}

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  long lines = 0;  // up to and including end_header
};

// One property line of the header ("property TYPE NAME" or "property list COUNT TYPE NAME").
PlyProperty ParsePlyProperty(const std::string& path, long number, std::istream& tokens) {
  PlyProperty property;
  std::string type;
  tokens >> type;
  if (type == "list") {
    tokens >> property.count_type >> property.type;
    if (!PlyTypeIsInteger(property.count_type)) {
      Fail(path, number, "list count type must be an integer type, got '" +
                             Excerpt(property.count_type) + "'");
    }
  } else {
    property.type = type;
  }
  if (!(tokens >> property.name)) Fail(path, number, "malformed property line");
  property.scalar = PlyScalarOf(property.type);
  if (property.scalar == PlyScalar::kUnknown) {
    Fail(path, number, "unknown property type '" + Excerpt(property.type) + "'");
  }
  if (!property.count_type.empty()) property.count_scalar = PlyScalarOf(property.count_type);
  return property;
}

PlyHeader ReadPlyHeader(const std::string& path, std::istream& in) {
  std::string line;
  if (!ReadLine(path, in, &line, 1) || line.rfind("ply", 0) != 0) {
    Fail(path, 1, "not a PLY file (missing 'ply' magic)");
  }
  PlyHeader header;
  header.lines = 1;
  bool has_format = false;
  while (ReadLine(path, in, &line, header.lines + 1)) {
    const long number = ++header.lines;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "format") {
      std::string name;
      tokens >> name;
      if (name == "ascii") header.format = PlyFormat::kAscii;
      else if (name == "binary_little_endian") header.format = PlyFormat::kBinaryLittleEndian;
      else if (name == "binary_big_endian") header.format = PlyFormat::kBinaryBigEndian;
      else Fail(path, number, "unknown PLY format '" + name + "'");
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      if (!(tokens >> element.name >> element.count) || element.count < 0) {
        Fail(path, number, "malformed element line");
      }
      header.elements.push_back(element);
    } else if (keyword == "property") {
      if (header.elements.empty()) Fail(path, number, "property before any element");
      header.elements.back().properties.push_back(ParsePlyProperty(path, number, tokens));
    } else if (keyword == "end_header") {
      if (!has_format) Fail(path, number, "PLY header has no format line");
      return header;
    } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
      Fail(path, number, "unknown PLY header keyword '" + keyword + "'");
    }
  }
  Fail(path, header.lines, "PLY header has no end_header");
}

// Where the vertex element keeps x, y, z, the normal (all three or none) and every other
// scalar property (the attributes).
struct VertexLayout {
  int xyz[3] = {-1, -1, -1};
  int normal[3] = {-1, -1, -1};
  std::vector<size_t> attributes;

  bool has_normals() const { return normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0; }
};

VertexLayout LayoutOf(const std::string& path, const PlyElement& vertex) {
  VertexLayout layout;
  const char* kNames[2][3] = {{"x", "y", "z"}, {"nx", "ny", "nz"}};
  for (size_t a = 0; a < vertex.properties.size(); ++a) {
    const PlyProperty& property = vertex.properties[a];
    for (size_t b = 0; b < a; ++b) {
      if (vertex.properties[b].name == property.name) {
        Fail(path, 0, "the vertex element has two properties named '" + property.name + "'");
      }
    }
    bool placed = false;
    for (int c = 0; c < 3; ++c) {
      for (int kind = 0; kind < 2; ++kind) {
        if (property.name != kNames[kind][c]) continue;
        if (!property.count_type.empty()) {
          Fail(path, 0, "the vertex property '" + property.name + "' is a list, not a number");
        }
        (kind == 0 ? layout.xyz : layout.normal)[c] = static_cast<int>(a);
        placed = true;
      }
    }
    if (!placed && property.count_type.empty()) layout.attributes.push_back(a);
  }
  if (layout.xyz[0] < 0 || layout.xyz[1] < 0 || layout.xyz[2] < 0) {
    Fail(path, 0, "the vertex element has no x, y, z properties");
  }
  return layout;
}

// Reads item `item` of `element` into `values` (one per property; a list keeps its last
// value). `number` counts the lines read so far (ascii).
void ReadPlyItem(const std::string& path, std::istream& in, PlyFormat format,
                 const PlyElement& element, long item, long* number,
                 std::vector<double>* values) {
  if (format == PlyFormat::kAscii) {
    std::string line;
    if (!ReadLine(path, in, &line, *number + 1)) {
      Fail(path, *number, "file ends inside element '" + element.name + "'");
    }
    ++*number;
    std::istringstream tokens(line);
    for (size_t a = 0; a < element.properties.size(); ++a) {
      long count = 1;
      if (!element.properties[a].count_type.empty() && !(tokens >> count)) count = -1;
      if (count < 0) Fail(path, *number, "malformed list");
      for (long c = 0; c < count; ++c) {
        std::string token;
        if (!(tokens >> token)) Fail(path, *number, "too few values on line");
        char* end = nullptr;
        (*values)[a] = std::strtod(token.c_str(), &end);
        if (*end != '\0') Fail(path, *number, "malformed number '" + token + "'");
      }
    }
    return;
  }
  const bool swap = (format == PlyFormat::kBinaryBigEndian) == HostIsLittleEndian();
  try {
    for (size_t a = 0; a < element.properties.size(); ++a) {
      const PlyProperty& property = element.properties[a];
      if (property.count_type.empty()) {
        (*values)[a] = ReadBinaryValue(in, property.scalar, swap);
        continue;
      }
      const long count = static_cast<long>(ReadBinaryValue(in, property.count_scalar, swap));
      for (long c = 0; c < count; ++c) ReadBinaryValue(in, property.scalar, swap);
    }
  } catch (const std::runtime_error&) {
    Fail(path, 0, "binary data ends inside element '" + element.name + "' (item " +
                      std::to_string(item) + " of " + std::to_string(element.count) + ")");
  }
}

// The vertex element as a PointCloud: x, y, z; nx, ny, nz as normals when all three exist;
// every other scalar property as a named scalar. Elements before it are read and skipped.
// Calls start(layout) once, then visit(values) for every vertex (its property values, in
// the header's order), after checking its coordinates are finite.
template <class Start, class Visit>
void VisitPly(const std::string& path, std::istream& in, Start start, Visit visit) {
  const PlyHeader header = ReadPlyHeader(path, in);
  CheckPlyCountsFitBody(path, header.format, header.elements, &in);
  long number = header.lines;
  for (const PlyElement& element : header.elements) {
    std::vector<double> values(element.properties.size());
    if (element.name != "vertex") {
      if (element.properties.empty()) continue;  // nothing to read, however many items
      for (long item = 0; item < element.count; ++item) {
        ReadPlyItem(path, in, header.format, element, item, &number, &values);
      }
      continue;
    }
    const VertexLayout layout = LayoutOf(path, element);
    start(element, layout);
    for (long item = 0; item < element.count; ++item) {
      ReadPlyItem(path, in, header.format, element, item, &number, &values);
      if (!Point3(values[layout.xyz[0]], values[layout.xyz[1]], values[layout.xyz[2]])
               .allFinite()) {
        Fail(path, header.format == PlyFormat::kAscii ? number : 0,
             "vertex " + std::to_string(item) + " has a non-finite coordinate");
      }
      visit(layout, values);
    }
    return;
  }
}

PointCloud ReadPly(const std::string& path, std::istream& in) {
  PointCloud cloud;
  auto start = [&](const PlyElement& vertex, const VertexLayout& layout) {
    for (size_t a : layout.attributes) {
      cloud.attributes.push_back(
          {vertex.properties[a].name, CanonicalPlyType(vertex.properties[a].type), {}});
    }
    cloud.points.reserve(vertex.count);
  };
  auto visit = [&](const VertexLayout& layout, const std::vector<double>& values) {
    cloud.points.emplace_back(values[layout.xyz[0]], values[layout.xyz[1]],
                              values[layout.xyz[2]]);
    if (layout.has_normals()) {
      cloud.normals.emplace_back(values[layout.normal[0]], values[layout.normal[1]],
                                 values[layout.normal[2]]);
    }
    for (size_t a = 0; a < layout.attributes.size(); ++a) {
      PointAttribute& attribute = cloud.attributes[a];
      const double value = values[layout.attributes[a]];
      // An ascii float holds what a binary one would: the value rounded to float.
      attribute.values.push_back(attribute.type == "float" ? static_cast<float>(value) : value);
    }
  };
  VisitPly(path, in, start, visit);
  return cloud;
}

}  // namespace

std::string FileExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = path.substr(dot + 1);
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

namespace {

// The format of `path`: `format` when given, else its extension; "-" needs `format`.
std::string InputFormat(const std::string& path, const std::string& format) {
  if (!format.empty()) return format;
  if (path == kStandardStream) {
    throw std::runtime_error("reading standard input ('-') needs --input_format (xyz, csv, "
                             "ply, las, pcd, off or obj)");
  }
  return FileExtension(path);
}

// The file at `path` opened for reading, or a one-line error naming why it cannot be.
std::ifstream OpenInput(const std::string& path) {
  if (path.empty()) throw std::runtime_error("the input file name is empty");
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) Fail(path, 0, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, 0, "cannot open file (missing or unreadable)");
  return in;
}

}  // namespace

PointCloud ReadPointCloud(const std::string& path, const std::string& format) {
  const std::string extension = InputFormat(path, format);
  if (path == kStandardStream) return ReadPointCloud(std::cin, extension, "standard input");
  std::ifstream in = OpenInput(path);
  return ReadPointCloud(in, extension, path);
}

PointCloud ReadPointCloud(std::istream& in, const std::string& extension,
                          const std::string& name) {
  SkipByteOrderMark(name, in);
  PointCloud cloud;
  if (IsXyz(extension)) {
    cloud = ReadXyz(name, in);
  } else if (extension == "ply") {
    cloud = ReadPly(name, in);
  } else if (extension == "off") {
    cloud.points = ReadOff(name, in);
  } else if (extension == "obj") {
    cloud.points = ReadObj(name, in);
  } else if (extension == "las" || extension == "laz") {
    cloud = ReadLas(name, in);
  } else if (extension == "pcd") {
    cloud = ReadPcd(name, in);
  } else {
    Fail(name, 0, "unknown point-cloud format '." + extension +
                      "' (expected .xyz, .txt, .pts, .csv, .ply, .pcd, .off, .obj or .las)");
  }
  if (cloud.points.empty()) {
    Fail(name, 0, cloud.skipped_points > 0 ? "every point has a NaN coordinate (no return)"
                                           : kNoPoints);
  }
  return cloud;
}

PointList ReadPoints(const std::string& path) { return ReadPointCloud(path).points; }

const PointAttribute* PointCloud::FindAttribute(const std::string& name) const {
  for (const PointAttribute& attribute : attributes) {
    if (attribute.name == name) return &attribute;
  }
  return nullptr;
}

void ForEachPoint(const std::string& path, const std::function<void(const Point3&)>& visit) {
  const std::string extension = FileExtension(path);
  if (extension == "las") {
    std::ifstream in = OpenInput(path);
    const LasHeader header = ReadLasHeader(path, in);
    VisitLasRecords(path, in, header, [&](const Point3& p, const double*) { visit(p); });
    return;
  }
  if (!IsXyz(extension) && extension != "ply") {
    for (const Point3& p : ReadPoints(path)) visit(p);
    return;
  }
  std::ifstream in = OpenInput(path);
  SkipByteOrderMark(path, in);
  long count = 0;
  if (extension == "ply") {
    VisitPly(path, in, [](const PlyElement&, const VertexLayout&) {},
             [&](const VertexLayout& layout, const std::vector<double>& values) {
               visit(Point3(values[layout.xyz[0]], values[layout.xyz[1]], values[layout.xyz[2]]));
               ++count;
             });
  } else {
    VisitXyz(path, in, [&](const Point3& p, const char*) {
      visit(p);
      ++count;
    });
  }
  if (count == 0) Fail(path, 0, kNoPoints);
}

namespace {

// ReadXyz's rules for its columns: whether every line has unit normals in columns 4-6, and
// the number of columns when every line has as many (else -1).
struct XyzColumns {
  bool normals = true;
  long columns = -1;
  std::vector<std::string> header;  // the header line's names, if there is one
};

XyzColumns ReadXyzColumns(const std::string& path) {
  std::ifstream in = OpenInput(path);
  SkipByteOrderMark(path, in);
  XyzColumns found;
  bool same = true;
  long count = 0;
  std::vector<double> line_columns;
  VisitXyz(path, in, [&](const Point3&, const char* rest) {
    ++count;
    Point3 n;
    found.normals = found.normals && ParseThreeNumbers(rest, &n) && n.allFinite() &&
                    std::abs(n.norm() - 1.0) < 0.01;
    if (!same) return;
    same = ParseColumns(rest, &line_columns) &&
           (count == 1 || static_cast<long>(line_columns.size()) == found.columns);
    found.columns = static_cast<long>(line_columns.size());
  }, &found.header);
  if (count == 0) Fail(path, 0, kNoPoints);
  if (!same) found.columns = -1;
  return found;
}

// Whether the first point line of an XYZ file has a column past x y z.
bool FirstXyzLineHasColumns(const std::string& path) {
  std::ifstream in = OpenInput(path);
  SkipByteOrderMark(path, in);
  std::string line;
  long number = 0;
  Point3 p;
  const char* rest = nullptr;
  std::vector<double> columns;
  std::vector<std::string> header;
  return NextXyzPoint(path, in, &line, &number, &p, &rest, &header) &&
         (!ParseColumns(rest, &columns) || !columns.empty());
}

}  // namespace

std::vector<PointAttribute> StreamedAttributes(const std::string& path) {
  const std::string extension = FileExtension(path);
  std::vector<PointAttribute> attributes;
  if (extension == "ply") {
    std::ifstream in = OpenInput(path);
    SkipByteOrderMark(path, in);
    const PlyHeader header = ReadPlyHeader(path, in);
    for (const PlyElement& element : header.elements) {
      if (element.name != "vertex") continue;
      for (size_t a : LayoutOf(path, element).attributes) {
        attributes.push_back(
            {element.properties[a].name, CanonicalPlyType(element.properties[a].type), {}});
      }
    }
  } else if (extension == "las") {
    std::ifstream in = OpenInput(path);
    attributes = ReadLasHeader(path, in).attributes;
  } else if (IsXyz(extension)) {
    if (!FirstXyzLineHasColumns(path)) return attributes;
    const XyzColumns found = ReadXyzColumns(path);
    if (found.columns <= 0) return attributes;
    const std::vector<std::string> names =
        XyzColumnNames(found.header, static_cast<size_t>(found.columns));
    for (size_t c = found.normals ? 3 : 0; c < names.size(); ++c) {
      attributes.push_back({names[c], "double", {}});
    }
  } else {
    for (const PointAttribute& attribute : ReadPointCloud(path).attributes) {
      attributes.push_back({attribute.name, attribute.type, {}});
    }
  }
  return attributes;
}

void ForEachPointWithAttributes(
    const std::string& path, const std::vector<PointAttribute>& attributes,
    const std::function<void(const Point3&, const double*)>& visit) {
  const std::string extension = FileExtension(path);
  std::vector<double> values(attributes.size());
  auto check_count = [&](size_t found) {
    if (found != attributes.size()) Fail(path, 0, "the file changed while it was read");
  };
  long count = 0;
  if (extension == "ply") {
    std::ifstream in = OpenInput(path);
    SkipByteOrderMark(path, in);
    VisitPly(
        path, in,
        [&](const PlyElement&, const VertexLayout& layout) {
          check_count(layout.attributes.size());
        },
        [&](const VertexLayout& layout, const std::vector<double>& vertex) {
          for (size_t a = 0; a < attributes.size(); ++a) {
            const double value = vertex[layout.attributes[a]];
            // As ReadPly: an ascii float holds what a binary one would.
            values[a] = attributes[a].type == "float" ? static_cast<float>(value) : value;
          }
          visit(Point3(vertex[layout.xyz[0]], vertex[layout.xyz[1]], vertex[layout.xyz[2]]),
                values.data());
          ++count;
        });
  } else if (extension == "las") {
    std::ifstream in = OpenInput(path);
    const LasHeader header = ReadLasHeader(path, in);
    check_count(header.attributes.size());
    VisitLasRecords(path, in, header, [&](const Point3& p, const double* fields) {
      visit(p, fields);
      ++count;
    });
  } else if (IsXyz(extension)) {
    // The attributes are the last columns (after the normals, when there are some).
    std::vector<double> line_columns;
    size_t columns = 0;  // the first line's: every line has as many
    std::ifstream in = OpenInput(path);
    SkipByteOrderMark(path, in);
    VisitXyz(path, in, [&](const Point3& p, const char* rest) {
      if (!attributes.empty()) {
        const bool parsed = ParseColumns(rest, &line_columns);
        if (count == 0) columns = line_columns.size();
        if (!parsed || line_columns.size() != columns || columns < attributes.size()) {
          check_count(0);
        }
      }
      visit(p, attributes.empty()
                   ? nullptr
                   : line_columns.data() + (line_columns.size() - attributes.size()));
      ++count;
    });
  } else {
    const PointCloud cloud = ReadPointCloud(path);
    check_count(cloud.attributes.size());
    for (size_t i = 0; i < cloud.points.size(); ++i) {
      for (size_t a = 0; a < attributes.size(); ++a) values[a] = cloud.attributes[a].values[i];
      visit(cloud.points[i], values.data());
      ++count;
    }
  }
  if (count == 0) Fail(path, 0, kNoPoints);
}

std::string OutputFormat(const std::string& path, const std::string& format) {
  const std::string chosen = format.empty() ? FileExtension(path) : format;
  if (chosen == "ply" || chosen == "xyz" || chosen == "txt" || chosen == "csv" ||
      chosen == "las" || chosen == "pcd") {
    return chosen;
  }
  if (chosen == "laz") {
    throw std::runtime_error("cannot write '" + path + "': LAZ (compressed LAS) is not "
                             "supported; write .las and compress it with `laszip`");
  }
  if (path == kStandardStream && format.empty()) {
    throw std::runtime_error("writing standard output ('-') needs --output_format (ply, xyz, "
                             "csv, las or pcd)");
  }
  throw std::runtime_error("cannot write '" + path + "': the output format must be ply, xyz, "
                           "txt, csv, las or pcd, got '" + chosen + "'");
}

PointWriter::PointWriter(const std::string& path, bool overwrite, size_t count,
                         bool with_normals,
                         std::vector<std::pair<std::string, std::string>> fields,
                         const std::vector<std::string>& comments, const std::string& format)
    : count_(count), with_normals_(with_normals) {
  const std::string chosen = OutputFormat(path, format);
  ply_ = chosen == "ply";
  separator_ = chosen == "csv" ? ',' : ' ';
  if (chosen == "las" || chosen == "pcd") {
    throw std::runtime_error("cannot write '" + path + "' point by point: LAS and PCD are "
                             "written whole (WritePointCloud); write PLY or XYZ here");
  }
  for (const auto& [name, type] : fields) {
    if (PlyTypeSize(type) == 0) {
      throw std::invalid_argument("property '" + name + "' has no PLY type ('" + type + "')");
    }
    types_.push_back(CanonicalPlyType(type));
  }
  file_ = std::make_unique<AtomicOutputFile>(path, overwrite);
  std::ofstream& out = file_->stream();
  if (!ply_) {
    out.precision(17);
    if (separator_ == ',') {  // a header line of names, as ReadXyz reads one
      out << "x,y,z";
      for (const auto& field : fields) {
        std::string name = field.first;  // a name the header line can hold as one field
        std::replace_if(name.begin(), name.end(), [](char c) { return c == ',' || c == '"'; },
                        '_');
        out << ',' << name;
      }
      out << '\n';
    }
    return;
  }
  if (!HostIsLittleEndian()) throw std::runtime_error("big-endian hosts are not supported");
  out << "ply\nformat binary_little_endian 1.0\ncomment written by lpd\n";
  for (const std::string& comment : comments) out << "comment " << comment << "\n";
  out << "element vertex " << count << "\n";
  out << "property double x\nproperty double y\nproperty double z\n";
  if (with_normals) out << "property float nx\nproperty float ny\nproperty float nz\n";
  for (size_t f = 0; f < fields.size(); ++f) {
    out << "property " << types_[f] << " " << fields[f].first << "\n";
  }
  out << "end_header\n";
}

PointWriter::~PointWriter() = default;

namespace {

// `value` as a T: rounded and clamped to T's range for an integer T (NaN gives 0).
template <typename T>
T Converted(double value) {
  if constexpr (std::is_integral_v<T>) {
    if (std::isnan(value)) return 0;
    const double rounded = std::round(value);
    if (rounded <= static_cast<double>(std::numeric_limits<T>::min())) {
      return std::numeric_limits<T>::min();
    }
    if (rounded >= static_cast<double>(std::numeric_limits<T>::max())) {
      return std::numeric_limits<T>::max();
    }
    return static_cast<T>(rounded);
  } else {
    return static_cast<T>(value);
  }
}

template <typename T>
void AppendAs(double value, std::vector<char>* record) {
  const T converted = Converted<T>(value);
  const char* bytes = reinterpret_cast<const char*>(&converted);
  record->insert(record->end(), bytes, bytes + sizeof(T));
}

}  // namespace

void AppendTyped(const std::string& type, double value, std::vector<char>* record) {
  if (type == "char") return AppendAs<int8_t>(value, record);
  if (type == "uchar") return AppendAs<uint8_t>(value, record);
  if (type == "short") return AppendAs<int16_t>(value, record);
  if (type == "ushort") return AppendAs<uint16_t>(value, record);
  if (type == "int") return AppendAs<int32_t>(value, record);
  if (type == "uint") return AppendAs<uint32_t>(value, record);
  if (type == "float") return AppendAs<float>(value, record);
  AppendAs<double>(value, record);
}

std::string CanonicalPlyType(const std::string& type) {
  const PlyScalar scalar = PlyScalarOf(type);
  for (const auto& [name, named] : kPlyScalarNames) {
    if (named == scalar) return name;  // the first name of its type
  }
  return type;
}

bool HostIsLittleEndian() {
  const uint16_t probe = 1;
  uint8_t first;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

void PointWriter::Write(const Point3& p, const Point3& normal, const double* values) {
  ++written_;
  std::ofstream& out = file_->stream();
  if (!ply_) {
    out << p.x() << separator_ << p.y() << separator_ << p.z();
    for (size_t f = 0; f < types_.size(); ++f) {
      out << separator_;
      if (PlyTypeIsInteger(types_[f])) {
        out << static_cast<long long>(Converted<int64_t>(values[f]));
      } else {
        out << (types_[f] == "float" ? static_cast<float>(values[f]) : values[f]);
      }
    }
    out << '\n';
    return;
  }
  record_.clear();
  const char* bytes = reinterpret_cast<const char*>(p.data());
  record_.insert(record_.end(), bytes, bytes + 3 * sizeof(double));
  if (with_normals_) {
    const Eigen::Vector3f as_float = normal.cast<float>();
    bytes = reinterpret_cast<const char*>(as_float.data());
    record_.insert(record_.end(), bytes, bytes + 3 * sizeof(float));
  }
  for (size_t f = 0; f < types_.size(); ++f) AppendTyped(types_[f], values[f], &record_);
  out.write(record_.data(), static_cast<std::streamsize>(record_.size()));
}

void PointWriter::Commit() {
  if (written_ != count_) {
    throw std::logic_error("PointWriter: " + std::to_string(written_) + " points written, " +
                           std::to_string(count_) + " announced");
  }
  file_->Commit();
}

void WritePointCloud(const std::string& path, const PointCloud& cloud, bool overwrite,
                     const std::string& format) {
  const std::string chosen = OutputFormat(path, format);
  if (chosen == "las" || chosen == "pcd") {
    AtomicOutputFile file(path, overwrite);
    if (chosen == "las") {
      WriteLas(file.stream(), cloud, path);
    } else {
      WritePcd(file.stream(), cloud, path);
    }
    file.Commit();
    return;
  }
  std::vector<std::pair<std::string, std::string>> fields;
  for (const PointAttribute& attribute : cloud.attributes) {
    if (attribute.values.size() != cloud.points.size()) {
      throw std::invalid_argument("property '" + attribute.name + "' has the wrong size");
    }
    fields.emplace_back(attribute.name, attribute.type);
  }
  const bool with_normals = !cloud.normals.empty();
  PointWriter writer(path, overwrite, cloud.points.size(), with_normals, fields, cloud.comments,
                     format);
  std::vector<double> values(fields.size());
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    for (size_t f = 0; f < values.size(); ++f) values[f] = cloud.attributes[f].values[i];
    writer.Write(cloud.points[i], with_normals ? cloud.normals[i] : Point3::Zero(),
                 values.data());
  }
  writer.Commit();
}

}  // namespace lpd::io
