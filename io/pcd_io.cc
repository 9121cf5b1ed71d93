#include "io/pcd_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <liblzf/lzf.h>

#include "io/point_cloud_io.h"

namespace lpd::io {
namespace {

[[noreturn]] void Fail(const std::string& name, long line, const std::string& reason) {
  if (line > 0) throw std::runtime_error(name + ":" + std::to_string(line) + ": " + reason);
  throw std::runtime_error(name + ": " + reason);
}

constexpr size_t kMaxHeaderLine = 65536;
// Values per point (the fields' COUNTs summed): bounds what a header can make us allocate.
constexpr uint64_t kMaxValuesPerPoint = 4096;
constexpr int kMaxHeaderLines = 1000;
// LZF turns 3 input bytes into at most 264 output bytes.
constexpr uint64_t kMaxLzfExpansion = 88;

enum class PcdData { kAscii, kBinary, kBinaryCompressed };

struct PcdField {
  std::string name;
  int size = 4;    // bytes per value
  char type = 'F'; // I, U or F
  int count = 1;   // values per point
  int offset = 0;  // of the field's first value in a binary record
};

struct PcdHeader {
  std::vector<PcdField> fields;
  uint64_t points = 0;
  PcdData data = PcdData::kAscii;
  int record_size = 0;  // bytes per point in a binary record
  long lines = 0;       // header lines read
};

std::vector<std::string> Tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

uint64_t ParseCount(const std::string& name, long line, const std::string& key,
                    const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || text[0] == '-' || errno == ERANGE || value > (1ull << 40)) {
    Fail(name, line, key + " must be a whole number of at most 2^40, got '" + text + "'");
  }
  return value;
}

PcdHeader ReadHeader(const std::string& name, std::istream& in) {
  PcdHeader header;
  std::vector<std::string> sizes, types, counts;
  bool has_points = false;
  uint64_t width = 0, height = 1;
  std::string line;
  while (true) {
    if (++header.lines > kMaxHeaderLines) Fail(name, header.lines, "no DATA line in the header");
    if (!std::getline(in, line)) {
      Fail(name, header.lines, header.lines == 1 ? "the file is empty" : "the header ends "
                                                   "before its DATA line");
    }
    if (line.size() > kMaxHeaderLine) Fail(name, header.lines, "header line too long");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> tokens = Tokens(line);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string& key = tokens[0];
    const std::vector<std::string> values(tokens.begin() + 1, tokens.end());
    if (key == "VERSION" || key == "VIEWPOINT") continue;
    if (key == "FIELDS" || key == "COLUMNS") {
      if (!header.fields.empty()) Fail(name, header.lines, "a second FIELDS line");
      for (const std::string& field : values) header.fields.push_back({field});
    } else if (key == "SIZE") {
      sizes = values;
    } else if (key == "TYPE") {
      types = values;
    } else if (key == "COUNT") {
      counts = values;
    } else if (key == "WIDTH" && values.size() == 1) {
      width = ParseCount(name, header.lines, key, values[0]);
    } else if (key == "HEIGHT" && values.size() == 1) {
      height = ParseCount(name, header.lines, key, values[0]);
    } else if (key == "POINTS" && values.size() == 1) {
      header.points = ParseCount(name, header.lines, key, values[0]);
      has_points = true;
    } else if (key == "DATA" && values.size() == 1) {
      if (values[0] == "ascii") {
        header.data = PcdData::kAscii;
      } else if (values[0] == "binary") {
        header.data = PcdData::kBinary;
      } else if (values[0] == "binary_compressed") {
        header.data = PcdData::kBinaryCompressed;
      } else {
        Fail(name, header.lines, "DATA must be ascii, binary or binary_compressed, got '" +
                                     values[0] + "'");
      }
      break;
    } else {
      Fail(name, header.lines, "not a PCD header line: '" + line.substr(0, 60) + "'");
    }
  }
  const size_t n = header.fields.size();
  if (n == 0) Fail(name, 0, "the header has no FIELDS");
  if (sizes.size() != n || types.size() != n || (!counts.empty() && counts.size() != n)) {
    Fail(name, 0, "the header's SIZE, TYPE and COUNT must each give one value per field (" +
                      std::to_string(n) + " fields)");
  }
  int offset = 0;
  uint64_t values_per_point = 0;
  for (size_t f = 0; f < n; ++f) {
    PcdField& field = header.fields[f];
    field.size = sizes[f] == "1" || sizes[f] == "2" || sizes[f] == "4" || sizes[f] == "8"
                     ? std::stoi(sizes[f])
                     : 0;
    field.type = types[f].size() == 1 ? types[f][0] : '?';
    const bool valid = field.size > 0 && (field.type == 'I' || field.type == 'U' ||
                                          (field.type == 'F' && field.size >= 4));
    if (!valid) {
      Fail(name, 0, "field '" + field.name + "' has TYPE " + types[f] + " and SIZE " + sizes[f] +
                        " (expected I or U of 1, 2, 4 or 8 bytes, or F of 4 or 8)");
    }
    const uint64_t count = counts.empty() ? 1 : ParseCount(name, 0, "COUNT", counts[f]);
    values_per_point += count;
    if (count < 1 || values_per_point > kMaxValuesPerPoint) {
      Fail(name, 0, "field '" + field.name + "' has COUNT " + std::to_string(count) +
                        " (at least 1, and at most " + std::to_string(kMaxValuesPerPoint) +
                        " values per point in all)");
    }
    field.count = static_cast<int>(count);
    field.offset = offset;
    offset += field.size * field.count;
  }
  header.record_size = offset;
  if (!has_points) header.points = width * height;
  if (width > 0 && width * height != header.points) {
    Fail(name, 0, "POINTS " + std::to_string(header.points) + " is not WIDTH x HEIGHT = " +
                      std::to_string(width * height));
  }
  return header;
}

// The little-endian value of `field` at `bytes`.
double DecodeValue(const PcdField& field, const unsigned char* bytes) {
  unsigned char value[8];
  std::memcpy(value, bytes, field.size);
  if (!HostIsLittleEndian()) std::reverse(value, value + field.size);
  auto as = [&value](auto typed) {
    std::memcpy(&typed, value, sizeof(typed));
    return static_cast<double>(typed);
  };
  switch (field.type) {
    case 'F': return field.size == 4 ? as(float{}) : as(double{});
    case 'I':
      switch (field.size) {
        case 1: return as(int8_t{});
        case 2: return as(int16_t{});
        case 4: return as(int32_t{});
        default: return as(int64_t{});
      }
    default:
      switch (field.size) {
        case 1: return as(uint8_t{});
        case 2: return as(uint16_t{});
        case 4: return as(uint32_t{});
        default: return as(uint64_t{});
      }
  }
}

// PCD's types and the PLY types attributes keep (8-byte integers become doubles): one table
// for reading and writing.
struct PcdType {
  const char* ply;
  char type;
  int size;
};
constexpr PcdType kPcdTypes[] = {{"char", 'I', 1},  {"uchar", 'U', 1}, {"short", 'I', 2},
                                 {"ushort", 'U', 2}, {"int", 'I', 4},   {"uint", 'U', 4},
                                 {"float", 'F', 4},  {"double", 'F', 8}};

// The PLY type an attribute of `field` keeps.
std::string AttributeType(const PcdField& field) {
  for (const PcdType& t : kPcdTypes) {
    if (t.type == field.type && t.size == field.size) return t.ply;
  }
  return "double";
}

// The PCD type of an attribute of PLY type `ply` (double for any other).
const PcdType& FieldType(const std::string& ply) {
  const std::string canonical = CanonicalPlyType(ply);
  for (const PcdType& t : kPcdTypes) {
    if (canonical == t.ply) return t;
  }
  return kPcdTypes[7];
}

// Where each value of a point goes: a coordinate, a normal component, an attribute, the
// packed colour, or nowhere.
struct Destinations {
  int xyz[3] = {-1, -1, -1};     // value index of x, y, z
  int normal[3] = {-1, -1, -1};  // of normal_x, normal_y, normal_z
  int colour = -1;               // of rgb or rgba
  bool alpha = false;
  std::vector<std::pair<int, int>> attributes;  // (value index, attribute index)
};

Destinations Route(const std::string& name, const PcdHeader& header, PointCloud* cloud,
                   std::vector<PcdField>* value_fields) {
  Destinations to;
  static const char* kAxes[3] = {"x", "y", "z"};
  static const char* kNormals[3] = {"normal_x", "normal_y", "normal_z"};
  // Normals only with all three components; a lone normal_x stays an attribute.
  int normal_components = 0;
  for (const char* component : kNormals) {
    normal_components += std::any_of(header.fields.begin(), header.fields.end(),
                                     [component](const PcdField& field) {
                                       return field.name == component && field.count == 1;
                                     });
  }
  for (const PcdField& field : header.fields) {
    for (int c = 0; c < field.count; ++c) {
      const int value = static_cast<int>(value_fields->size());
      value_fields->push_back(field);
      if (field.name == "_") continue;
      if (field.count == 1) {
        bool placed = false;
        for (int a = 0; a < 3 && !placed; ++a) {
          if (field.name == kAxes[a]) {
            if (field.type != 'F') Fail(name, 0, "field '" + field.name + "' must be of TYPE F");
            to.xyz[a] = value;
            placed = true;
          } else if (field.name == kNormals[a] && normal_components == 3) {
            to.normal[a] = value;
            placed = true;
          }
        }
        if ((field.name == "rgb" || field.name == "rgba") && field.size == 4) {
          to.colour = value;
          to.alpha = field.name == "rgba";
          placed = true;
        }
        if (placed) continue;
      }
      const std::string attribute =
          field.count == 1 ? field.name : field.name + "_" + std::to_string(c);
      to.attributes.emplace_back(value, static_cast<int>(cloud->attributes.size()));
      cloud->attributes.push_back({attribute, AttributeType(field), {}});
    }
  }
  if (to.xyz[0] < 0 || to.xyz[1] < 0 || to.xyz[2] < 0) {
    Fail(name, 0, "the header has no x, y and z fields");
  }
  if (to.colour >= 0) {
    // Named after the packed field when the file has fields called red, green or blue too.
    std::string prefix;
    for (const char* channel : {"red", "green", "blue", "alpha"}) {
      if (cloud->FindAttribute(channel)) prefix = to.alpha ? "rgba_" : "rgb_";
    }
    for (const char* channel : {"red", "green", "blue", "alpha"}) {
      if (std::string(channel) == "alpha" && !to.alpha) break;
      cloud->attributes.push_back({prefix + channel, "uchar", {}});
    }
  }
  return to;
}

// Adds one point from its `values` (one per value of the record).
void AddPoint(const std::string& name, const Destinations& to, const std::vector<double>& values,
              const std::vector<uint32_t>& colour_bits, long line, PointCloud* cloud,
              energy::PointList* normals) {
  const energy::Point3 p(values[to.xyz[0]], values[to.xyz[1]], values[to.xyz[2]]);
  if (std::isnan(p.x()) || std::isnan(p.y()) || std::isnan(p.z())) {
    ++cloud->skipped_points;
    return;
  }
  if (!p.allFinite()) Fail(name, line, "a point has an infinite coordinate");
  cloud->points.push_back(p);
  if (to.normal[0] >= 0 && to.normal[1] >= 0 && to.normal[2] >= 0) {
    normals->emplace_back(values[to.normal[0]], values[to.normal[1]], values[to.normal[2]]);
  }
  for (const auto& [value, attribute] : to.attributes) {
    cloud->attributes[attribute].values.push_back(values[value]);
  }
  if (to.colour >= 0) {
    // PCL packs 0xAARRGGBB into the field's 4 bytes (its bits, whatever the TYPE).
    const uint32_t bits = colour_bits[0];
    const size_t first = cloud->attributes.size() - (to.alpha ? 4 : 3);
    const int shifts[4] = {16, 8, 0, 24};
    for (size_t c = 0; first + c < cloud->attributes.size(); ++c) {
      cloud->attributes[first + c].values.push_back((bits >> shifts[c]) & 0xFF);
    }
  }
}

uint32_t LittleEndianWord(const unsigned char* bytes) {
  return static_cast<uint32_t>(bytes[0]) | static_cast<uint32_t>(bytes[1]) << 8 |
         static_cast<uint32_t>(bytes[2]) << 16 | static_cast<uint32_t>(bytes[3]) << 24;
}

void ReadAscii(const std::string& name, std::istream& in, const PcdHeader& header,
               const std::vector<PcdField>& value_fields, const Destinations& to,
               PointCloud* cloud, energy::PointList* normals) {
  std::vector<double> values(value_fields.size());
  std::vector<uint32_t> colour_bits(1);
  std::string line;
  long number = header.lines;
  uint64_t read = 0;
  while (read < header.points) {
    ++number;
    if (!std::getline(in, line)) {
      Fail(name, number, "the file ends after " + std::to_string(read) + " of its " +
                             std::to_string(header.points) + " points");
    }
    if (line.size() > kMaxHeaderLine) Fail(name, number, "line too long");
    const std::vector<std::string> tokens = Tokens(line);
    if (tokens.empty()) continue;
    if (tokens.size() != values.size()) {
      Fail(name, number, "expected " + std::to_string(values.size()) + " values, got " +
                             std::to_string(tokens.size()));
    }
    for (size_t v = 0; v < values.size(); ++v) {
      const char* text = tokens[v].c_str();
      char* end = nullptr;
      values[v] = std::strtod(text, &end);
      if (end == text || *end != '\0') {
        Fail(name, number, "'" + tokens[v].substr(0, 40) + "' is not a number");
      }
      if (static_cast<int>(v) == to.colour) {
        // Written by PCL as the float whose bits are the colour, or as the integer.
        if (value_fields[v].type == 'F') {
          const float as_float = static_cast<float>(values[v]);
          std::memcpy(&colour_bits[0], &as_float, 4);
        } else {
          colour_bits[0] = static_cast<uint32_t>(values[v]);
        }
      }
    }
    AddPoint(name, to, values, colour_bits, number, cloud, normals);
    ++read;
  }
}

// Reads `count` bytes, or fails saying what was being read.
std::vector<unsigned char> ReadBytes(const std::string& name, std::istream& in, uint64_t count,
                                     const std::string& what) {
  std::vector<unsigned char> bytes;
  constexpr uint64_t kChunk = 1 << 20;  // grow only as the file delivers
  while (bytes.size() < count) {
    const uint64_t chunk = std::min<uint64_t>(kChunk, count - bytes.size());
    const size_t start = bytes.size();
    bytes.resize(start + chunk);
    in.read(reinterpret_cast<char*>(bytes.data() + start), static_cast<std::streamsize>(chunk));
    if (static_cast<uint64_t>(in.gcount()) != chunk) {
      Fail(name, 0, "the file ends inside " + what + " (" +
                        std::to_string(start + in.gcount()) + " of " + std::to_string(count) +
                        " bytes)");
    }
  }
  return bytes;
}

// Decodes `points` records from `bytes`: packed records, or (field_major) each value's
// column of all points after the other.
void DecodeRecords(const std::string& name, const std::vector<unsigned char>& bytes,
                   uint64_t points, bool field_major, const PcdHeader& header,
                   const std::vector<PcdField>& value_fields, const Destinations& to,
                   PointCloud* cloud, energy::PointList* normals) {
  // Byte position of value v of point 0, and the step from one point to the next.
  std::vector<uint64_t> start(value_fields.size());
  std::vector<uint64_t> step(value_fields.size());
  uint64_t field_start = 0;
  size_t v = 0;
  for (const PcdField& field : header.fields) {
    for (int c = 0; c < field.count; ++c, ++v) {
      if (field_major) {
        start[v] = field_start + static_cast<uint64_t>(c) * field.size;
        step[v] = static_cast<uint64_t>(field.size) * field.count;
      } else {
        start[v] = field.offset + static_cast<uint64_t>(c) * field.size;
        step[v] = header.record_size;
      }
    }
    field_start += points * field.size * field.count;
  }
  std::vector<double> values(value_fields.size());
  std::vector<uint32_t> colour_bits(1);
  for (uint64_t i = 0; i < points; ++i) {
    for (size_t v = 0; v < values.size(); ++v) {
      const unsigned char* at = bytes.data() + start[v] + i * step[v];
      values[v] = DecodeValue(value_fields[v], at);
      if (static_cast<int>(v) == to.colour) colour_bits[0] = LittleEndianWord(at);
    }
    AddPoint(name, to, values, colour_bits, 0, cloud, normals);
  }
}

}  // namespace

void WritePcd(std::ostream& out, const PointCloud& cloud, const std::string& name) {
  if (!HostIsLittleEndian()) throw std::runtime_error("big-endian hosts are not supported");
  struct Column {
    std::string name;
    const PcdType* type;
    const std::vector<double>* values = nullptr;  // an attribute's, else written below
  };
  const PcdType& coordinate = FieldType(cloud.float_coordinates ? "float" : "double");
  const PcdType& single = FieldType("float");
  std::vector<Column> columns = {{"x", &coordinate}, {"y", &coordinate}, {"z", &coordinate}};
  if (!cloud.normals.empty()) {
    for (const char* component : {"normal_x", "normal_y", "normal_z"}) {
      columns.push_back({component, &single});
    }
  }
  // The colour channels, packed as PCL packs them: rgb as a float's bits, rgba as a uint.
  auto uchar_attribute = [&cloud](const char* channel) {
    const PointAttribute* attribute = cloud.FindAttribute(channel);
    return attribute && attribute->type == "uchar" ? attribute : nullptr;
  };
  std::vector<const PointAttribute*> channels = {uchar_attribute("red"), uchar_attribute("green"),
                                                 uchar_attribute("blue")};
  if (std::find(channels.begin(), channels.end(), nullptr) != channels.end()) channels.clear();
  if (!channels.empty() && uchar_attribute("alpha")) channels.push_back(uchar_attribute("alpha"));
  const bool alpha = channels.size() == 4;
  if (!channels.empty()) {
    columns.push_back({alpha ? "rgba" : "rgb", &FieldType(alpha ? "uint" : "float")});
  }
  for (const PointAttribute& attribute : cloud.attributes) {
    if (std::find(channels.begin(), channels.end(), &attribute) != channels.end()) continue;
    Column column{attribute.name, &FieldType(attribute.type), &attribute.values};
    // Field names are unique: an attribute called normal_x beside the normals, say, is renamed.
    while (std::any_of(columns.begin(), columns.end(),
                       [&column](const Column& other) { return other.name == column.name; })) {
      column.name = "input_" + column.name;
    }
    columns.push_back(column);
  }
  const size_t n = cloud.points.size();
  out << "# .PCD v0.7 - Point Cloud Data file format (written by lpd)\nVERSION 0.7\nFIELDS";
  for (const Column& column : columns) out << ' ' << column.name;
  out << "\nSIZE";
  for (const Column& column : columns) out << ' ' << column.type->size;
  out << "\nTYPE";
  for (const Column& column : columns) out << ' ' << column.type->type;
  out << "\nCOUNT";
  for (size_t c = 0; c < columns.size(); ++c) out << " 1";
  out << "\nWIDTH " << n << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n
      << "\nDATA binary\n";
  std::vector<char> record;
  for (size_t i = 0; i < n; ++i) {
    record.clear();
    for (const Column& column : columns) {
      if (column.values) {
        AppendTyped(column.type->ply, (*column.values)[i], &record);
      } else if (column.name.size() == 1) {  // x, y, z
        AppendTyped(column.type->ply, cloud.points[i][column.name[0] - 'x'], &record);
      } else if (column.name.rfind("normal_", 0) == 0) {
        AppendTyped(column.type->ply, cloud.normals[i][column.name.back() - 'x'], &record);
      } else {  // rgb or rgba: the channels' bits, 0xAARRGGBB
        uint32_t bits = 0;
        const int shifts[4] = {16, 8, 0, 24};
        std::vector<char> channel;
        for (size_t c = 0; c < channels.size(); ++c) {
          channel.clear();
          AppendTyped("uchar", channels[c]->values[i], &channel);
          bits |= static_cast<uint32_t>(static_cast<uint8_t>(channel[0])) << shifts[c];
        }
        AppendTyped("uint", bits, &record);
      }
    }
    out.write(record.data(), static_cast<std::streamsize>(record.size()));
  }
  if (!out) throw std::runtime_error(name + ": write error");
}

PointCloud ReadPcd(const std::string& name, std::istream& in) {
  const PcdHeader header = ReadHeader(name, in);
  PointCloud cloud;
  std::vector<PcdField> value_fields;
  const Destinations to = Route(name, header, &cloud, &value_fields);
  cloud.float_coordinates = value_fields[to.xyz[0]].size == 4 &&
                            value_fields[to.xyz[1]].size == 4 && value_fields[to.xyz[2]].size == 4;
  energy::PointList normals;
  const uint64_t body = header.points * header.record_size;
  if (header.data == PcdData::kAscii) {
    ReadAscii(name, in, header, value_fields, to, &cloud, &normals);
  } else if (header.data == PcdData::kBinary) {
    const std::vector<unsigned char> bytes = ReadBytes(name, in, body, "its binary points");
    DecodeRecords(name, bytes, header.points, false, header, value_fields, to, &cloud, &normals);
  } else {
    const std::vector<unsigned char> sizes = ReadBytes(name, in, 8, "its compressed sizes");
    const uint64_t compressed = LittleEndianWord(sizes.data());
    const uint64_t uncompressed = LittleEndianWord(sizes.data() + 4);
    if (uncompressed != body) {
      Fail(name, 0, "the compressed block holds " + std::to_string(uncompressed) +
                        " bytes, but POINTS x the record size is " + std::to_string(body));
    }
    if (uncompressed > kMaxLzfExpansion * compressed + 16) {
      Fail(name, 0, "the compressed block of " + std::to_string(compressed) +
                        " bytes cannot hold " + std::to_string(uncompressed));
    }
    const std::vector<unsigned char> packed =
        ReadBytes(name, in, compressed, "its compressed points");
    std::vector<unsigned char> bytes(uncompressed);
    if (uncompressed > 0 &&
        lzf_decompress(packed.data(), static_cast<unsigned int>(compressed), bytes.data(),
                       static_cast<unsigned int>(uncompressed)) != uncompressed) {
      Fail(name, 0, "the compressed points are corrupt (LZF decompression failed)");
    }
    DecodeRecords(name, bytes, header.points, true, header, value_fields, to, &cloud, &normals);
  }
  bool finite_normals = normals.size() == cloud.points.size() && !normals.empty();
  for (const energy::Point3& normal : normals) finite_normals &= normal.allFinite();
  if (finite_normals) {
    cloud.normals = std::move(normals);
  } else if (!normals.empty()) {
    // Carried as attributes instead: PCL marks a point without a normal with NaN.
    const char* kNames[3] = {"normal_x", "normal_y", "normal_z"};
    for (int a = 0; a < 3; ++a) {
      PointAttribute attribute{kNames[a], AttributeType(value_fields[to.normal[a]]), {}};
      for (const energy::Point3& normal : normals) attribute.values.push_back(normal[a]);
      cloud.attributes.push_back(std::move(attribute));
    }
  }
  return cloud;
}

}  // namespace lpd::io
