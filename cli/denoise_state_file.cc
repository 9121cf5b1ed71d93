#include "cli/denoise_state_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/atomic_output_file.h"
#include "lpd/parameters.h"

namespace lpd::cli {
namespace {

constexpr char kMagic[8] = {'L', 'P', 'D', 'S', 'T', 'A', 'T', 'E'};
constexpr char kEndMark[8] = {'L', 'P', 'D', 'S', 'E', 'N', 'D', '\n'};
// 2: the saved parameters include the data-derived rules (k = auto, fit and smoothing
// balance, projection, passes). A version-1 state lacks them and would resume under other
// weights than it was written with, so it is refused.
// 4: the saved parameters include the progress test (progress_tolerance). A version-3 state
// was written before it existed and resumes with it off, as it would have run then.
// 5: a checksum of every byte follows the end mark, so that a changed byte is refused
// rather than resumed from; versions 3 and 4 have none.
// 6: the motion test (motion_tolerance) and what it reads: the noise deviation and each
// iteration's motion. An older state resumes with the test off, as it would have run then.
constexpr uint32_t kVersion = 6;
constexpr uint32_t kOldestVersion = 3;
constexpr uint32_t kByteOrderMark = 0x01020304u;

// FNV-1a, 64 bits: a checksum against changed bytes (a flipped bit, an edited field), not
// against an adversary who recomputes it.
class Checksum {
 public:
  void Add(const char* bytes, size_t count) {
    for (size_t i = 0; i < count; ++i) {
      value_ = (value_ ^ static_cast<uint8_t>(bytes[i])) * 0x100000001b3ull;
    }
  }
  uint64_t value() const { return value_; }

 private:
  uint64_t value_ = 0xcbf29ce484222325ull;
};

class Writer {
 public:
  explicit Writer(std::ostream& out) : out_(out) {}
  template <typename T>
  void Value(const T& value) {
    Array(&value, 1);
  }
  template <typename T>
  void Array(const T* values, size_t count) {
    const char* bytes = reinterpret_cast<const char*>(values);
    checksum_.Add(bytes, sizeof(T) * count);
    out_.write(bytes, sizeof(T) * count);
  }
  uint64_t checksum() const { return checksum_.value(); }
  void Text(const std::string& text) {
    Value(static_cast<uint32_t>(text.size()));
    Array(text.data(), text.size());
  }

 private:
  std::ostream& out_;
  Checksum checksum_;
};

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) Fail("cannot open file (missing or unreadable)");
    in_.seekg(0, std::ios::end);
    remaining_ = static_cast<uint64_t>(in_.tellg());
    in_.seekg(0);
  }
  [[noreturn]] void Fail(const std::string& reason) const {
    throw std::runtime_error(path_ + ": " + reason);
  }
  template <typename T>
  T Value() {
    T value;
    Array(&value, 1);
    return value;
  }
  template <typename T>
  void Array(T* values, uint64_t count) {
    // Checked against the file's size first, so a corrupt count cannot allocate or read
    // past the end.
    if (count > remaining_ / sizeof(T)) Fail("truncated state file");
    in_.read(reinterpret_cast<char*>(values), sizeof(T) * count);
    if (!in_) Fail("read error");
    checksum_.Add(reinterpret_cast<const char*>(values), sizeof(T) * count);
    remaining_ -= sizeof(T) * count;
  }
  // Of the bytes read so far.
  uint64_t checksum() const { return checksum_.value(); }
  template <typename T, typename Allocator>
  void Vector(uint64_t count, std::vector<T, Allocator>* values) {
    if (count > remaining_ / sizeof(T)) Fail("truncated state file");
    values->resize(count);
    Array(values->data(), count);
  }
  std::string Text() {
    std::vector<char> bytes;
    Vector(Value<uint32_t>(), &bytes);
    return std::string(bytes.begin(), bytes.end());
  }
  uint64_t remaining() const { return remaining_; }

 private:
  std::string path_;
  std::ifstream in_;
  uint64_t remaining_ = 0;
  Checksum checksum_;
};

// Fails naming `what` unless every value is finite.
template <typename Values>
void RequireFinite(const Values& values, const char* what, const Reader& in) {
  for (const auto& value : values) {
    if (!std::isfinite(static_cast<double>(value))) {
      in.Fail(std::string("corrupt state file (non-finite ") + what + ")");
    }
  }
}

// `count` points of three native doubles.
energy::PointList ReadPoints(int32_t count, Reader* in) {
  std::vector<double> coordinates;
  in->Vector(3 * static_cast<uint64_t>(count), &coordinates);
  energy::PointList points(count);
  for (int i = 0; i < count; ++i) {
    points[i] = energy::Point3(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]);
  }
  return points;
}

}  // namespace

void WriteDenoiseState(const std::string& path, const solvers::DenoiseState& state,
                       const solvers::DenoiseOptions& options, bool overwrite) {
  const energy::Problem& problem = state.problem;
  const energy::Variables& v = state.variables;
  const solvers::MinimizerProgress& progress = state.progress;
  io::AtomicOutputFile file(path, overwrite);
  Writer out(file.stream());
  out.Array(kMagic, sizeof(kMagic));
  out.Value(kVersion);
  out.Value(kByteOrderMark);
  out.Value(static_cast<int32_t>(options.settings.num_threads));
  std::vector<std::string> names;
  for (const std::string& name : DenoiseParameterNames()) {
    if (DenoiseParameterApplies(name, options.solver)) names.push_back(name);
  }
  // The balance the run used: a resumed state keeps no neighbourhood estimates to scale it by
  // (NeighborhoodSize::smoothing_scale).
  solvers::DenoiseOptions used = options;
  used.weights.smoothing_balance *= state.neighborhood.smoothing_scale;
  out.Value(static_cast<uint32_t>(names.size()));
  for (const std::string& name : names) {
    out.Text(name);
    out.Text(GetDenoiseParameter(name, used));
  }
  out.Array(problem.frame.center.data(), 3);
  out.Value(problem.frame.scale);
  out.Value(options.problem.min_squared_distance_ratio);
  const int32_t n = problem.num_points();
  const int32_t k = problem.k();
  out.Value(n);
  out.Value(k);
  out.Array(state.order.data(), state.order.size());
  for (const energy::Point3& p : problem.points) out.Array(p.data(), 3);
  out.Value(static_cast<int32_t>(state.left_out.size()));
  out.Array(state.left_out.data(), state.left_out.size());
  for (const energy::Point3& p : state.left_out_points) out.Array(p.data(), 3);
  out.Array(problem.graph.neighbors.data(), problem.graph.neighbors.size());
  out.Array(v.h.data(), v.h.size());
  out.Array(v.t.data(), v.t.size());
  out.Array(v.l.data(), v.l.size());
  out.Value(static_cast<int64_t>(v.m.size()));
  out.Array(v.m.data(), v.m.size());
  out.Array(v.s.data(), v.s.size());
  out.Value(static_cast<int32_t>(progress.iterations));
  out.Value(progress.mu_l);
  out.Value(progress.gnc.mu_l.current);
  out.Value(progress.gnc.mu_m.current);
  out.Value(static_cast<int32_t>(progress.gnc.stage_iterations));
  out.Value(static_cast<uint32_t>(progress.energy_history.size()));
  out.Array(progress.energy_history.data(), progress.energy_history.size());
  out.Value(progress.noise_sigma);
  out.Value(static_cast<uint32_t>(progress.motion_history.size()));
  out.Array(progress.motion_history.data(), progress.motion_history.size());
  out.Array(kEndMark, sizeof(kEndMark));
  out.Value(out.checksum());
  file.Commit();
}

SavedDenoiseRun ReadDenoiseState(const std::string& path) {
  Reader in(path);
  char magic[sizeof(kMagic)];
  if (in.remaining() < sizeof(magic)) in.Fail("not an lpd state file (too short)");
  in.Array(magic, sizeof(magic));
  if (std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) in.Fail("not an lpd state file");
  const uint32_t version = in.Value<uint32_t>();
  if (version < kOldestVersion || version > kVersion) {
    in.Fail("state file version " + std::to_string(version) + ", this lpd reads versions " +
            std::to_string(kOldestVersion) + "-" + std::to_string(kVersion));
  }
  if (in.Value<uint32_t>() != kByteOrderMark) {
    in.Fail("state file written on a machine of the other byte order");
  }
  SavedDenoiseRun run;
  run.num_threads = in.Value<int32_t>();
  if (run.num_threads < 1 || run.num_threads > 1024) {
    in.Fail("corrupt state file (thread count " + std::to_string(run.num_threads) + ")");
  }
  if (version == 3) run.parameters.emplace_back("progress_tolerance", "0");
  const uint32_t num_parameters = in.Value<uint32_t>();
  for (uint32_t p = 0; p < num_parameters; ++p) {
    std::string name = in.Text();
    run.parameters.emplace_back(std::move(name), in.Text());
  }
  if (version < 6) run.parameters.emplace_back("motion_tolerance", "0");

  solvers::DenoiseState& state = run.state;
  energy::Problem& problem = state.problem;
  in.Array(problem.frame.center.data(), 3);
  problem.frame.scale = in.Value<double>();
  const double min_squared_distance_ratio = in.Value<double>();
  if (!problem.frame.center.allFinite() || !(problem.frame.scale > 0.0) ||
      !std::isfinite(problem.frame.scale) || !(min_squared_distance_ratio >= 0.0) ||
      !std::isfinite(min_squared_distance_ratio)) {
    in.Fail("corrupt state file (frame)");
  }
  const int32_t n = in.Value<int32_t>();
  const int32_t k = in.Value<int32_t>();
  if (n < 2 || k < 1 || k >= n) in.Fail("corrupt state file (point count or k)");
  in.Vector(n, &state.order);
  problem.points = ReadPoints(n, &in);
  for (const energy::Point3& p : problem.points) {
    if (!p.allFinite()) in.Fail("corrupt state file (non-finite point)");
  }
  const int32_t num_left_out = in.Value<int32_t>();
  if (num_left_out < 0) in.Fail("corrupt state file (left-out point count)");
  in.Vector(num_left_out, &state.left_out);
  state.left_out_points = ReadPoints(num_left_out, &in);
  for (const energy::Point3& p : state.left_out_points) {
    if (!p.allFinite()) in.Fail("corrupt state file (non-finite point)");
  }
  // Every input index once, over the solved and the left-out points.
  const int64_t total = static_cast<int64_t>(n) + num_left_out;
  std::vector<uint8_t> seen(total, 0);
  for (const std::vector<int>* indices : {&state.order, &state.left_out}) {
    for (int index : *indices) {
      if (index < 0 || index >= total || seen[index]++) {
        in.Fail("corrupt state file (input order)");
      }
    }
  }
  problem.graph.k = k;
  in.Vector(static_cast<uint64_t>(n) * k, &problem.graph.neighbors);
  for (int j : problem.graph.neighbors) {
    if (j < 0 || j >= n) in.Fail("corrupt state file (neighbour index)");
  }
  energy::BuildPairs(&problem.graph);
  energy::ComputeWeights(min_squared_distance_ratio, &problem);

  energy::Variables& v = state.variables;
  v.h.resize(n, 4);
  v.t.resize(n, 4);
  v.l.resize(n, k + 1);
  in.Array(v.h.data(), v.h.size());
  in.Array(v.t.data(), v.t.size());
  in.Array(v.l.data(), v.l.size());
  const int64_t num_pairs = in.Value<int64_t>();
  if (num_pairs != problem.graph.num_pairs()) in.Fail("corrupt state file (pair count)");
  v.m.resize(num_pairs);
  v.s.resize(num_pairs);
  in.Array(v.m.data(), v.m.size());
  in.Array(v.s.data(), v.s.size());
  if (!v.h.allFinite() || !v.t.allFinite() || !v.l.allFinite() || !v.m.allFinite() ||
      !v.s.allFinite()) {
    in.Fail("corrupt state file (non-finite planes or line processes)");
  }

  solvers::MinimizerProgress& progress = state.progress;
  progress.iterations = in.Value<int32_t>();
  progress.mu_l = in.Value<double>();
  progress.gnc.mu_l.current = in.Value<double>();
  progress.gnc.mu_m.current = in.Value<double>();
  progress.gnc.stage_iterations = in.Value<int32_t>();
  in.Vector(in.Value<uint32_t>(), &progress.energy_history);
  RequireFinite(progress.energy_history, "energy", in);
  if (version >= 6) {
    progress.noise_sigma = in.Value<double>();
    in.Vector(in.Value<uint32_t>(), &progress.motion_history);
  } else {
    progress.motion_history.assign(progress.energy_history.size(), NAN);
  }
  if (progress.iterations < 0 || progress.gnc.stage_iterations < 0 ||
      !(std::isnan(progress.mu_l) || progress.mu_l > 0.0) ||
      !(std::isnan(progress.noise_sigma) ||
        (progress.noise_sigma > 0.0 && std::isfinite(progress.noise_sigma))) ||
      progress.motion_history.size() != progress.energy_history.size()) {
    in.Fail("corrupt state file (progress)");
  }
  for (double motion : progress.motion_history) {
    if (!(std::isnan(motion) || (motion >= 0.0 && std::isfinite(motion)))) {
      in.Fail("corrupt state file (motion)");
    }
  }
  char end[sizeof(kEndMark)];
  in.Array(end, sizeof(end));
  if (std::memcmp(end, kEndMark, sizeof(kEndMark)) != 0) {
    in.Fail("corrupt state file (bad end mark)");
  }
  if (version >= 5) {
    const uint64_t computed = in.checksum();
    if (in.Value<uint64_t>() != computed) {
      in.Fail("corrupt state file (checksum mismatch: the file was changed after it was saved)");
    }
  }
  if (in.remaining() != 0) in.Fail("corrupt state file (bytes after the end mark)");
  return run;
}

}  // namespace lpd::cli
