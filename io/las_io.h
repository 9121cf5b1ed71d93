// lpd: LAS 1.0-1.4 point clouds (ASPRS LAS specification), read and written by the project:
// Debian 12 packages no LAS library (no LASlib, PDAL or laspy). Point data record formats 0-3
// and 6-8; the waveform formats (4, 5, 9, 10) and LAZ (compressed) files are refused by name.
//
// Every field of a record becomes a point attribute with its LAS type: intensity,
// return_number, number_of_returns, scan_direction_flag, edge_of_flight_line,
// classification, synthetic, key_point, withheld, overlap and scanner_channel (formats 6-8),
// scan_angle_rank (0-3) or scan_angle (6-8), user_data, point_source_id, gps_time, red, green,
// blue, nir, and each extra byte past the format's record as extra_byte_N. The header's
// scale and offset, format, version, identifiers and variable-length records (a coordinate
// system, say) travel with the cloud (LasLayout), so that a LAS written from it keeps them; a
// cloud from another format is written as LAS 1.2 format 0 with a scale of its extent / 1e9.
#ifndef LPD_IO_LAS_IO_H_
#define LPD_IO_LAS_IO_H_

#include <cstdint>
#include <functional>
#include <istream>
#include <string>
#include <vector>

#include "energy/point3.h"
#include "io/point_cloud_io.h"

namespace lpd::io {

struct LasLayout {
  uint8_t version_minor = 2;     // LAS 1.x
  uint8_t point_format = 0;      // 0-3 or 6-8
  uint16_t record_length = 20;   // the format's record plus the extra bytes
  uint16_t file_source_id = 0;
  uint16_t global_encoding = 0;
  uint8_t project_id[16] = {};
  std::string system_identifier = "lpd";
  double scale[3] = {0.001, 0.001, 0.001};
  double offset[3] = {0.0, 0.0, 0.0};
  uint32_t number_of_vlrs = 0;
  std::vector<char> vlrs;        // the variable-length records, byte for byte
};

// The record length of point format `format` without extra bytes, or 0 for a format lpd does
// not read.
int LasRecordLength(int format);

// Reads a LAS file from `in` (no seeking, so pipes work); `name` stands for it in messages.
// Throws std::runtime_error "NAME: reason" on anything malformed, truncated or unsupported.
PointCloud ReadLas(const std::string& name, std::istream& in);

// The same a record at a time: ReadLasHeader reads the header and the variable-length
// records, VisitLasRecords then calls visit(p, values) for every point record, values holding
// its fields in the order of `attributes` (names and types, no values), as ReadLas reads them.
struct LasHeader {
  LasLayout layout;
  uint64_t count = 0;
  std::vector<PointAttribute> attributes;
};
LasHeader ReadLasHeader(const std::string& name, std::istream& in);
void VisitLasRecords(const std::string& name, std::istream& in, const LasHeader& header,
                     const std::function<void(const energy::Point3&, const double*)>& visit);

// Writes `cloud` as LAS to `out`: with cloud.las when it has one (its version, format, scale,
// offset and records), else as LAS 1.2 format 0 (DefaultLasLayout of its bounding box).
// Fields come from the attributes of the same names (0 when missing); the header's bounds,
// counts and counts by return are those of the points written. Throws std::runtime_error if
// a coordinate does not fit the scale.
void WriteLas(std::ostream& out, const PointCloud& cloud, const std::string& name);

// LAS 1.2, format 0, for points within [low, high]: integer coordinates of at most 1e9 steps
// across the extent (int32 holds 2.1e9), offset at `low`.
LasLayout DefaultLasLayout(const energy::Point3& low, const energy::Point3& high);

// WriteLas a point at a time, to a seekable `out`: the header and the variable-length records
// of `layout` first, the header again with the bounds and counts on Finish. Write takes one
// value per name of `attributes`; the record's fields take the values of the attributes named
// as they are (0 when none is).
class LasWriter {
 public:
  LasWriter(std::ostream& out, LasLayout layout, const std::vector<std::string>& attributes,
            std::string name);
  void Write(const energy::Point3& p, const double* values);
  void Finish();

 private:
  std::ostream& out_;
  LasLayout layout_;
  std::string name_;
  std::streampos start_;
  std::vector<int> source_;  // per record field, then extra byte: the attribute, or -1
  int returns_field_ = 0;
  std::vector<char> record_;
  uint64_t count_ = 0;
  double low_[3] = {0, 0, 0}, high_[3] = {0, 0, 0};
  uint64_t by_return_[15] = {};
};

}  // namespace lpd::io

#endif  // LPD_IO_LAS_IO_H_
