#include "tiles/tile_store.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <stdexcept>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "io/atomic_output_file.h"
#include "io/interruption.h"
#include "io/las_io.h"
#include "io/point_cloud_io.h"

namespace lpd::tiles {
namespace {

constexpr size_t kChunkPoints = 1 << 16;  // points per read of points.bin
constexpr uint64_t kSampleSeed = 1;

// One own point's result in a tile file.
struct Record {
  uint32_t index;
  double position[3];
  float normal[3];
  float outlier_score, feature_score;
  uint8_t is_outlier, is_feature, kept;
};
constexpr size_t kRecordBytes = 4 + 24 + 12 + 8 + 3;

void Pack(const Record& r, char* out) {
  std::memcpy(out, &r.index, 4);
  std::memcpy(out + 4, r.position, 24);
  std::memcpy(out + 28, r.normal, 12);
  std::memcpy(out + 40, &r.outlier_score, 4);
  std::memcpy(out + 44, &r.feature_score, 4);
  out[48] = static_cast<char>(r.is_outlier);
  out[49] = static_cast<char>(r.is_feature);
  out[50] = static_cast<char>(r.kept);
}

Record Unpack(const char* in) {
  Record r;
  std::memcpy(&r.index, in, 4);
  std::memcpy(r.position, in + 4, 24);
  std::memcpy(r.normal, in + 28, 12);
  std::memcpy(&r.outlier_score, in + 40, 4);
  std::memcpy(&r.feature_score, in + 44, 4);
  r.is_outlier = static_cast<uint8_t>(in[48]);
  r.is_feature = static_cast<uint8_t>(in[49]);
  r.kept = static_cast<uint8_t>(in[50]);
  return r;
}

// A file of `size` bytes created at `path` and mapped into memory for reading and writing;
// removed when the object goes.
// Where the merge writes the kept points, in input order.
class MergedOutput {
 public:
  virtual ~MergedOutput() = default;
  // Point `index` of tile `tile`, its result `r` and its input row's `attributes`.
  virtual void Write(uint32_t index, int tile, bool seam, const Record& r,
                     const double* attributes) = 0;
  virtual void Commit() = 0;
};

// PLY (or XYZ): normals, the input's attributes (input_NAME where a name is one of lpd's
// fields), then lpd's fields.
class PointOutput : public MergedOutput {
 public:
  PointOutput(const std::string& output, bool overwrite, size_t count,
              const std::vector<io::PointAttribute>& attributes)
      : num_attributes_(attributes.size()) {
    const std::vector<std::pair<std::string, std::string>> lpd_fields = {
        {"outlier", "float"}, {"outlier_score", "float"}, {"feature", "float"},
        {"feature_score", "float"}, {"seam", "float"}, {"source_index", "uint"},
        {"tile", "uint"}};
    std::vector<std::pair<std::string, std::string>> fields;
    auto taken = [&](const std::string& name) {
      auto named = [&name](const auto& field) { return field.first == name; };
      return std::any_of(fields.begin(), fields.end(), named) ||
             std::any_of(lpd_fields.begin(), lpd_fields.end(), named);
    };
    for (const io::PointAttribute& attribute : attributes) {
      std::string name = attribute.name;
      while (taken(name)) name = "input_" + name;
      fields.emplace_back(name, attribute.type);
    }
    fields.insert(fields.end(), lpd_fields.begin(), lpd_fields.end());
    writer_ = std::make_unique<io::PointWriter>(output, overwrite, count, /*with_normals=*/true,
                                                fields);
  }
  void Write(uint32_t index, int tile, bool seam, const Record& r,
             const double* attributes) override {
    values_.assign(attributes, attributes + num_attributes_);
    values_.insert(values_.end(), {static_cast<double>(r.is_outlier), r.outlier_score,
                                   static_cast<double>(r.is_feature), r.feature_score,
                                   seam ? 1.0 : 0.0, static_cast<double>(index),
                                   static_cast<double>(tile)});
    writer_->Write(energy::Point3(r.position[0], r.position[1], r.position[2]),
                   energy::Point3(r.normal[0], r.normal[1], r.normal[2]), values_.data());
  }
  void Commit() override { writer_->Commit(); }

 private:
  size_t num_attributes_;
  std::unique_ptr<io::PointWriter> writer_;
  std::vector<double> values_;
};

// LAS, a record at a time: the input's fields and, when the input is LAS, its header (else
// one for the points' bounding box `box`); class 7 (low noise) on the outliers that
// --outliers=mark keeps, as untiled runs write them.
class LasOutput : public MergedOutput {
 public:
  LasOutput(const std::string& input, const std::string& output, bool overwrite,
            const std::vector<io::PointAttribute>& attributes, const Eigen::AlignedBox3d& box)
      : num_attributes_(attributes.size()), file_(output, overwrite) {
    std::vector<std::string> names;
    for (const io::PointAttribute& attribute : attributes) names.push_back(attribute.name);
    classification_ = std::find(names.begin(), names.end(), "classification") - names.begin();
    if (classification_ == names.size()) names.push_back("classification");
    io::LasLayout layout;
    if (io::FileExtension(input) == "las") {
      std::ifstream in(input, std::ios::binary);
      layout = io::ReadLasHeader(input, in).layout;
    } else {
      layout = io::DefaultLasLayout(box.min(), box.max());
    }
    values_.resize(names.size(), 0.0);
    writer_ = std::make_unique<io::LasWriter>(file_.stream(), std::move(layout), names, output);
  }
  void Write(uint32_t, int, bool, const Record& r, const double* attributes) override {
    std::copy_n(attributes, num_attributes_, values_.begin());
    if (classification_ == num_attributes_) values_[classification_] = 0.0;
    constexpr double kLowNoise = 7;  // ASPRS class 7
    if (r.is_outlier) values_[classification_] = kLowNoise;
    writer_->Write(energy::Point3(r.position[0], r.position[1], r.position[2]), values_.data());
  }
  void Commit() override {
    writer_->Finish();
    file_.Commit();
  }

 private:
  size_t num_attributes_;
  size_t classification_;
  io::AtomicOutputFile file_;
  std::unique_ptr<io::LasWriter> writer_;
  std::vector<double> values_;
};

class MappedFile {
 public:
  MappedFile(const std::string& path, size_t size) : path_(path), size_(size) {
    descriptor_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0600);
    if (descriptor_ < 0 || ::ftruncate(descriptor_, static_cast<off_t>(size)) != 0) {
      Release();
      throw std::runtime_error("cannot create " + path + ": " + std::strerror(errno));
    }
    if (size_ > 0) {
      void* mapped = ::mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_SHARED, descriptor_, 0);
      if (mapped == MAP_FAILED) {
        Release();
        throw std::runtime_error("cannot map " + path + ": " + std::strerror(errno));
      }
      data_ = static_cast<char*>(mapped);
    }
  }
  ~MappedFile() { Release(); }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  char* data() { return data_; }

 private:
  void Release() {
    if (data_) ::munmap(data_, size_);
    if (descriptor_ >= 0) ::close(descriptor_);
    ::unlink(path_.c_str());
    data_ = nullptr;
    descriptor_ = -1;
  }
  std::string path_;
  size_t size_;
  int descriptor_ = -1;
  char* data_ = nullptr;
};

std::string TilePath(const std::string& directory, int tile) {
  return directory + "/tile_" + std::to_string(tile) + ".bin";
}

// Writes points to points.bin and keeps a uniform sample of them (reservoir sampling).
class Spooler {
 public:
  Spooler(const std::string& directory, size_t sample_size, energy::PointList* sample)
      : out_(directory + "/points.bin", std::ios::binary), sample_size_(sample_size),
        sample_(sample), random_(kSampleSeed) {
    if (!out_) throw std::runtime_error("cannot write " + directory + "/points.bin");
    sample_->clear();
  }

  void Add(const energy::Point3& p) {
    if (count_ >= UINT32_MAX) throw std::runtime_error("more than 2^32 - 1 points");
    if (count_ % kChunkPoints == 0) io::ThrowIfInterrupted();
    out_.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
    if (sample_->size() < sample_size_) {
      sample_->push_back(p);
    } else {
      const size_t slot = std::uniform_int_distribution<size_t>(0, count_)(random_);
      if (slot < sample_size_) (*sample_)[slot] = p;
    }
    ++count_;
  }

  size_t Finish() {
    out_.close();
    if (!out_) {
      throw std::runtime_error("writing the tiles' copy of the points failed (disk full?)");
    }
    return count_;
  }

 private:
  std::ofstream out_;
  size_t sample_size_;
  energy::PointList* sample_;
  std::mt19937_64 random_;
  size_t count_ = 0;
};

}  // namespace

std::vector<double> TileSummary::Flatten() const {
  return {static_cast<double>(tile),       static_cast<double>(own_points),
          static_cast<double>(kept),       static_cast<double>(outliers),
          static_cast<double>(features),   static_cast<double>(halo_points),
          static_cast<double>(k),          static_cast<double>(solved_points),
          static_cast<double>(iterations), converged ? 1.0 : 0.0,
          seconds,                         box.min().x(),
          box.min().y(),                   box.min().z(),
          box.max().x(),                   box.max().y(),
          box.max().z(),                   halo_width};
}

TileSummary TileSummary::Unflatten(const std::vector<double>& v) {
  if (v.size() != 18) throw std::runtime_error("malformed tile summary");
  TileSummary s;
  s.tile = static_cast<int>(v[0]);
  s.own_points = static_cast<long>(v[1]);
  s.kept = static_cast<long>(v[2]);
  s.outliers = static_cast<long>(v[3]);
  s.features = static_cast<long>(v[4]);
  s.halo_points = static_cast<long>(v[5]);
  s.k = static_cast<int>(v[6]);
  s.solved_points = static_cast<int>(v[7]);
  s.iterations = static_cast<int>(v[8]);
  s.converged = v[9] != 0.0;
  s.seconds = v[10];
  s.box = Eigen::AlignedBox3d(Eigen::Vector3d(v[11], v[12], v[13]),
                              Eigen::Vector3d(v[14], v[15], v[16]));
  s.halo_width = v[17];
  return s;
}

std::string TileStore::CreateDirectory() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/lpd-tiles-XXXXXX";
  if (!mkdtemp(pattern.data())) {
    throw std::runtime_error("cannot create a temporary directory for the tiles: " + pattern);
  }
  return pattern;
}

TileStore::TileStore(std::string directory, bool owner)
    : directory_(std::move(directory)), owner_(owner) {
  slots_.push_back(io::RegisterTemporaryFile(directory_));
  slots_.push_back(io::RegisterTemporaryFile(directory_ + "/points.bin"));
}

TileStore::~TileStore() {
  for (int slot : slots_) io::UnregisterTemporaryFile(slot);
  if (!owner_ || directory_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

size_t TileStore::Spool(const std::string& input, size_t sample_size, energy::PointList* sample) {
  Spooler spooler(directory_, sample_size, sample);
  io::ForEachPoint(input, [&](const energy::Point3& p) { spooler.Add(p); });
  return spooler.Finish();
}

size_t TileStore::Spool(const energy::PointList& points, size_t sample_size,
                        energy::PointList* sample) {
  Spooler spooler(directory_, sample_size, sample);
  for (const energy::Point3& p : points) spooler.Add(p);
  return spooler.Finish();
}

void TileStore::Scan(const std::function<void(uint32_t, const energy::Point3&)>& visit) const {
  std::ifstream in(directory_ + "/points.bin", std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + directory_ + "/points.bin");
  std::vector<double> chunk(3 * kChunkPoints);
  uint32_t index = 0;
  while (in) {
    in.read(reinterpret_cast<char*>(chunk.data()),
            static_cast<std::streamsize>(chunk.size() * sizeof(double)));
    io::ThrowIfInterrupted();
    const size_t read = static_cast<size_t>(in.gcount()) / (3 * sizeof(double));
    for (size_t a = 0; a < read; ++a, ++index) {
      visit(index, energy::Point3(chunk[3 * a], chunk[3 * a + 1], chunk[3 * a + 2]));
    }
  }
}

void TileStore::WriteTile(int tile, const std::vector<uint32_t>& own,
                          const solvers::TileOutcome& outcome) const {
  slots_.push_back(io::RegisterTemporaryFile(TilePath(directory_, tile)));
  std::ofstream out(TilePath(directory_, tile), std::ios::binary);
  char bytes[kRecordBytes];
  for (size_t a = 0; a < own.size(); ++a) {
    Record r;
    r.index = own[a];
    for (int c = 0; c < 3; ++c) {
      r.position[c] = outcome.projected[a][c];
      r.normal[c] = static_cast<float>(outcome.normals[a][c]);
    }
    r.outlier_score = static_cast<float>(outcome.indicators.outlier_score[a]);
    r.feature_score = static_cast<float>(outcome.indicators.feature_score[a]);
    r.is_outlier = outcome.indicators.is_outlier[a];
    r.is_feature = outcome.indicators.is_feature[a];
    r.kept = outcome.kept[a];
    Pack(r, bytes);
    out.write(bytes, kRecordBytes);
  }
  out.close();
  if (!out) throw std::runtime_error("writing " + TilePath(directory_, tile) + " failed");
}

void TileStore::Merge(const solvers::TileTree& tree, const std::vector<TileSummary>& tiles,
                      const std::string& input, const std::string& output,
                      bool overwrite) const {
  size_t kept = 0;
  for (const TileSummary& tile : tiles) kept += tile.kept;
  // The tiles' records gathered by input index into one memory-mapped file, one tile file
  // open at a time: the merge then holds three files open however many tiles there are
  // (opening them all at once failed past the limit of open files, 1024 by default).
  size_t count = 0;
  for (int t = 0; t < tree.num_tiles; ++t) {
    std::error_code error;
    const uintmax_t bytes = std::filesystem::file_size(TilePath(directory_, t), error);
    if (error || bytes % kRecordBytes != 0) {
      throw std::runtime_error("missing or damaged " + TilePath(directory_, t));
    }
    count += bytes / kRecordBytes;
  }
  const std::string gathered_path = directory_ + "/results.bin";
  slots_.push_back(io::RegisterTemporaryFile(gathered_path));
  MappedFile gathered(gathered_path, count * kRecordBytes);
  std::vector<uint8_t> filled(count, 0);
  std::vector<char> bytes(kRecordBytes * kChunkPoints);
  for (int t = 0; t < tree.num_tiles; ++t) {
    std::ifstream in(TilePath(directory_, t), std::ios::binary);
    if (!in) throw std::runtime_error("missing " + TilePath(directory_, t));
    while (in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())) || in.gcount() > 0) {
      const size_t records = static_cast<size_t>(in.gcount()) / kRecordBytes;
      for (size_t r = 0; r < records; ++r) {
        const char* record = bytes.data() + r * kRecordBytes;
        uint32_t index;
        std::memcpy(&index, record, sizeof(index));
        if (index >= count || filled[index]++) {
          throw std::runtime_error(TilePath(directory_, t) + " holds a point twice or out of range");
        }
        std::memcpy(gathered.data() + static_cast<size_t>(index) * kRecordBytes, record,
                    kRecordBytes);
      }
      io::ThrowIfInterrupted();
    }
  }
  const std::vector<io::PointAttribute> attributes =
      input.empty() ? std::vector<io::PointAttribute>() : io::StreamedAttributes(input);
  std::unique_ptr<MergedOutput> merged;
  if (io::OutputFormat(output, "") == "las") {
    Eigen::AlignedBox3d box;
    for (const TileSummary& tile : tiles) box.extend(tile.box);
    merged = std::make_unique<LasOutput>(input, output, overwrite, attributes, box);
  } else {
    merged = std::make_unique<PointOutput>(output, overwrite, kept, attributes);
  }
  auto write = [&](uint32_t index, const energy::Point3& p, const double* row) {
    if (index >= count || !filled[index]) {
      throw std::runtime_error("no tile holds the result of point " + std::to_string(index));
    }
    const Record r = Unpack(gathered.data() + static_cast<size_t>(index) * kRecordBytes);
    if (!r.kept) return;
    const int t = tree.Locate(p);
    bool seam = false;
    for (const TileSummary& other : tiles) {
      if (other.tile != t && solvers::InHalo(other.box, other.halo_width, p)) {
        seam = true;
        break;
      }
    }
    merged->Write(index, t, seam, r, row);
  };
  if (attributes.empty()) {
    Scan([&](uint32_t index, const energy::Point3& p) { write(index, p, nullptr); });
  } else {
    // The input again, beside points.bin: the spooled points, in the same order.
    std::ifstream spooled(directory_ + "/points.bin", std::ios::binary);
    uint32_t index = 0;
    io::ForEachPointWithAttributes(input, attributes,
                                   [&](const energy::Point3& p, const double* row) {
                                     double stored[3];
                                     if (!spooled.read(reinterpret_cast<char*>(stored),
                                                       sizeof(stored)) ||
                                         p != energy::Point3(stored[0], stored[1], stored[2])) {
                                       throw std::runtime_error(
                                           input + " changed while it was denoised");
                                     }
                                     write(index++, p, row);
                                   });
    if (index != count) throw std::runtime_error(input + " changed while it was denoised");
  }
  merged->Commit();
}

}  // namespace lpd::tiles
