#include "io/las_io.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "io/point_cloud_io.h"

namespace lpd::io {
namespace {

[[noreturn]] void Fail(const std::string& name, const std::string& reason) {
  throw std::runtime_error(name + ": " + reason);
}

// One field of a point record: a whole value of `type` at `offset`, or, when `bits` > 0,
// `bits` bits from bit `shift` of the byte at `offset`.
struct LasField {
  const char* name;
  const char* type;
  int offset;
  int shift = 0;
  int bits = 0;
};

// The fields of each point format after X, Y, Z (three int32 at 0, 4, 8).
const std::vector<LasField>& FieldsOf(int format) {
  static const std::vector<LasField> kLegacy = {
      {"intensity", "ushort", 12},
      {"return_number", "uchar", 14, 0, 3},
      {"number_of_returns", "uchar", 14, 3, 3},
      {"scan_direction_flag", "uchar", 14, 6, 1},
      {"edge_of_flight_line", "uchar", 14, 7, 1},
      {"classification", "uchar", 15, 0, 5},
      {"synthetic", "uchar", 15, 5, 1},
      {"key_point", "uchar", 15, 6, 1},
      {"withheld", "uchar", 15, 7, 1},
      {"scan_angle_rank", "char", 16},
      {"user_data", "uchar", 17},
      {"point_source_id", "ushort", 18}};
  static const std::vector<LasField> kExtended = {
      {"intensity", "ushort", 12},
      {"return_number", "uchar", 14, 0, 4},
      {"number_of_returns", "uchar", 14, 4, 4},
      {"synthetic", "uchar", 15, 0, 1},
      {"key_point", "uchar", 15, 1, 1},
      {"withheld", "uchar", 15, 2, 1},
      {"overlap", "uchar", 15, 3, 1},
      {"scanner_channel", "uchar", 15, 4, 2},
      {"scan_direction_flag", "uchar", 15, 6, 1},
      {"edge_of_flight_line", "uchar", 15, 7, 1},
      {"classification", "uchar", 16},
      {"user_data", "uchar", 17},
      {"scan_angle", "short", 18},
      {"point_source_id", "ushort", 20},
      {"gps_time", "double", 22}};
  static const std::vector<LasField> kFormats[] = {
      kLegacy,
      [] {
        auto f = kLegacy;
        f.push_back({"gps_time", "double", 20});
        return f;
      }(),
      [] {
        auto f = kLegacy;
        f.insert(f.end(), {{"red", "ushort", 20}, {"green", "ushort", 22}, {"blue", "ushort", 24}});
        return f;
      }(),
      [] {
        auto f = kLegacy;
        f.insert(f.end(), {{"gps_time", "double", 20},
                           {"red", "ushort", 28},
                           {"green", "ushort", 30},
                           {"blue", "ushort", 32}});
        return f;
      }(),
      {}, {},  // 4, 5: waveform
      kExtended,
      [] {
        auto f = kExtended;
        f.insert(f.end(), {{"red", "ushort", 30}, {"green", "ushort", 32}, {"blue", "ushort", 34}});
        return f;
      }(),
      [] {
        auto f = kExtended;
        f.insert(f.end(), {{"red", "ushort", 30},
                           {"green", "ushort", 32},
                           {"blue", "ushort", 34},
                           {"nir", "ushort", 36}});
        return f;
      }()};
  return kFormats[format];
}

template <typename T>
T Get(const char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

template <typename T>
void Put(char* bytes, T value) {
  std::memcpy(bytes, &value, sizeof(T));
}

double ReadValue(const char* record, const LasField& field) {
  const char* at = record + field.offset;
  if (field.bits > 0) {
    return (static_cast<uint8_t>(*at) >> field.shift) & ((1 << field.bits) - 1);
  }
  const std::string type = field.type;
  if (type == "uchar") return Get<uint8_t>(at);
  if (type == "char") return Get<int8_t>(at);
  if (type == "ushort") return Get<uint16_t>(at);
  if (type == "short") return Get<int16_t>(at);
  return Get<double>(at);
}

// `value` rounded and clamped to [low, high].
long long Clamped(double value, long long low, long long high) {
  if (std::isnan(value)) return 0;
  return static_cast<long long>(std::clamp(std::round(value), static_cast<double>(low),
                                           static_cast<double>(high)));
}

void WriteValue(const LasField& field, double value, char* record) {
  char* at = record + field.offset;
  if (field.bits > 0) {
    const int mask = ((1 << field.bits) - 1) << field.shift;
    const int bits = static_cast<int>(Clamped(value, 0, (1 << field.bits) - 1)) << field.shift;
    *at = static_cast<char>((static_cast<uint8_t>(*at) & ~mask) | bits);
    return;
  }
  const std::string type = field.type;
  if (type == "uchar") return Put<uint8_t>(at, static_cast<uint8_t>(Clamped(value, 0, 255)));
  if (type == "char") return Put<int8_t>(at, static_cast<int8_t>(Clamped(value, -128, 127)));
  if (type == "ushort") return Put<uint16_t>(at, static_cast<uint16_t>(Clamped(value, 0, 65535)));
  if (type == "short") {
    return Put<int16_t>(at, static_cast<int16_t>(Clamped(value, -32768, 32767)));
  }
  Put<double>(at, value);
}

int HeaderSize(int version_minor) {
  return version_minor >= 4 ? 375 : version_minor == 3 ? 235 : 227;
}

// Reads `count` bytes or fails naming what ended early.
void ReadExactly(std::istream& in, char* bytes, size_t count, const std::string& name,
                 const char* what) {
  if (count == 0) return;
  if (!in.read(bytes, static_cast<std::streamsize>(count))) {
    Fail(name, std::string("the file ends inside ") + what);
  }
}

}  // namespace

int LasRecordLength(int format) {
  static const int kLengths[] = {20, 28, 26, 34, 0, 0, 30, 36, 38};
  return format >= 0 && format <= 8 ? kLengths[format] : 0;
}

LasHeader ReadLasHeader(const std::string& name, std::istream& in) {
  if (!HostIsLittleEndian()) Fail(name, "LAS files are read on little-endian hosts only");
  char header[375] = {};
  ReadExactly(in, header, 227, name, "the LAS header");
  if (std::memcmp(header, "LASF", 4) != 0) Fail(name, "not a LAS file (no 'LASF' signature)");
  LasLayout layout;
  const uint8_t major = Get<uint8_t>(header + 24);
  layout.version_minor = Get<uint8_t>(header + 25);
  if (major != 1 || layout.version_minor > 4) {
    Fail(name, "LAS version " + std::to_string(major) + "." +
                   std::to_string(layout.version_minor) + " is not supported (1.0-1.4 are)");
  }
  const uint16_t header_size = Get<uint16_t>(header + 94);
  const uint32_t point_offset = Get<uint32_t>(header + 96);
  layout.number_of_vlrs = Get<uint32_t>(header + 100);
  const uint8_t format_byte = Get<uint8_t>(header + 104);
  layout.record_length = Get<uint16_t>(header + 105);
  if (format_byte & 0xC0) {
    Fail(name, "is LAZ (compressed LAS), which lpd does not read: decompress it first, e.g. "
               "`laszip -i in.laz -o in.las` or `pdal translate in.laz in.las`");
  }
  layout.point_format = format_byte;
  const int core = LasRecordLength(layout.point_format);
  if (core == 0) {
    Fail(name, "LAS point format " + std::to_string(layout.point_format) +
                   " is not supported (formats 0-3 and 6-8 are)");
  }
  if (layout.record_length < core) {
    Fail(name, "point record length " + std::to_string(layout.record_length) +
                   " is shorter than format " + std::to_string(layout.point_format) + "'s " +
                   std::to_string(core) + " bytes");
  }
  if (header_size < HeaderSize(std::min<int>(layout.version_minor, 2)) ||
      header_size > point_offset) {
    Fail(name, "inconsistent header size " + std::to_string(header_size) +
                   " and point data offset " + std::to_string(point_offset));
  }
  // The rest of the header (1.3 and 1.4 fields, and any bytes a writer added).
  std::vector<char> rest(header_size - 227);
  ReadExactly(in, rest.data(), rest.size(), name, "the LAS header");
  if (!rest.empty()) {
    std::memcpy(header + 227, rest.data(), std::min<size_t>(rest.size(), 375 - 227));
  }
  uint64_t count = Get<uint32_t>(header + 107);
  if (layout.version_minor >= 4 && header_size >= 375 && count == 0) {
    count = Get<uint64_t>(header + 247);
  }
  layout.file_source_id = Get<uint16_t>(header + 4);
  layout.global_encoding = Get<uint16_t>(header + 6);
  std::memcpy(layout.project_id, header + 8, 16);
  layout.system_identifier.assign(header + 26, strnlen(header + 26, 32));
  for (int c = 0; c < 3; ++c) {
    layout.scale[c] = Get<double>(header + 131 + 8 * c);
    layout.offset[c] = Get<double>(header + 155 + 8 * c);
    if (!std::isfinite(layout.scale[c]) || layout.scale[c] == 0.0 ||
        !std::isfinite(layout.offset[c])) {
      Fail(name, "invalid scale or offset in the LAS header");
    }
  }
  // In chunks, so that an offset past the end of the file allocates no more than the file has.
  for (uint32_t remaining = point_offset - header_size; remaining > 0;) {
    const uint32_t chunk = std::min<uint32_t>(remaining, 1 << 16);
    const size_t start = layout.vlrs.size();
    layout.vlrs.resize(start + chunk);
    ReadExactly(in, layout.vlrs.data() + start, chunk, name, "the variable-length records");
    remaining -= chunk;
  }
  if (count == 0) Fail(name, "the file contains no points");

  LasHeader result;
  result.count = count;
  for (const LasField& field : FieldsOf(layout.point_format)) {
    result.attributes.push_back({field.name, field.type, {}});
  }
  for (int b = 0; b < layout.record_length - core; ++b) {
    result.attributes.push_back({"extra_byte_" + std::to_string(b), "uchar", {}});
  }
  result.layout = std::move(layout);
  return result;
}

void VisitLasRecords(const std::string& name, std::istream& in, const LasHeader& header,
                     const std::function<void(const energy::Point3&, const double*)>& visit) {
  const LasLayout& layout = header.layout;
  const std::vector<LasField>& fields = FieldsOf(layout.point_format);
  const int core = LasRecordLength(layout.point_format);
  const int extra_bytes = layout.record_length - core;
  std::vector<char> record(layout.record_length);
  std::vector<double> values(fields.size() + extra_bytes);
  for (uint64_t i = 0; i < header.count; ++i) {
    if (!in.read(record.data(), layout.record_length)) {
      Fail(name, "the file ends inside point record " + std::to_string(i) + " of " +
                     std::to_string(header.count));
    }
    energy::Point3 p;
    for (int c = 0; c < 3; ++c) {
      p[c] = Get<int32_t>(record.data() + 4 * c) * layout.scale[c] + layout.offset[c];
    }
    if (!p.allFinite()) Fail(name, "point " + std::to_string(i) + " has a non-finite coordinate");
    for (size_t f = 0; f < fields.size(); ++f) values[f] = ReadValue(record.data(), fields[f]);
    for (int b = 0; b < extra_bytes; ++b) {
      values[fields.size() + b] = static_cast<uint8_t>(record[core + b]);
    }
    visit(p, values.data());
  }
}

PointCloud ReadLas(const std::string& name, std::istream& in) {
  LasHeader header = ReadLasHeader(name, in);
  PointCloud cloud;
  cloud.attributes = header.attributes;
  // Grown as records arrive, so that a header claiming more points than the file holds
  // costs nothing before the data runs out.
  VisitLasRecords(name, in, header, [&](const energy::Point3& p, const double* values) {
    cloud.points.push_back(p);
    for (size_t a = 0; a < cloud.attributes.size(); ++a) {
      cloud.attributes[a].values.push_back(values[a]);
    }
  });
  cloud.las = std::make_shared<LasLayout>(std::move(header.layout));
  return cloud;
}

LasLayout DefaultLasLayout(const energy::Point3& low, const energy::Point3& high) {
  LasLayout layout;
  const double extent = std::max((high - low).maxCoeff(), 1e-300);
  const double scale = std::pow(10.0, std::ceil(std::log10(extent / 1e9)));
  for (int c = 0; c < 3; ++c) {
    layout.scale[c] = scale;
    layout.offset[c] = low[c];
  }
  return layout;
}

LasWriter::LasWriter(std::ostream& out, LasLayout layout,
                     const std::vector<std::string>& attributes, std::string name)
    : out_(out), layout_(std::move(layout)), name_(std::move(name)) {
  if (!HostIsLittleEndian()) Fail(name_, "LAS files are written on little-endian hosts only");
  const std::vector<LasField>& fields = FieldsOf(layout_.point_format);
  const int extra_bytes = layout_.record_length - LasRecordLength(layout_.point_format);
  source_.assign(fields.size() + extra_bytes, -1);
  for (size_t f = 0; f < source_.size(); ++f) {
    const std::string field_name =
        f < fields.size() ? fields[f].name : "extra_byte_" + std::to_string(f - fields.size());
    const auto found = std::find(attributes.begin(), attributes.end(), field_name);
    if (found != attributes.end()) source_[f] = static_cast<int>(found - attributes.begin());
  }
  returns_field_ = static_cast<int>(
      std::find_if(fields.begin(), fields.end(),
                   [](const LasField& f) { return std::string(f.name) == "return_number"; }) -
      fields.begin());
  record_.resize(layout_.record_length);
  start_ = out_.tellp();
  // Room for the header, written again on Finish, then the records.
  const std::vector<char> header(HeaderSize(layout_.version_minor), 0);
  out_.write(header.data(), static_cast<std::streamsize>(header.size()));
  out_.write(layout_.vlrs.data(), static_cast<std::streamsize>(layout_.vlrs.size()));
}

void LasWriter::Write(const energy::Point3& p, const double* values) {
  const std::vector<LasField>& fields = FieldsOf(layout_.point_format);
  const int core = LasRecordLength(layout_.point_format);
  char* record = record_.data();
  std::fill(record_.begin(), record_.end(), 0);
  for (int c = 0; c < 3; ++c) {
    const double steps = std::round((p[c] - layout_.offset[c]) / layout_.scale[c]);
    if (!(std::abs(steps) <= std::numeric_limits<int32_t>::max())) {
      Fail(name_, "point " + std::to_string(count_) + " does not fit the LAS scale and offset");
    }
    Put<int32_t>(record + 4 * c, static_cast<int32_t>(steps));
    const double written = steps * layout_.scale[c] + layout_.offset[c];
    low_[c] = count_ == 0 ? written : std::min(low_[c], written);
    high_[c] = count_ == 0 ? written : std::max(high_[c], written);
  }
  for (size_t f = 0; f < fields.size(); ++f) {
    if (source_[f] >= 0) WriteValue(fields[f], values[source_[f]], record);
  }
  for (size_t b = fields.size(); b < source_.size(); ++b) {
    if (source_[b] >= 0) {
      record[core + b - fields.size()] = static_cast<char>(Clamped(values[source_[b]], 0, 255));
    }
  }
  const int return_number = static_cast<int>(ReadValue(record, fields[returns_field_]));
  if (return_number >= 1 && return_number <= 15) ++by_return_[return_number - 1];
  out_.write(record, layout_.record_length);
  ++count_;
}

void LasWriter::Finish() {
  const LasLayout& layout = layout_;
  const uint64_t n = count_;
  const int header_size = HeaderSize(layout.version_minor);
  std::vector<char> header(header_size, 0);
  std::memcpy(header.data(), "LASF", 4);
  Put<uint16_t>(header.data() + 4, layout.file_source_id);
  // No waveform packets are written (bits 1 and 2).
  Put<uint16_t>(header.data() + 6, layout.global_encoding & ~uint16_t{6});
  std::memcpy(header.data() + 8, layout.project_id, 16);
  Put<uint8_t>(header.data() + 24, 1);
  Put<uint8_t>(header.data() + 25, layout.version_minor);
  std::memcpy(header.data() + 26, layout.system_identifier.data(),
              std::min<size_t>(layout.system_identifier.size(), 32));
  std::memcpy(header.data() + 58, "lpd", 3);
  Put<uint16_t>(header.data() + 94, static_cast<uint16_t>(header_size));
  Put<uint32_t>(header.data() + 96, static_cast<uint32_t>(header_size + layout.vlrs.size()));
  Put<uint32_t>(header.data() + 100, layout.number_of_vlrs);
  Put<uint8_t>(header.data() + 104, layout.point_format);
  Put<uint16_t>(header.data() + 105, layout.record_length);
  // Legacy counts: formats 0-5 whose counts fit 32 bits (LAS 1.4 leaves them 0 otherwise).
  const bool legacy = layout.point_format <= 5 && n <= std::numeric_limits<uint32_t>::max();
  if (legacy) {
    Put<uint32_t>(header.data() + 107, static_cast<uint32_t>(n));
    for (int r = 0; r < 5; ++r) {
      Put<uint32_t>(header.data() + 111 + 4 * r, static_cast<uint32_t>(by_return_[r]));
    }
  } else if (layout.version_minor < 4) {
    Fail(name_, "LAS 1." + std::to_string(layout.version_minor) + " cannot hold " +
                    std::to_string(n) + " points of format " +
                    std::to_string(layout.point_format));
  }
  for (int c = 0; c < 3; ++c) {
    Put<double>(header.data() + 131 + 8 * c, layout.scale[c]);
    Put<double>(header.data() + 155 + 8 * c, layout.offset[c]);
    Put<double>(header.data() + 179 + 16 * c, high_[c]);
    Put<double>(header.data() + 187 + 16 * c, low_[c]);
  }
  if (layout.version_minor >= 4) {
    Put<uint64_t>(header.data() + 247, n);
    for (int r = 0; r < 15; ++r) Put<uint64_t>(header.data() + 255 + 8 * r, by_return_[r]);
  }
  const std::streampos end = out_.tellp();
  out_.seekp(start_);
  out_.write(header.data(), header_size);
  out_.seekp(end);
  if (!out_) Fail(name_, "writing the LAS file failed");
}

void WriteLas(std::ostream& out, const PointCloud& cloud, const std::string& name) {
  LasLayout layout;
  if (cloud.las) {
    layout = *cloud.las;
  } else if (!cloud.points.empty()) {
    energy::Point3 low = cloud.points[0], high = cloud.points[0];
    for (const energy::Point3& p : cloud.points) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    layout = DefaultLasLayout(low, high);
  }
  std::vector<std::string> names;
  for (const PointAttribute& attribute : cloud.attributes) names.push_back(attribute.name);
  LasWriter writer(out, std::move(layout), names, name);
  std::vector<double> values(names.size());
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    for (size_t a = 0; a < names.size(); ++a) values[a] = cloud.attributes[a].values[i];
    writer.Write(cloud.points[i], values.data());
  }
  writer.Finish();
}

}  // namespace lpd::io
