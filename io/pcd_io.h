// lpd: reading and writing PCD point clouds (the Point Cloud Library's format, v0.5-0.7), by
// the project: Debian's PCL (libpcl-dev) would bring hundreds of megabytes of dependencies for
// one header and three body layouts. The LZF blocks of binary_compressed files are
// decompressed by liblzf.
//
// A header of keyword lines (FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS,
// DATA; '#' starts a comment), then the points: ascii (a line per point), binary (packed
// little-endian records) or binary_compressed (the fields one after the other, LZF-
// compressed). x, y and z are required; normal_x, normal_y and normal_z become the normals
// when all are finite; rgb and rgba (colours packed into 4 bytes, as PCL writes them) become
// the attributes red, green, blue (and alpha) as uchar (rgb_red, ... where the file has a
// field called red, green, blue or alpha too); every other field becomes an
// attribute of its type (a field of COUNT c > 1 gives NAME_0 .. NAME_{c-1}; 8-byte integers
// are read as doubles; the '_' padding fields of PCL are skipped). A point whose x, y or z is
// NaN, an organized cloud's mark of "no return", is left out (PointCloud::skipped_points
// counts them); an infinite coordinate is an error.
#ifndef LPD_IO_PCD_IO_H_
#define LPD_IO_PCD_IO_H_

#include <istream>
#include <ostream>
#include <string>

namespace lpd::io {

struct PointCloud;

// Writes `cloud` to `out` as binary PCD v0.7: x, y, z (TYPE F, SIZE 4 when the cloud was read
// with float coordinates, else 8), normal_x, normal_y, normal_z (F 4) when it has normals,
// red, green and blue as PCL's packed rgb (F 4; with alpha, rgba U 4) when all are uchar
// attributes, and every other attribute with its type. Throws std::runtime_error on a write
// error.
void WritePcd(std::ostream& out, const PointCloud& cloud, const std::string& name);

// Reads a PCD file from `in` (no seeking, so pipes work); `name` stands for it in messages.
// Throws std::runtime_error "NAME[:LINE]: reason" on anything malformed, truncated or
// unsupported, and never allocates for more points than the body holds.
PointCloud ReadPcd(const std::string& name, std::istream& in);

}  // namespace lpd::io

#endif  // LPD_IO_PCD_IO_H_
