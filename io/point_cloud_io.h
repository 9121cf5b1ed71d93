// lpd: reading and writing point clouds.
//
// Read: XYZ text (".xyz", ".txt", ".pts": the first three numbers of each line, separated by
// spaces or tabs; '#' starts a comment; CRLF line ends and a UTF-8 byte-order mark are
// accepted; columns 4-6 become normals when they are unit vectors on every line, other extra
// columns are ignored), PLY (ascii, binary little or big endian; the x, y, z
// properties of the "vertex" element), LAS (las_io.h), PCD (pcd_io.h), OFF and OBJ
// (vertices only). Every reader rejects
// malformed lines, NaN and infinite coordinates with "FILE:LINE: reason", and empty files.
// Write: PLY (binary little endian, with normals and per-point scalar properties that
// CloudCompare and MeshLab show as scalar fields) or XYZ text, chosen by extension; writes
// are atomic (see AtomicOutputFile).
#ifndef LPD_IO_POINT_CLOUD_IO_H_
#define LPD_IO_POINT_CLOUD_IO_H_

#include <cstdint>
#include <functional>
#include <istream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "energy/point3.h"

namespace lpd::io {

class AtomicOutputFile;
struct LasLayout;

// A per-point property other than the coordinates and the normals: a colour channel, an
// intensity, a class, lpd's own flags and scores.
struct PointAttribute {
  std::string name;
  // A PLY scalar type: char, uchar, short, ushort, int, uint, float or double. Written back
  // with it, so that a property survives a run bit for bit.
  std::string type;
  std::vector<double> values;  // one per point; a double holds every value of these types
};

struct PointCloud {
  energy::PointList points;
  energy::PointList normals;  // empty, or one per point
  std::vector<PointAttribute> attributes;
  std::vector<std::string> comments;  // PLY header comments (one line each)
  // The LAS header a cloud read from LAS came with (las_io.h); written back with it.
  std::shared_ptr<const LasLayout> las;
  // Points of the file left out: a PCD file's points with a NaN coordinate (pcd_io.h).
  size_t skipped_points = 0;
  // The file gave x, y, z as 4-byte floats (PCD); a PCD written from the cloud keeps them so.
  bool float_coordinates = false;

  // The attribute called `name`, or nullptr.
  const PointAttribute* FindAttribute(const std::string& name) const;
};

// Throws std::runtime_error with a one-line reason on any problem, also when a PLY header
// declares more items than its body can hold (nothing is allocated for them). PLY files also
// give their normals (nx, ny, nz) and every other per-vertex scalar property with its type;
// XYZ files their normals as above and their other columns, when every line has as many, as
// double attributes column_4, column_5, ...; LAS files every field of their records
// (las_io.h); PCD files (ascii, binary or binary_compressed) their normals, colours and
// other fields (pcd_io.h); other formats give points only. LAZ is refused with how to
// convert it.
// `path` "-" reads standard input; `format` ("xyz", "ply", ...) replaces the extension and
// is needed for "-". Pipes, FIFOs and devices are read without seeking.
PointCloud ReadPointCloud(const std::string& path, const std::string& format = "");
// The same from a stream holding a file of format `extension` ("xyz", "ply", ...); `name`
// stands for the file in messages. `in` must be seekable (a file or a string stream).
PointCloud ReadPointCloud(std::istream& in, const std::string& extension,
                          const std::string& name);
energy::PointList ReadPoints(const std::string& path);

// Calls visit(p) for every point of the file at `path` in file order, holding one line, PLY
// vertex or LAS record at a time (.xyz/.txt/.pts, .ply, .las; other formats are read whole),
// with the checks and errors of ReadPointCloud.
void ForEachPoint(const std::string& path, const std::function<void(const energy::Point3&)>& visit);

// The attributes ReadPointCloud reads from `path` (names and types, no values): a PLY's or
// LAS file's header, an XYZ file read once (none without a column past x y z on its first
// point line), other formats read whole.
std::vector<PointAttribute> StreamedAttributes(const std::string& path);

// ForEachPoint with those `attributes` (StreamedAttributes(path)): visit(p, values), values
// holding the point's attributes in their order.
void ForEachPointWithAttributes(
    const std::string& path, const std::vector<PointAttribute>& attributes,
    const std::function<void(const energy::Point3&, const double*)>& visit);

// Writes `cloud` to `path` (".ply", ".xyz"/".txt", ".las" or ".pcd", or `format`; "-" is
// standard output and needs `format`); throws std::runtime_error on failure.
void WritePointCloud(const std::string& path, const PointCloud& cloud, bool overwrite,
                     const std::string& format = "");

// The format written to `path`: `format` when given, else the extension; throws
// std::runtime_error naming the problem if it is not ply, xyz, txt, csv, las or pcd.
std::string OutputFormat(const std::string& path, const std::string& format);

// Writes a point set point by point in WritePointCloud's layout: binary PLY with x y z
// (double), nx ny nz (float) when `with_normals`, then the `fields` (name, PLY type) in order;
// or XYZ text: x y z and the fields' values (CSV: comma-separated, after a header line of
// the names, "x,y,z,..."). `count` points must be written before Commit,
// which puts the file in place (AtomicOutputFile; nothing appears without it).
class PointWriter {
 public:
  PointWriter(const std::string& path, bool overwrite, size_t count, bool with_normals,
              std::vector<std::pair<std::string, std::string>> fields,
              const std::vector<std::string>& comments = {}, const std::string& format = "");
  ~PointWriter();
  // `values` holds one value per field, in their order; each is converted to its field's
  // type (rounded and clamped to its range for the integer types).
  void Write(const energy::Point3& p, const energy::Point3& normal, const double* values);
  void Commit();

 private:
  std::unique_ptr<AtomicOutputFile> file_;
  bool ply_;
  char separator_;  // between a text line's values
  size_t count_;
  size_t written_ = 0;
  bool with_normals_;
  std::vector<std::string> types_;
  std::vector<char> record_;
};

// Appends `value` to `record` as the little-endian bytes of the PLY type `type` (canonical
// name; rounded and clamped to its range for the integer types, NaN giving 0; double for
// any other name): the one conversion of the PLY and PCD writers.
void AppendTyped(const std::string& type, double value, std::vector<char>* record);

// The PLY 1.0 name of `type` (int8 is char, float32 is float, ...).
std::string CanonicalPlyType(const std::string& type);

bool HostIsLittleEndian();

// Lower-cased extension of `path` without the dot ("" if none).
std::string FileExtension(const std::string& path);

}  // namespace lpd::io

#endif  // LPD_IO_POINT_CLOUD_IO_H_
