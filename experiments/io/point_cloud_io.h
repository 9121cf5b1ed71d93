// lpd: reading and writing point clouds.
//
// Read: XYZ text (".xyz", ".txt", ".pts": the first three numbers of each line, separated by
// spaces or tabs; '#' starts a comment; CRLF line ends and a UTF-8 byte-order mark are
// accepted; columns 4-6 become normals when they are unit vectors on every line, other extra
// columns are ignored), PLY (ascii, binary little or big endian; the x, y, z
// properties of the "vertex" element), OFF and OBJ (vertices only). Every reader rejects
// malformed lines, NaN and infinite coordinates with "FILE:LINE: reason", and empty files.
// Write: PLY (binary little endian, with normals and per-point scalar properties that
// CloudCompare and MeshLab show as scalar fields) or XYZ text, chosen by extension; writes
// are atomic (see AtomicOutputFile).
#ifndef LPD_EXPERIMENTS_IO_POINT_CLOUD_IO_H_
#define LPD_EXPERIMENTS_IO_POINT_CLOUD_IO_H_

#include <cstdint>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "energy/point3.h"

namespace lpd::experiments {

struct PointCloud {
  energy::PointList points;
  energy::PointList normals;  // empty, or one per point
  // Named per-point scalar properties (e.g. "outlier", "feature_score"), one value per point.
  std::vector<std::pair<std::string, std::vector<float>>> scalars;
  // Named per-point indices ("source_index", "tile"), PLY type uint: exact beyond the 2^24
  // where a float stops counting. A PLY "uint" property is read into these.
  std::vector<std::pair<std::string, std::vector<uint32_t>>> index_fields;
  std::vector<std::string> comments;  // PLY header comments (one line each)

  // The scalar property called `name`, or nullptr.
  const std::vector<float>* FindScalar(const std::string& name) const;
  // The index field called `name`, or nullptr.
  const std::vector<uint32_t>* FindIndexField(const std::string& name) const;
};

// Throws std::runtime_error with a one-line reason on any problem, also when a PLY header
// declares more items than its body can hold (nothing is allocated for them). PLY files also
// give their normals (nx, ny, nz) and other per-vertex scalar properties, XYZ files their
// normals as above; other formats give points only.
PointCloud ReadPointCloud(const std::string& path);
// The same from a stream holding a file of format `extension` ("xyz", "ply", ...); `name`
// stands for the file in messages. `in` must be seekable (a file or a string stream).
PointCloud ReadPointCloud(std::istream& in, const std::string& extension,
                          const std::string& name);
energy::PointList ReadPoints(const std::string& path);

// Writes `cloud` to `path` (".ply" or ".xyz"/".txt"); throws std::runtime_error on failure.
void WritePointCloud(const std::string& path, const PointCloud& cloud, bool overwrite);

// Lower-cased extension of `path` without the dot ("" if none).
std::string FileExtension(const std::string& path);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_IO_POINT_CLOUD_IO_H_
