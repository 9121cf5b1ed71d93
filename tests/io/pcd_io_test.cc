// PCD files: the three body layouts built byte by byte here, colours, normals, typed and
// multi-value fields, organized clouds with NaN points, and one-line errors on bad files.
#include "io/pcd_io.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/point_cloud_io.h"

namespace lpd::io {
namespace {

PointCloud Read(const std::string& text) {
  std::istringstream in(text);
  return ReadPointCloud(in, "pcd", "cloud.pcd");
}

// The message ReadPointCloud throws on `text` ("" if none).
std::string ReadError(const std::string& text) {
  try {
    Read(text);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// Whether reading `text` fails with a message holding `part` (the message when not).
::testing::AssertionResult ErrorSays(const std::string& text, const std::string& part) {
  const std::string error = ReadError(text);
  if (error.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "error '" << error << "' does not say '" << part << "'";
}

template <typename T>
void Append(T value, std::string* bytes) {  // little endian, as on the test machines
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes->append(raw, sizeof(T));
}

// A literal-only LZF stream of `data`: runs of at most 32 bytes, each after a control byte
// holding its length minus one (the format liblzf decompresses).
std::string LiteralLzf(const std::string& data) {
  std::string packed;
  for (size_t start = 0; start < data.size(); start += 32) {
    const size_t run = std::min<size_t>(32, data.size() - start);
    packed.push_back(static_cast<char>(run - 1));
    packed.append(data, start, run);
  }
  return packed;
}

// Three points; the second is an organized cloud's "no return".
constexpr float kX[3] = {1.5f, std::numeric_limits<float>::quiet_NaN(), -2.25f};
constexpr float kY[3] = {2.0f, 0.0f, 0.125f};
constexpr float kZ[3] = {-3.0f, 0.0f, 7.0f};
constexpr uint32_t kRgb[3] = {0x00FF8001u, 0, 0xFF0A0B0Cu};  // 0xAARRGGBB
constexpr uint16_t kRing[3] = {7, 0, 65535};
constexpr int8_t kTag[3][2] = {{-1, 2}, {0, 0}, {127, -128}};

const char kHeader[] =
    "# .PCD v0.7 - Point Cloud Data file format\n"
    "VERSION 0.7\n"
    "FIELDS x y z rgb ring _ tag\n"
    "SIZE 4 4 4 4 2 2 1\n"
    "TYPE F F F F U U I\n"
    "COUNT 1 1 1 1 1 1 2\n"
    "WIDTH 3\n"
    "HEIGHT 1\n"
    "VIEWPOINT 0 0 0 1 0 0 0\n"
    "POINTS 3\n";

void ExpectTheThreePoints(const PointCloud& cloud) {
  ASSERT_EQ(cloud.points.size(), 2u);
  EXPECT_EQ(cloud.skipped_points, 1u);
  EXPECT_EQ(cloud.points[0], energy::Point3(1.5, 2.0, -3.0));
  EXPECT_EQ(cloud.points[1], energy::Point3(-2.25, 0.125, 7.0));
  EXPECT_TRUE(cloud.normals.empty());
  std::vector<std::string> names;
  for (const PointAttribute& a : cloud.attributes) names.push_back(a.name + ":" + a.type);
  EXPECT_EQ(names, (std::vector<std::string>{"ring:ushort", "tag_0:char", "tag_1:char",
                                             "red:uchar", "green:uchar", "blue:uchar"}));
  EXPECT_EQ(cloud.FindAttribute("ring")->values, (std::vector<double>{7, 65535}));
  EXPECT_EQ(cloud.FindAttribute("tag_0")->values, (std::vector<double>{-1, 127}));
  EXPECT_EQ(cloud.FindAttribute("tag_1")->values, (std::vector<double>{2, -128}));
  EXPECT_EQ(cloud.FindAttribute("red")->values, (std::vector<double>{0xFF, 0x0A}));
  EXPECT_EQ(cloud.FindAttribute("green")->values, (std::vector<double>{0x80, 0x0B}));
  EXPECT_EQ(cloud.FindAttribute("blue")->values, (std::vector<double>{0x01, 0x0C}));
}

// The rgb field as PCL writes it in ascii: the float whose bits are the colour.
std::string PackedFloatText(uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, 4);
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

TEST(PcdIo, ReadsAsciiBinaryAndCompressedBodiesAlike) {
  std::string ascii = std::string(kHeader) + "DATA ascii\n";
  for (int i = 0; i < 3; ++i) {
    std::ostringstream line;
    line.precision(9);
    line << kX[i] << ' ' << kY[i] << ' ' << kZ[i] << ' ' << PackedFloatText(kRgb[i]) << ' '
         << kRing[i] << " 0 " << int{kTag[i][0]} << ' ' << int{kTag[i][1]} << "\r\n";
    ascii += line.str();
  }
  ExpectTheThreePoints(Read(ascii));

  std::string records;
  for (int i = 0; i < 3; ++i) {
    Append(kX[i], &records);
    Append(kY[i], &records);
    Append(kZ[i], &records);
    Append(kRgb[i], &records);
    Append(kRing[i], &records);
    Append(uint16_t{0xBEEF}, &records);  // padding
    Append(kTag[i][0], &records);
    Append(kTag[i][1], &records);
  }
  ExpectTheThreePoints(Read(std::string(kHeader) + "DATA binary\n" + records));

  // binary_compressed stores each field's values of all points one after the other.
  std::string columns;
  for (int i = 0; i < 3; ++i) Append(kX[i], &columns);
  for (int i = 0; i < 3; ++i) Append(kY[i], &columns);
  for (int i = 0; i < 3; ++i) Append(kZ[i], &columns);
  for (int i = 0; i < 3; ++i) Append(kRgb[i], &columns);
  for (int i = 0; i < 3; ++i) Append(kRing[i], &columns);
  for (int i = 0; i < 3; ++i) Append(uint16_t{0xBEEF}, &columns);
  for (int i = 0; i < 3; ++i) {
    Append(kTag[i][0], &columns);
    Append(kTag[i][1], &columns);
  }
  const std::string packed = LiteralLzf(columns);
  std::string compressed = std::string(kHeader) + "DATA binary_compressed\n";
  Append(static_cast<uint32_t>(packed.size()), &compressed);
  Append(static_cast<uint32_t>(columns.size()), &compressed);
  ExpectTheThreePoints(Read(compressed + packed));
}

TEST(PcdIo, FiniteNormalsAreNormalsAndOthersStayAttributes) {
  const std::string head =
      "FIELDS x y z normal_x normal_y normal_z curvature\nSIZE 8 8 8 4 4 4 4\n"
      "TYPE F F F F F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n";
  const PointCloud cloud = Read(head + "0 0 0 0 0 1 0.5\n1 2 3 1 0 0 0.25\n");
  ASSERT_EQ(cloud.normals.size(), 2u);
  EXPECT_EQ(cloud.normals[1], energy::Point3(1, 0, 0));
  EXPECT_EQ(cloud.FindAttribute("curvature")->type, "float");
  const PointCloud partial = Read(head + "0 0 0 nan nan nan nan\n1 2 3 1 0 0 0.25\n");
  EXPECT_TRUE(partial.normals.empty());
  ASSERT_NE(partial.FindAttribute("normal_x"), nullptr);
  EXPECT_TRUE(std::isnan(partial.FindAttribute("normal_x")->values[0]));
  const PointCloud lone = Read(
      "FIELDS x y z normal_x\nSIZE 4 4 4 4\nTYPE F F F F\nPOINTS 1\nDATA ascii\n1 2 3 0.5\n");
  EXPECT_TRUE(lone.normals.empty());
  ASSERT_NE(lone.FindAttribute("normal_x"), nullptr);
  EXPECT_EQ(lone.FindAttribute("normal_x")->values, std::vector<double>{0.5});
  // Packed colours beside a field called red keep apart from it.
  const PointCloud both = Read(
      "FIELDS x y z red rgb\nSIZE 4 4 4 4 4\nTYPE F F F F U\nPOINTS 1\nDATA ascii\n"
      "1 2 3 0.25 16711680\n");
  EXPECT_EQ(both.FindAttribute("red")->values, std::vector<double>{0.25});
  ASSERT_NE(both.FindAttribute("rgb_red"), nullptr);
  EXPECT_EQ(both.FindAttribute("rgb_red")->values, std::vector<double>{255});
}

// What WritePcd writes, ReadPcd reads back: float coordinates, normals, packed colours with
// alpha and typed attributes unchanged.
TEST(PcdIo, WrittenCloudsReadBackUnchanged) {
  PointCloud cloud;
  cloud.float_coordinates = true;
  cloud.points = {{1.5, -2.25, 3.0}, {0.125, 4.0, -5.5}};
  cloud.normals = {{0, 0, 1}, {0.6, 0.8, 0}};
  cloud.attributes = {{"intensity", "ushort", {7, 65535}},
                      {"red", "uchar", {255, 1}},
                      {"green", "uchar", {128, 2}},
                      {"blue", "uchar", {0, 3}},
                      {"alpha", "uchar", {255, 4}},
                      {"score", "double", {0.1, -1e300}},
                      {"tag", "char", {-128, 127}}};
  std::ostringstream out;
  WritePcd(out, cloud, "out.pcd");
  const PointCloud back = Read(out.str());
  EXPECT_TRUE(back.float_coordinates);
  EXPECT_EQ(back.points, cloud.points);
  ASSERT_EQ(back.normals.size(), 2u);
  EXPECT_NEAR((back.normals[1] - cloud.normals[1]).norm(), 0.0, 1e-7);
  for (const PointAttribute& attribute : cloud.attributes) {
    const PointAttribute* read = back.FindAttribute(attribute.name);
    ASSERT_NE(read, nullptr) << attribute.name;
    EXPECT_EQ(read->type, attribute.type) << attribute.name;
    EXPECT_EQ(read->values, attribute.values) << attribute.name;
  }
  EXPECT_NE(out.str().find("FIELDS x y z normal_x normal_y normal_z rgba intensity score tag\n"
                           "SIZE 4 4 4 4 4 4 4 2 8 1\nTYPE F F F F F F U U F I\n"),
            std::string::npos);
  // An attribute named like a field lpd writes keeps its values under another name.
  PointCloud named = cloud;
  named.attributes.push_back({"normal_x", "float", {0.5, 0.25}});
  std::ostringstream renamed;
  WritePcd(renamed, named, "out.pcd");
  const PointCloud renamed_back = Read(renamed.str());
  EXPECT_EQ(renamed_back.normals.size(), 2u);
  ASSERT_NE(renamed_back.FindAttribute("input_normal_x"), nullptr);
  EXPECT_EQ(renamed_back.FindAttribute("input_normal_x")->values, (std::vector<double>{0.5, 0.25}));
  // Coordinates that did not come as floats are written as doubles.
  cloud.float_coordinates = false;
  cloud.points[0].x() = 0.1;
  std::ostringstream doubles;
  WritePcd(doubles, cloud, "out.pcd");
  EXPECT_EQ(Read(doubles.str()).points, cloud.points);
}

TEST(PcdIo, BadFilesGiveOneLineErrors) {
  const std::string fields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n";
  EXPECT_TRUE(ErrorSays("", "the file is empty"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\n", "before its DATA line"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\nDATA zip\n", "DATA must be ascii"));
  EXPECT_TRUE(ErrorSays("FIELDS x y z\nSIZE 4 4\nTYPE F F F\nPOINTS 1\nDATA ascii\n1 2 3\n",
                        "one value per field"));
  EXPECT_TRUE(ErrorSays("FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\nPOINTS 1\nDATA ascii\n1 2 3\n",
                        "field 'z' has TYPE F and SIZE 2"));
  EXPECT_TRUE(ErrorSays("FIELDS x y z\nSIZE 4 4 4\nTYPE F F U\nPOINTS 1\nDATA ascii\n1 2 3\n",
                        "field 'z' must be of TYPE F"));
  EXPECT_TRUE(ErrorSays("FIELDS x y\nSIZE 4 4\nTYPE F F\nPOINTS 1\nDATA ascii\n1 2\n",
                        "no x, y and z fields"));
  EXPECT_TRUE(ErrorSays(fields + "WIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n", "WIDTH x HEIGHT"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 2\nDATA ascii\n1 2 3\n", "ends after 1 of its 2"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\nDATA ascii\n1 2\n", "expected 3 values, got 2"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\nDATA ascii\n1 2 abc\n", "'abc' is not a number"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\nDATA ascii\n1 2 inf\n", "infinite coordinate"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\nDATA ascii\nnan 2 3\n", "every point has a NaN"));
  EXPECT_TRUE(ErrorSays(fields + "POINTS -1\nDATA ascii\n", "POINTS must be a whole number"));
  // A header that claims 4e9 points on a 12-byte body: nothing is allocated for them.
  EXPECT_TRUE(ErrorSays(fields + "POINTS 4000000000\nDATA binary\n123456789012",
                        "the file ends inside its binary points (12 of 48000000000 bytes)"));
  std::string sizes;
  Append(uint32_t{4}, &sizes);
  Append(uint32_t{12}, &sizes);
  EXPECT_TRUE(ErrorSays(fields + "POINTS 1\nDATA binary_compressed\n" + sizes + "\x1f\x01\x02\x03",
                        "corrupt"));
  std::string huge;
  Append(uint32_t{4}, &huge);
  Append(uint32_t{1200000}, &huge);
  EXPECT_TRUE(ErrorSays(fields + "POINTS 100000\nDATA binary_compressed\n" + huge + "abcd",
                        "cannot hold 1200000"));
  EXPECT_EQ(ReadError("x\n").find("cloud.pcd:1: not a PCD header line"), 0u);
  EXPECT_TRUE(
      ErrorSays("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 4294967297\nPOINTS 1\n"
                "DATA ascii\n1 2 3\n",
                "has COUNT 4294967297"));
  EXPECT_TRUE(
      ErrorSays(fields + "FIELDS a b\nPOINTS 1\nDATA ascii\n1 2 3\n", "a second FIELDS line"));
}

}  // namespace
}  // namespace lpd::io
