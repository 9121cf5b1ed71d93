// lpd: the two sides of a thin part that the solve merged, told apart again point by point.
//
// Sides closer than about 2.5 noise deviations are, to every neighbourhood test, one sheet
// with wider noise (energy/sheet_split.h), and the output puts them on their mid-surface,
// farther from either side than the input was (a plate 2.1 deviations thick: CD 7.83 against
// the input's 6.17 x 1e-4). The input still says which side each point most likely came
// from. Around a merged output the offsets z = n.(p - o) of the input points are a mixture
// of two Gaussians at +a and -a with the noise's deviation s, whose moments about 0 are
//   m2 = a^2 + s^2,   m4 = a^4 + 6 a^2 s^2 + 3 s^4,   so   m4 - 3 m2^2 = -2 a^4
// (kurtosis m4 / m2^2 = 3 - 2 a^4 / m2^2: 2.5 for sides 2 s apart, 3 for one sheet). Each
// point moves to the side the sign of its offset picks, +-a along n: on the wrong side with
// probability Phi(-a / s) (16% for sides 2 s apart), but on a side either way, and 2 a
// Phi(-a / s) = 0.32 s from its own side on average. The posterior mean a tanh(a z / s^2)
// has the smaller squared error (RMS 0.67 s against 0.79 s) but is 0.45 s from its own side
// on average and leaves a slab of points between the sides, 0.32 s from the nearer one
// (simulated; docs/method.md, "Thin parts").
//
// The moments are taken over regions of kSidesRegionPoints output points; a region counts
// as merged where its kurtosis is more than kSidesKurtosisStandardErrors standard errors
// (sqrt(24 / n) for n Gaussian offsets) under 3: 2.75 at 1,500 points. Regions of one sheet
// read 2.80-3.10 at their 1% quantile, merged sides 1.9-2.1 deviations apart 2.55-2.75 at
// their median (the benchmark's meshes and thin parts at 10K and 50K, offsets from each
// point's own output, docs/method.md). The points the final step flags as outliers count in
// the moments (at their nearest kept output's reference plane, below): left out, they would
// cut the noise's tails and read 2.8 on one sheet.
#ifndef LPD_SOLVERS_MERGED_SIDES_H_
#define LPD_SOLVERS_MERGED_SIDES_H_

#include <cstdint>
#include <vector>

#include "energy/point3.h"
#include "solvers/neighborhood_size.h"

namespace lpd::solvers {

constexpr int kSidesRegionPoints = 1500;
constexpr double kSidesKurtosisStandardErrors = 2.0;
// Regions are measured around every kSidesRegionCentreStride-th point; every point takes the
// region of its nearest centre.
constexpr int kSidesRegionCentreStride = 96;
// One sheet's regions fall under the bar by chance in about Phi(-2) = 2.3% of cases, and a
// split thin part's in a few percent: a cloud is taken to have merged sides only where a
// tenth of its regions read so, as a thin region grows only where a tenth of the points are
// split (energy/sheet_split.h). JOINT 0.01 and 0.03 have 2% and 2-3% (on
// flat parts, away from the edges), and the correction took them from 1.142 to 1.175e-3 and
// from 5.613 to 5.714e-3. A plate split already can reach it (plate_t0.06 10K 2%, 4.2
// deviations thick: 2.74 -> 2.83 CD x 1e4, input 7.34; docs/method.md).
constexpr double kMinMergedRegionShare = 0.1;
// A thin part is a region, but each region's kurtosis reads with a standard error of 0.13,
// so sides 1.3-2 deviations apart (kurtosis 2.81-2.55) read over the bar in part of their
// regions, and which ones turns on the output's last digits (more iterations moved a region
// more or less). So the merged regions grow, as thin regions do (energy/sheet_split.h): a
// region among the kSidesGrowthNeighbors nearest centres of a merged one is merged too where
// its kurtosis is kSidesGrowthStandardErrors under 3 (2.94). Half a standard error, not one:
// sides 1.4 deviations apart read 2.78, over 2.87 in a quarter of their regions, and the
// growth stopped there, leaving patches on the mid-surface. Neighbouring regions share most
// of their points, so chance seeds on one sheet would grow as well: the growth runs only
// where kMinGrowthSeedShare of the regions are seeds (docs/method.md, "The merged regions
// grow"). The share lies between merged plates' (19% and up) and that of the clouds where
// growing hurts (10-11%; docs/method.md, "The growth at 15% of seeds").
constexpr int kSidesGrowthNeighbors = 6;
constexpr double kSidesGrowthStandardErrors = 0.5;
constexpr double kMinGrowthSeedShare = 0.15;
// At 10K points a region holds 15% of the cloud, the regions overlap so much that the seed
// share swings from draw to draw, and near the seed bar it can fall under both shares above:
// on 16 draws of the benchmark's plate_t0.03 at 10K points and 3% (sides 1.4 deviations
// apart), 8-61 of the 104 regions were seeds, and the three draws with 8-15 came out on the
// mid-plane (P2M x 1e4 7.3-8.3, against 1.4-2.8 on the others). The cloud as a whole tells
// them apart: their offsets, pooled over every point, read kurtosis 2.83-2.84, 3.3-3.6
// standard errors (sqrt(24 / n)) under 3. So the regions also count as merged, and grow,
// where the pooled offsets read kPooledKurtosisStandardErrors under 3 and the seeds are
// kMinSeedChanceMultiple times the share of one sheet's regions that reads under the seed
// bar by chance (ChanceShareUnder: Phi(-2) = 2.3%, so 4.6%). On the benchmark's 27 mesh
// cells at 10K points the pooled offsets read at most 1.9 standard errors under 3 (lilium).
// The share of growable regions, which a chance draw of one sheet also moves as a whole, did
// not tell them apart as well (docs/method.md, "A cloud read as merged as a whole").
constexpr double kMinSeedChanceMultiple = 2.0;
constexpr double kPooledKurtosisStandardErrors = 3.0;
// Neighbouring regions share most of their points, so a noise draw that reads high over a
// patch of a merged part reads so in a cluster of regions: on the benchmark's plate_t0.03 at
// 10K points and 3% (sides 1.4 deviations apart), 10 neighbouring regions of 104 read
// 2.94-3.07 inside 94 merged ones, and their points stayed on the mid-plane (9.9% of the
// outputs, 82% of the squared error). So where the merged regions grow, a region not merged
// joins them where kSidesFillNeighbors or more of its kSidesGrowthNeighbors nearest centres
// are merged, round after round until none joins, with its merged neighbours' mean sides
// (docs/method.md, "Holes in the merged regions"). Along a straight border between merged
// regions and others, about half of a region's nearest centres are merged, and it stays.
constexpr int kSidesFillNeighbors = 4;

// The kurtosis under which a region of `region_points` offsets counts as two sides.
double MaxMergedKurtosis(int region_points);
// The kurtosis under which a region next to a merged one counts as merged too.
double MaxGrowthKurtosis(int region_points);
// The share of one sheet's regions whose kurtosis reads `standard_errors` under 3 or lower by
// chance: Phi(-standard_errors).
double ChanceShareUnder(double standard_errors);

// Two sides +-half_gap with noise variance sigma_squared, from the moments about 0 above;
// false where m4 / m2^2 is not under max_kurtosis or the fit leaves no noise, and where it
// is not over energy::kMinTwoSidesKurtosis (2.2): flat-topped noise (1.8 for uniform noise,
// which the split's within-run test also keeps apart, sheet_split.h) or sides more than
// about 2.8 deviations apart, which the split itself separates.
struct TwoSides {
  double half_gap = 0.0;
  double sigma_squared = 0.0;
};
bool EstimateTwoSides(double m2, double m4, double max_kurtosis, TwoSides* sides);

// The regions of kSidesRegionPoints points around every kSidesRegionCentreStride-th point of
// a pool, each with its offsets' moments about 0 read as two sides (a seed) or not.
struct SideRegions {
  energy::PointList centres;
  std::vector<TwoSides> sides;            // set where under MaxGrowthKurtosis
  std::vector<uint8_t> growable;          // under MaxGrowthKurtosis
  std::vector<uint8_t> seed;              // under MaxMergedKurtosis
  std::vector<uint8_t> merged;            // set by MarkMergedRegions
  std::vector<double> median_abs_offset;  // of the region's offsets
  // Read over its points that see no other layer only (a split region, below); those points
  // alone move.
  std::vector<uint8_t> unsplit_only;
  // Counts in the seed shares: every region but a split one with too few such points.
  std::vector<uint8_t> counted;
  // The sums of z^2 and z^4 over every point's offset z, and their count, leaving out the
  // points that see another layer (`split` of MeasureSideRegions).
  double pooled_m2_sum = 0.0;
  double pooled_m4_sum = 0.0;
  size_t pooled_count = 0;

  // For each of `points`, the region of its nearest centre where that region is merged, else
  // -1.
  std::vector<int> MergedRegionOf(const energy::PointList& points, int num_threads) const;
};

// `offsets[i]` is point i's offset from the surface at `positions[i]`; the regions are
// centred on every kSidesRegionCentreStride-th point of `pool` (indices into positions), none
// merged yet. Empty where fewer than kSidesRegionPoints positions are given.
// `split` (optional, per position): the point's output sees another output layer beyond the
// reference's band (SidesReference). A region where kSidesSplitRegionShare or more of its
// points do has its sides split already (below), but the graph can leave patches of a thin
// part merged beside its split layers: at the corners and rims of sheets 2.8 noise
// deviations apart at 10K points and 2%, 6.7% of the outputs on the mid-plane, 64% of the
// squared error (docs/method.md, "Merged patches beside split layers"). Such a region is
// read over the points that see no other layer, with the bars of their count, where
// kMinUnsplitRegionPoints or more remain; with fewer it is neither a seed nor growable and
// does not count in the seed shares.
SideRegions MeasureSideRegions(const energy::PointList& positions,
                               const std::vector<double>& offsets, const std::vector<int>& pool,
                               int num_threads, const std::vector<uint8_t>* split = nullptr);

// The merged regions of `parts`, measured each over its own points (the solved points of a
// run and its extension to the points a subsample left out, subsample_extension.h), with the
// seeds counted over all of them: the halves of one cloud are one surface, and counted apart,
// a half's share reads under a bar that the cloud's passes (a plate 1.4 deviations thick at
// 50K points and 3%: 18% and 43% seeds, docs/method.md, "One count for both halves"). Where
// under kMinMergedRegionShare of all regions are seeds and the cloud does not read as merged
// as a whole (above, over all parts), none is merged and false is returned; else the seeds
// are merged, and where kMinGrowthSeedShare or more are seeds or the cloud reads as merged as
// a whole, so are the growable regions connected to a seed through growable regions among
// each other's kSidesGrowthNeighbors nearest centres (of the same part), whatever the order
// of the centres, and then the holes among them (kSidesFillNeighbors). The shares count the
// `counted` regions only.
bool MarkMergedRegions(const std::vector<SideRegions*>& parts, int num_threads);

// Whether the probe reads each side's noise of merged sides (neighborhood_size.h):
// kThinCloudShare or more of its regions nearly split (the evidence that also keeps the
// full smoothing balance). The final step's test runs on every cloud: measured from the
// reference, one sheet's regions read under the bar by chance only, and the meshes of the
// learned denoisers' benchmark stay under kMinMergedRegionShare (docs/method.md, "Thin
// parts").
bool SidesMayHaveMerged(const NeighborhoodSize& estimates);

// The offsets z are measured from a reference surface, not from each point's own output.
// Where the graph split part of a thin region by side (energy/sheet_split.h), each output
// follows its own input part way: the walls of a hollow box 1.9 noise deviations thick, at
// 50K points and 3% noise, come out near their mid-surface but spread over a quarter of the
// noise with the input's side, and the offsets from the outputs lose their two-sided shape
// (their regions read 2.9 where such sides read 2.56; docs/method.md, "Thin parts"). The
// reference moves each output along its normal n by the mean of n.(o_j - o) over the
// kSidesReferenceNeighbors outputs o_j nearest across n (in the tangent plane) among its
// kSidesReferenceSearched x kSidesReferenceNeighbors nearest, of those whose normals lie
// within kSidesReferenceMaxAngleDegrees of n (not the other face of an edge) and whose
// height |n.(o_j - o)| is under a band: the middle of what the outputs of a merged part
// spread over, but not the other side of a part that the graph split cleanly (the split
// takes sides 2.8 deviations apart or more, and its outputs lie on them). Nearest in space,
// the neighbours would lean to outputs at o's own height where the spread is as thick as
// their radius, and the reference would follow each output part way (docs/method.md, "The
// reference's neighbours across the normal").
//
// The band is kSidesReferenceBandDeviations times the deviation of the inputs' offsets from
// their own outputs (OffsetDeviation), read after the solve: on the benchmark's meshes 0.82-0.97
// of the true noise, 0.69-0.93 at 50K points and 3%, where the noise probe, whose planes follow
// noise as wide as the spacing, reads 0.47-0.70 (docs/method.md, "The band"). So the band
// spans the two layers of a part split in places only (a plate 2.1 deviations thick at 50K and
// 2%, its outputs on layers 1.4 deviations apart), and stays under the 2.8 deviations between
// the sides of a part split cleanly.
constexpr int kSidesReferenceNeighbors = 60;
constexpr int kSidesReferenceSearched = 2;
constexpr double kSidesReferenceMaxAngleDegrees = 20.0;
constexpr double kSidesReferenceBandDeviations = 2.0;
// A part the graph split cleanly has its outputs on two layers, each point on the layer
// nearer its input. The offsets from a layer are then the noise cut off where it crossed the
// mid-plane, and their kurtosis reads low: 2.76 for sides 4.2 deviations apart, 2.82 for 3
// (simulated), at the seed bar. On plates 4.2 deviations thick at 10K and 20K points, 0-36%
// of the regions read as seeds; moved to +-a, the points left their layers (P2M 1.09 ->
// 1.49 on one draw). An output sees another layer where kSidesOtherLayerShare or more of its
// searched neighbours facing its way lie beyond the band; merged sides' outputs lie within
// it (docs/method.md, "Sides split already").
constexpr double kSidesOtherLayerShare = 0.25;
constexpr double kSidesSplitRegionShare = 0.5;
// Over 200 points a kurtosis reads with a standard error of 0.35, and the seed bar is 2.31
// (1,500 points: 0.13 and 2.75); 100 or 400 moved the sheets above by under 1%.
constexpr int kMinUnsplitRegionPoints = 200;
// Where the points are dense, the searched neighbours span less than the gap of sides split
// cleanly: at 50K points, two sheets 5.9 deviations apart are out of each other's reach, the
// offsets from each sheet, cut off at the mid-plane, read under the seed bar in enough
// regions, and each sheet was split into two layers a deviation apart. So an output also
// sees another layer where a quarter of the outputs facing its way within
// kSidesOtherLayerReachBands bands lie beyond the band (FlagOtherLayerWithinReach;
// docs/method.md, "Beyond the searched neighbours"). Within a ball of radius R, a layer a gap
// g away holds a share (R^2 - g^2) / (2 R^2 - g^2) of the outputs, a quarter where
// R = 1.22 g: 4 bands reached 3.3 bands, and sheets 5.7 deviations apart at 50K points and 1%
// read 3.4 (their band 1.66 deviations; P2M x 1e4 0.647, 0.257 within 5 bands).
constexpr double kSidesOtherLayerReachBands = 5.0;
// The share is read over a subsample of the outputs, about this many within the reach (at 50K
// points the reach holds 3,000-4,000 outputs of two layers).
constexpr int kSidesOtherLayerSampled = 300;
constexpr int kSidesOtherLayerStrideProbes = 64;

// kMedianAbsToSigma times the median of |n_i.(inputs[i] - outputs[i])| over the anchors
// (indices into all three, normals of unit length); 0 without anchors.
double OffsetDeviation(const energy::PointList& inputs, const energy::PointList& outputs,
                       const energy::PointList& normals, const std::vector<int>& anchors);

// The reference above for the `anchors` (indices into outputs, each with a unit normal),
// from the outputs of the anchors only; every other entry is its output. `band` in the frame
// of the points; 0: the outputs themselves. Deterministic for any thread count.
// `other_layer` (optional, per output): whether the anchor sees another layer (above); 0 for
// the other outputs.
energy::PointList SidesReference(const energy::PointList& outputs,
                                 const energy::PointList& normals,
                                 const std::vector<int>& anchors, double band, int num_threads,
                                 std::vector<uint8_t>* other_layer = nullptr);

// Flags in `other_layer` (per output, as SidesReference sets it) each anchor not flagged yet
// where kSidesOtherLayerShare or more of the anchors' outputs within
// kSidesOtherLayerReachBands x `band` that face its way (normals within
// kSidesReferenceMaxAngleDegrees) lie beyond the band, the anchors read being every s-th of
// the list, s = max(1, floor(m / kSidesOtherLayerSampled)) with m the median count of anchors
// within the reach of anchors 0, c, 2c, ... (kSidesOtherLayerStrideProbes of them, c the
// count over that number). Deterministic for any thread count.
// SeparateMergedSides runs it only where the regions read as merged without it.
void FlagOtherLayerWithinReach(const energy::PointList& outputs,
                               const energy::PointList& normals,
                               const std::vector<int>& anchors, double band, int num_threads,
                               std::vector<uint8_t>* other_layer);

// One set of points to tell sides apart in: `outputs` are the projections of `inputs` (same
// order) with unit or zero `normals`; points without `movable` or a normal stay, but their
// offsets count.
struct SidesPart {
  const energy::PointList& inputs;
  const energy::PointList& outputs;
  const energy::PointList& normals;
  const std::vector<uint8_t>& movable;
};

// Each part's outputs with each movable point of a merged region (MarkMergedRegions over the
// parts' regions) moved along its normal to its reference (SidesReference, with the band
// above, from the part's own outputs) + sign(z) a (above), but for the points of a region
// read over its unsplit points that see another layer. A part with fewer than
// kSidesRegionPoints movable points with a normal has no regions and stays. `moved`
// (optional): how many points moved. Deterministic for any thread count.
std::vector<energy::PointList> SeparateMergedSides(const std::vector<SidesPart>& parts,
                                                   int num_threads, int* moved = nullptr);

// The same for one part.
energy::PointList SeparateMergedSides(const energy::PointList& inputs,
                                      const energy::PointList& outputs,
                                      const energy::PointList& normals,
                                      const std::vector<uint8_t>& movable, int num_threads,
                                      int* moved = nullptr);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_MERGED_SIDES_H_
