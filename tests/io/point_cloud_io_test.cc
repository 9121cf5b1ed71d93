// Readers and writers: round trips, every format, and clear errors on bad files.
#include "io/point_cloud_io.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "io/atomic_output_file.h"

namespace lpd::io {
namespace {

namespace fs = std::filesystem;

class PointCloudIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() /
                 ("lpd_io_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                  "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = (directory_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // The message of the exception io::ReadPoints throws on `path` ("" if none).
  static std::string ReadError(const std::string& path) {
    try {
      io::ReadPoints(path);
    } catch (const std::runtime_error& error) {
      return error.what();
    }
    return "";
  }
  fs::path directory_;
};

TEST_F(PointCloudIoTest, ReadsEveryFormat) {
  EXPECT_EQ(io::ReadPoints(Write("a.xyz", "# comment\n1 2 3 9 9\n\n4 5 6\n")).size(), 2u);
  const auto obj = io::ReadPoints(Write("a.obj", "# c\nv 1 2 3\nvn 0 0 1\nv 4 5 6\nf 1 2 2\n"));
  ASSERT_EQ(obj.size(), 2u);
  EXPECT_EQ(obj[1], energy::Point3(4, 5, 6));
  const auto off = io::ReadPoints(Write("a.off", "OFF\n# c\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  ASSERT_EQ(off.size(), 3u);
  EXPECT_EQ(off[2], energy::Point3(0, 1, 0));
  const auto ply = io::ReadPoints(Write(
      "a.ply",
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float y\nproperty float x\n"
      "property float z\nproperty uchar red\nelement face 1\nproperty list uchar int "
      "vertex_indices\nend_header\n1 2 3 255\n4 5 6 0\n3 0 1 1\n"));
  ASSERT_EQ(ply.size(), 2u);
  EXPECT_EQ(ply[0], energy::Point3(2, 1, 3));
}

TEST_F(PointCloudIoTest, BinaryPlyRoundTripWithAttributes) {
  io::PointCloud cloud;
  cloud.points = {{1.5, -2.25, 1e-9}, {3, 4, 5}};
  cloud.normals = {{0, 0, 1}, {1, 0, 0}};
  cloud.attributes = {{"feature", "float", {1.0, 0.0}}};
  const std::string path = (directory_ / "out.ply").string();
  io::WritePointCloud(path, cloud, false);
  const auto points = io::ReadPoints(path);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], cloud.points[0]);
  EXPECT_EQ(points[1], cloud.points[1]);
  // An existing output is never replaced without `overwrite`, and is left intact.
  EXPECT_THROW(io::WritePointCloud(path, io::PointCloud{{{9, 9, 9}}, {}, {}, {}}, false),
               std::runtime_error);
  EXPECT_EQ(io::ReadPoints(path).size(), 2u);
  const std::string xyz = (directory_ / "out.xyz").string();
  io::WritePointCloud(xyz, cloud, false);
  EXPECT_EQ(io::ReadPoints(xyz)[0], cloud.points[0]);
}

// Every PLY scalar type keeps its values exactly, at the ends of its range too (2^24 + 1 is
// the first integer a float cannot hold); out-of-range values are clamped to the type.
TEST_F(PointCloudIoTest, BigEndianBinaryPlyReadsItsValues) {
  // Two vertices laid out byte by byte, most significant byte first: a double x, a float y,
  // a short z, a uchar list (skipped) and a ushort attribute.
  std::string body;
  auto append_reversed = [&body](const void* value, size_t size) {
    const char* bytes = static_cast<const char*>(value);
    for (size_t b = size; b-- > 0;) body.push_back(bytes[b]);
  };
  for (int v = 0; v < 2; ++v) {
    const double x = v == 0 ? -1.25 : 1e10;
    const float y = v == 0 ? 0.5f : -3.0f;
    const int16_t z = v == 0 ? -300 : 7;
    const uint8_t count = v == 0 ? 2 : 0;
    const uint16_t tag = v == 0 ? 65535 : 258;
    append_reversed(&x, sizeof(x));
    append_reversed(&y, sizeof(y));
    append_reversed(&z, sizeof(z));
    append_reversed(&count, 1);
    for (int c = 0; c < count; ++c) {
      const int32_t item = 1000 + c;
      append_reversed(&item, sizeof(item));
    }
    append_reversed(&tag, sizeof(tag));
  }
  const std::string path = Write(
      "big.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty double x\n"
                 "property float32 y\nproperty int16 z\nproperty list uint8 int w\n"
                 "property ushort tag\nend_header\n" + body);
  const PointCloud cloud = ReadPointCloud(path);
  ASSERT_EQ(cloud.points.size(), 2u);
  EXPECT_EQ(cloud.points[0], energy::Point3(-1.25, 0.5, -300));
  EXPECT_EQ(cloud.points[1], energy::Point3(1e10, -3, 7));
  ASSERT_EQ(cloud.attributes.size(), 1u);
  EXPECT_EQ(cloud.attributes[0].values, (std::vector<double>{65535, 258}));
}

TEST_F(PointCloudIoTest, AttributesKeepTheirTypeAndValues) {
  io::PointCloud cloud;
  cloud.points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  cloud.attributes = {{"a_char", "char", {-128, 127, 0}},
                      {"red", "uchar", {0, 255, 17}},
                      {"a_short", "short", {-32768, 32767, -1}},
                      {"a_ushort", "ushort", {0, 65535, 1}},
                      {"a_int", "int", {-2147483648.0, 2147483647.0, 5}},
                      {"source_index", "uint", {16777217, 4000000000.0, 4294967295.0}},
                      {"score", "float", {0.5, 0.1f, -1e30f}},
                      {"exact", "double", {0.1, 1.0 / 3.0, -1e300}},
                      {"clamped", "uchar", {-5, 300, 2.6}}};
  for (const char* name : {"attributes.ply", "attributes_ascii.ply"}) {
    const std::string path = (directory_ / name).string();
    if (std::string(name) == "attributes.ply") {
      io::WritePointCloud(path, cloud, false);
    } else {  // the same values in an ascii PLY written by hand (int8 etc.: the PLY aliases)
      Write(name,
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nproperty int8 a_char\nproperty uint8 red\nproperty int16 a_short\n"
            "property uint16 a_ushort\nproperty int32 a_int\nproperty uint32 source_index\n"
            "property float32 score\nproperty float64 exact\nproperty uchar clamped\n"
            "end_header\n"
            "0 0 0 -128 0 -32768 0 -2147483648 16777217 0.5 0.10000000000000001 0 0\n"
            "1 1 1 127 255 32767 65535 2147483647 4000000000 0.100000001490116 "
            "0.33333333333333331 255 255\n"
            "2 2 2 0 17 -1 1 5 4294967295 -1.00000001504747e+30 -1e+300 3 3\n");
    }
    const io::PointCloud read = io::ReadPointCloud(path);
    ASSERT_EQ(read.attributes.size(), cloud.attributes.size()) << name;
    for (size_t a = 0; a < cloud.attributes.size(); ++a) {
      const io::PointAttribute& expected = cloud.attributes[a];
      const io::PointAttribute* found = read.FindAttribute(expected.name);
      ASSERT_NE(found, nullptr) << expected.name;
      EXPECT_EQ(found->type, expected.type) << expected.name;
      if (expected.name == "clamped") {
        EXPECT_EQ(found->values, (std::vector<double>{0, 255, 3})) << name;
      } else if (expected.type == "float") {
        for (int i = 0; i < 3; ++i) {
          EXPECT_EQ(found->values[i], static_cast<float>(expected.values[i])) << name;
        }
      } else {
        EXPECT_EQ(found->values, expected.values) << name << " " << expected.name;
      }
    }
  }
  EXPECT_EQ(io::ReadPointCloud((directory_ / "attributes.ply").string()).FindAttribute("x"),
            nullptr);
}

TEST_F(PointCloudIoTest, XyzColumnsBecomeAttributesWhenEveryLineHasThem) {
  const io::PointCloud colours =
      io::ReadPointCloud(Write("colours.xyz", "0 0 0 255 0 10\n1 1 1 0 128 20.5\n"));
  ASSERT_EQ(colours.attributes.size(), 3u);
  EXPECT_EQ(colours.attributes[0].name, "column_4");
  EXPECT_EQ(colours.attributes[2].values, (std::vector<double>{10, 20.5}));
  const io::PointCloud normals =
      io::ReadPointCloud(Write("normals.xyz", "0 0 0 0 0 1 7\n1 1 1 1 0 0 8\n"));
  EXPECT_EQ(normals.normals.size(), 2u);
  ASSERT_EQ(normals.attributes.size(), 1u);
  EXPECT_EQ(normals.attributes[0].name, "column_7");
  EXPECT_TRUE(io::ReadPointCloud(Write("ragged.xyz", "0 0 0 1\n1 1 1\n")).attributes.empty());
}

// CSV-style text: commas or semicolons between the columns, a header line of names (as
// CloudCompare, PDAL and spreadsheets write), the point count of Leica's PTS; the streamed
// path (tiles) names the columns as the whole-file one does.
TEST_F(PointCloudIoTest, XyzReadsCsvSeparatorsHeadersAndPtsCounts) {
  const std::string csv = Write("scan.txt", "x,y,z,intensity\n1,2,3,40\n4.5,5,6,41\n");
  const io::PointCloud cloud = io::ReadPointCloud(csv);
  ASSERT_EQ(cloud.points.size(), 2u);
  EXPECT_EQ(cloud.points[1], energy::Point3(4.5, 5, 6));
  ASSERT_EQ(cloud.attributes.size(), 1u);
  EXPECT_EQ(cloud.attributes[0].name, "intensity");
  EXPECT_EQ(cloud.attributes[0].values, (std::vector<double>{40, 41}));
  const std::vector<io::PointAttribute> streamed = io::StreamedAttributes(csv);
  ASSERT_EQ(streamed.size(), 1u);
  EXPECT_EQ(streamed[0].name, "intensity");
  std::vector<double> values;
  io::ForEachPointWithAttributes(csv, streamed, [&](const energy::Point3&, const double* v) {
    values.push_back(v[0]);
  });
  EXPECT_EQ(values, (std::vector<double>{40, 41}));

  const io::PointCloud compare =
      io::ReadPointCloud(Write("cc.csv", "//X,Y,Z,R,G,B\n0;0;0;255;0;9\n1; 1; 1; 7; 8; 9\n"));
  ASSERT_EQ(compare.attributes.size(), 3u);
  EXPECT_EQ(compare.attributes[0].name, "R");
  EXPECT_EQ(compare.attributes[2].values, (std::vector<double>{9, 9}));
  EXPECT_EQ(compare.points[1], energy::Point3(1, 1, 1));
  const io::PointCloud quoted =
      io::ReadPointCloud(Write("pdal.txt", "\"X\",\"Y\",\"Z\",\"Return-Number\"\n1,2,3,1\n"));
  ASSERT_EQ(quoted.attributes.size(), 1u);
  EXPECT_EQ(quoted.attributes[0].name, "Return_Number");
  // Names that do not fit the columns (or repeat) leave the columns numbered.
  EXPECT_EQ(io::ReadPointCloud(Write("short.txt", "x y z\n1 2 3 4\n")).attributes[0].name,
            "column_4");
  EXPECT_EQ(io::ReadPointCloud(Write("twice.txt", "x y z a a\n1 2 3 4 5\n")).attributes[1].name,
            "column_5");

  const io::PointCloud pts = io::ReadPointCloud(Write("scan.pts", "2\n1 2 3 9\n4 5 6 8\n"));
  ASSERT_EQ(pts.points.size(), 2u);
  EXPECT_EQ(pts.points[0], energy::Point3(1, 2, 3));

  // One such line, before the first point only; a count or names later is malformed.
  EXPECT_NE(ReadError(Write("late.txt", "1 2 3\nx y z\n")).find(":2: expected three numbers"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("two.txt", "x y z\nx y z\n1 2 3\n")).find(":2: expected"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("count.txt", "1 2 3\n5\n")).find(":2: expected"), std::string::npos);
  EXPECT_NE(ReadError(Write("words.txt", "x y\n1 2 3\n")).find(":1: expected"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("header_only.txt", "x,y,z\n")).find("no points"), std::string::npos);
}

// CSV out: a header line of the names, then comma-separated values, read back as written.
TEST_F(PointCloudIoTest, CsvOutputRoundTripsWithItsHeader) {
  io::PointCloud cloud;
  cloud.points = {{1.5, -2, 3}, {4, 5, 6.25}};
  cloud.attributes.push_back({"intensity", "ushort", {7, 65535}});
  cloud.attributes.push_back({"gps_time", "double", {0.125, 1e9}});
  cloud.attributes.push_back({"a,b", "float", {1, 2}});  // a PLY name may hold a comma
  const std::string path = (directory_ / "out.csv").string();
  io::WritePointCloud(path, cloud, false);
  std::ifstream in(path);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "x,y,z,intensity,gps_time,a_b");
  EXPECT_EQ(first, "1.5,-2,3,7,0.125,1");
  const io::PointCloud back = io::ReadPointCloud(path);
  EXPECT_EQ(back.points, cloud.points);
  ASSERT_EQ(back.attributes.size(), 3u);
  EXPECT_EQ(back.attributes[1].name, "gps_time");
  EXPECT_EQ(back.attributes[2].name, "a_b");
  EXPECT_EQ(back.attributes[0].values, cloud.attributes[0].values);
  EXPECT_EQ(back.attributes[1].values, cloud.attributes[1].values);
  EXPECT_EQ(io::OutputFormat("-", "csv"), "csv");
}

// The OFF variants: 4OFF divides by w, nOFF reads its dimension line, C/N/ST carry extra
// numbers; a header claiming more vertices than there are cannot read faces as points.
TEST_F(PointCloudIoTest, OffVariantsAreReadOrRefusedByName) {
  EXPECT_EQ(io::ReadPoints(Write("w.off", "4OFF\n1 0 0\n2 4 6 2\n"))[0], energy::Point3(1, 2, 3));
  EXPECT_EQ(io::ReadPoints(Write("n.off", "nOFF\n3\n1 0 0\n1 2 3\n"))[0], energy::Point3(1, 2, 3));
  EXPECT_EQ(io::ReadPoints(Write("n1.off", "nOFF 3 2 0 0\n1 2 3\n4 5 6\n")).size(), 2u);
  EXPECT_EQ(io::ReadPoints(Write("cn.off", "CNOFF\n1 0 0\n1 2 3 0 0 1 0.5 0.5 0.5 1\n"))[0],
            energy::Point3(1, 2, 3));
  EXPECT_NE(ReadError(Write("n4.off", "nOFF\n4\n1 0 0\n1 2 3 4\n")).find("dimension 4"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("bin.off", "OFF BINARY\n")).find("binary OFF"), std::string::npos);
  EXPECT_NE(ReadError(Write("xoff.off", "QOFF\n1 0 0\n1 2 3\n")).find("unknown OFF variant"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("claims.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
                .find("claim more vertices"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("w0.off", "4OFF\n1 0 0\n1 2 3 0\n")).find("w = 0"),
            std::string::npos);
}

TEST_F(PointCloudIoTest, RepeatedOrListCoordinatesAreRefused) {
  EXPECT_NE(ReadError(Write("twice.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                         "property float x\nproperty float y\nproperty float z\n"
                                         "property float x\nend_header\n1 2 3 999\n"))
                .find("two properties named 'x'"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("list.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                        "property list uchar float x\nproperty float y\n"
                                        "property float z\nend_header\n1 1 2 3\n"))
                .find("'x' is a list"),
            std::string::npos);
}

// Every point io::ForEachPoint visits, or the message of the exception it throws.
std::pair<energy::PointList, std::string> StreamPoints(const std::string& path) {
  energy::PointList points;
  try {
    io::ForEachPoint(path, [&](const energy::Point3& p) { points.push_back(p); });
  } catch (const std::runtime_error& error) {
    return {points, error.what()};
  }
  return {points, ""};
}

TEST_F(PointCloudIoTest, StreamingVisitsTheSamePointsAndFailsTheSameWay) {
  io::PointCloud cloud;
  cloud.points = {{1.5, -2.25, 1e-9}, {3, 4, 5}, {-7, 0.125, 2}};
  cloud.normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  cloud.attributes = {{"score", "float", {0.5, 0.25, 1.0}}};
  const std::string binary = (directory_ / "binary.ply").string();
  io::WritePointCloud(binary, cloud, false);
  const std::string las = (directory_ / "records.las").string();
  io::WritePointCloud(las, cloud, false);
  const std::string paths[] = {
      binary, las,
      Write("ascii.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                         "property float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n"),
      Write("a.xyz", "# comment\n1 2 3 9 9\n\n4 5 6\n"),
      Write("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")};
  for (const std::string& path : paths) {
    const auto [streamed, error] = StreamPoints(path);
    EXPECT_EQ(error, "") << path;
    EXPECT_EQ(streamed, io::ReadPoints(path)) << path;
  }
  for (const char* bad : {"nan.xyz", "empty.xyz", "bad.ply"}) {
    const std::string path =
        Write(bad, std::string(bad) == "nan.xyz"   ? "1 2 3\nnan 2 3\n"
                   : std::string(bad) == "bad.ply" ? "ply\nformat ascii 1.0\nelement vertex 2\n"
                                                     "property float x\nend_header\n1\n2\n"
                                                   : "");
    EXPECT_EQ(StreamPoints(path).second, ReadError(path)) << bad;
    EXPECT_NE(ReadError(path), "") << bad;
  }
  // A LAS file cut inside its last record.
  std::ifstream whole(las, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(whole)), {});
  const std::string cut = Write("cut.las", bytes.substr(0, bytes.size() - 5));
  EXPECT_EQ(StreamPoints(cut).second, ReadError(cut));
  EXPECT_NE(ReadError(cut).find("ends inside point record 2 of 3"), std::string::npos)
      << ReadError(cut);
}

// What io::ForEachPointWithAttributes gives, as a cloud (points and attributes).
io::PointCloud StreamCloud(const std::string& path) {
  io::PointCloud cloud;
  cloud.attributes = io::StreamedAttributes(path);
  io::ForEachPointWithAttributes(
      path, cloud.attributes, [&](const energy::Point3& p, const double* values) {
        cloud.points.push_back(p);
        for (size_t a = 0; a < cloud.attributes.size(); ++a) {
          cloud.attributes[a].values.push_back(values[a]);
        }
      });
  return cloud;
}

TEST_F(PointCloudIoTest, StreamingWithAttributesGivesWhatTheWholeReaderReads) {
  io::PointCloud cloud;
  cloud.points = {{1.5, -2.25, 1e-9}, {3, 4, 5}, {-7, 0.125, 2}};
  cloud.normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  cloud.attributes = {{"red", "uchar", {255, 0, 7}}, {"score", "float", {0.5, 0.25, 1.0}},
                      {"tile", "int", {-3, 4, 2}}};
  const std::string binary = (directory_ / "colours.ply").string();
  io::WritePointCloud(binary, cloud, false);
  const std::string las = (directory_ / "colours.las").string();
  io::WritePointCloud(las, cloud, false);
  const std::string paths[] = {
      binary, las,
      Write("ascii.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                         "property float y\nproperty float z\nproperty float w\n"
                         "property uchar c\nend_header\n1 2 3 0.1 9\n4 5 6 0.7 200\n"),
      Write("columns.xyz", "# comment\n1 2 3 9 8\n\n4 5 6 7 6.5\n"),
      Write("normals.xyz", "1 2 3 0 0 1 4\n4 5 6 1 0 0 5\n"),
      Write("normals_only.xyz", "1 2 3 0 0 1\n4 5 6 1 0 0\n"),
      Write("ragged.xyz", "1 2 3 9\n4 5 6\n7 8 9 1 2\n")};
  for (const std::string& path : paths) {
    const io::PointCloud whole = io::ReadPointCloud(path);
    const io::PointCloud streamed = StreamCloud(path);
    EXPECT_EQ(streamed.points, whole.points) << path;
    ASSERT_EQ(streamed.attributes.size(), whole.attributes.size()) << path;
    for (size_t a = 0; a < whole.attributes.size(); ++a) {
      EXPECT_EQ(streamed.attributes[a].name, whole.attributes[a].name) << path;
      EXPECT_EQ(streamed.attributes[a].type, whole.attributes[a].type) << path;
      EXPECT_EQ(streamed.attributes[a].values, whole.attributes[a].values) << path;
    }
  }
  EXPECT_EQ(StreamCloud(paths[2]).attributes.size(), 2u);  // w (0.1 read as a float), c
  EXPECT_EQ(StreamCloud(paths[3]).attributes.size(), 2u);  // column_4, column_5
  EXPECT_EQ(StreamCloud(paths[4]).attributes.size(), 1u);  // column_7 after the normals
  EXPECT_TRUE(StreamCloud(paths[5]).attributes.empty());   // normals only
  EXPECT_TRUE(StreamCloud(paths[6]).attributes.empty());   // ragged: no columns
}

TEST_F(PointCloudIoTest, APointWriterShortOfItsCountLeavesNoFile) {
  const std::string path = (directory_ / "short.ply").string();
  {
    io::PointWriter writer(path, false, 2, false, {});
    writer.Write({1, 2, 3}, {0, 0, 0}, nullptr);
    EXPECT_THROW(writer.Commit(), std::logic_error);
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(PointCloudIoTest, BadFilesGiveOneLineErrorsNamingTheProblem) {
  EXPECT_NE(ReadError((directory_ / "missing.xyz").string()).find("cannot open"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("empty.xyz", "")).find("no points"), std::string::npos);
  EXPECT_NE(ReadError(Write("bad.xyz", "1 2 3\n1 2 x\n")).find("bad.xyz:2:"), std::string::npos);
  EXPECT_NE(ReadError(Write("nan.xyz", "1 2 3\nnan 2 3\n")).find("non-finite"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("inf.xyz", "1 2 3\n1 inf 3\n")).find("inf.xyz:2:"), std::string::npos);
  EXPECT_NE(ReadError(Write("inf2.xyz", "1 2 3\n1 -inf 3\n")).find("non-finite"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("a.abc", "1 2 3\n")).find("unknown point-cloud format"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("t.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 5\n"
                                     "property float x\nproperty float y\nproperty float z\n"
                                     "end_header\nabc"))
                .find("declares 5 'vertex' items but the remaining 3 bytes hold at most 0"),
            std::string::npos);
  // A list longer than the body: the counts fit, the data does not.
  const std::string list_header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nproperty list uchar float w\nend_header\n";
  EXPECT_NE(ReadError(Write("list.ply", list_header + std::string(12, '\0') + '\xff'))
                .find("binary data ends inside element 'vertex'"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("n.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                     "property float x\nproperty float y\nend_header\n1 2\n"))
                .find("no x, y, z"),
            std::string::npos);
  EXPECT_NE(ReadError(Write("short.off", "OFF\n3 1 0\n0 0 0\n")).find("file ends"),
            std::string::npos);
  for (const char* name : {"missing.xyz", "empty.xyz", "bad.xyz", "nan.xyz", "t.ply"}) {
    const std::string message = ReadError((directory_ / name).string());
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(PointCloudIoTest, TextFromOtherToolsReadsTheSame) {
  const energy::PointList expected = {{1, 2, 3}, {-4.5, 5e-3, 6e10}};
  const std::string plain = "1 2 3\n-4.5 0.005 60000000000\n";
  EXPECT_EQ(io::ReadPoints(Write("plain.xyz", plain)), expected);
  EXPECT_EQ(io::ReadPoints(Write("bom.xyz", "\xEF\xBB\xBF" + plain)), expected);
  EXPECT_EQ(io::ReadPoints(Write("crlf.xyz", "1 2 3\r\n-4.5 0.005 60000000000\r\n")), expected);
  EXPECT_EQ(io::ReadPoints(Write("tabs.xyz", "# x\ty\tz\r\n1\t2\t3\n\t-4.5E0  5.0e-3\t6e+10 # a\n")),
            expected);
  EXPECT_EQ(io::ReadPoints(Write("bom.off", "\xEF\xBB\xBFOFF\r\n2 0 0\r\n1 2 3\r\n-4.5 5e-3 6e10\r\n")),
            expected);
  EXPECT_EQ(io::ReadPoints(Write("bom.ply", "\xEF\xBB\xBFply\r\nformat ascii 1.0\r\nelement vertex 2\r\n"
                                        "property double x\r\nproperty double y\r\nproperty "
                                        "double z\r\nend_header\r\n1 2 3\r\n-4.5 5e-3 6e10\r\n")),
            expected);
  EXPECT_NE(ReadError(Write("utf16.xyz", std::string("\xFF\xFE" "1\0 \0" "2\0", 8)))
                .find("utf16.xyz:1: UTF-16 text is not supported"),
            std::string::npos);
}

TEST_F(PointCloudIoTest, XyzExtraColumnsAreNormalsOnlyWhenUnit) {
  const io::PointCloud with_normals =
      io::ReadPointCloud(Write("n.xyz", "1 2 3 0 0 1\n4 5 6 0.6 0.8 0\n"));
  ASSERT_EQ(with_normals.normals.size(), 2u);
  EXPECT_EQ(with_normals.normals[1], energy::Point3(0.6, 0.8, 0));
  EXPECT_EQ(with_normals.points[1], energy::Point3(4, 5, 6));
  // Colours, a missing column on one line, or a non-unit triple: points only.
  for (const char* text : {"1 2 3 255 0 0\n4 5 6 0 255 0\n", "1 2 3 0 0 1\n4 5 6\n",
                           "1 2 3 0 0 1\n4 5 6 0 0 2\n"}) {
    const io::PointCloud cloud = io::ReadPointCloud(Write("c.xyz", text));
    EXPECT_EQ(cloud.points.size(), 2u);
    EXPECT_TRUE(cloud.normals.empty()) << text;
  }
}

TEST_F(PointCloudIoTest, AbandonedAtomicFileLeavesNothingBehind) {
  const std::string path = (directory_ / "partial.ply").string();
  {
    io::AtomicOutputFile file(path, false);
    file.stream() << "half";
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::is_empty(directory_));
}

}  // namespace
}  // namespace lpd::io
