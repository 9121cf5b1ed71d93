// lpd: points that the solve left between the two output layers of a thin part, put on the
// layer their input is nearer to.
//
// Where the graph splits a thin part by side (energy/sheet_split.h), most outputs come out on
// the two sides, but points whose neighbourhood was not split fit a surface across both and
// land in between: on a plate 2.8 noise deviations thick at 50K points and 3% noise, a fifth
// of the points lie more than a sixth of the gap from either side (CD / P2M x 1e4 2.54 /
// 2.37; put on the side their input's sign picks, 0.90 / 0.74; by this step 1.44 / 1.28;
// docs/method.md, "Points between two layers"). At 50K the nearest hundred outputs of a
// point on one side barely reach the other, so the layers are read over kLayerNeighbors.
//
// Around every kLayerCentreStride-th output o_c, its kLayerNeighbors nearest outputs o_j
// (normals n_j) give a layer normal c, the dominant eigenvector of sum n_j n_j^T. Of the
// outputs within sqrt(kLayerReachSquared) times the farthest of them, the kLayerNeighbors
// nearest across c (in the plane normal to c) give heights h_j = c.(o_j - o_c): the nearest
// in space reach the other layer over a smaller disk than their own where the gap is a good
// part of their radius r (a plate 2.8 noise deviations thick at 50K points: a fifth of them
// on the other side, and the runs' footprints, below, differ as a curved patch's middle and
// rim do). Around a point on one of two layers a gap g apart, the disk of radius rho across
// that holds kLayerNeighbors outputs on both has rho^2 = r^2 - g^2 / 2 (r^2 / 2 where the
// nearest do not reach the other layer), and the ball of radius sqrt(rho^2 + g^2) takes it
// in: within sqrt(2) r for gaps up to 1.2 r. Their exact 2-means
// split (runs of kMinLayerShare of the points or more; energy::BestTwoRuns) reads as two
// layers where
//   - the runs' means are kMinLayerGapDeviations to kMaxLayerGapDeviations deviations of the
//     inputs' offsets from their outputs apart (OffsetDeviation, merged_sides.h): the sides
//     the split takes apart (2.8 noise deviations and up) but whose points it leaves between,
//     up to 4.5 noise deviations apart where the offsets read 0.57 of the noise (the plate
//     above); far wider gaps are one sheet's middle and rim at noise far under the
//     spacing (20 deviations and more);
//   - the separation (gap over the pooled within-run deviation) passes kMinLayerSeparation
//     (a uniform spread splits at 3.46, one Gaussian sheet at about 2.7);
//   - the footprint difference is under kMaxLayerFootprintDifference (sheet_split.h: two sides
//     cover the same footprint, a curved patch's middle and rim do not).
// An output o whose nearest centre has two layers lies between them where its height
// c.(o - o_c) is more than kBetweenLayerSpreads robust deviations (kMedianAbsToSigma times
// the median absolute deviation about the median) of the nearer run from that run's median,
// and more than kBetweenLayerGapShare of the gap from it. It then moves along c onto the
// median of the run nearer to its input's height c.(p - o_c).
//
// Curved layers. A rod a few noise deviations thick reads as two layers along its dominant
// normal, its front and back halves, and against their medians its flanks lie between them:
// moved along c they left the surface (the benchmark's thin_cylinder, radius 2-3 deviations).
// So each run is also fitted with a quadratic height field over the plane across c (least
// squares, then again over the points near the first fit), and where the larger principal
// curvature of the two fields times the gap exceeds kMaxFlatLayerBend (a rod's halves:
// curvature 1 / r, gap about 4 r / pi, so 1.3; two flat sheets read 0.02-0.3), the fields
// stand in for the medians: an output is measured against the runs' heights at its own
// place across c, the deviations are taken about the fields, and it stays where the fields
// lie less than kMinCurvedLayerGapShare of the gap apart (a rod's flank, where its halves
// meet). A point near a rod's axis still moves, onto the field of its input's side. Flat
// layers keep the medians: six coefficients read noisier than one median, and with the
// fields everywhere the thicker plate at 10K 3% came out farther (P2M 2.68 -> 2.96;
// docs/method.md, "Curved layers, and a second pass").
//
// The layers' heights from the inputs. Where the graph splits the sides only in places (sheets
// 2.8 noise deviations apart at 10K points and 2%: a quarter of the probe's regions), the
// solve pulls the two output layers toward each other: there their medians lay 0.09-0.16
// noise deviations inside the sheets, and their 10th percentiles 0.4 deviations inside. The
// inputs of the outputs read around a centre are fitted with two Gaussian layers of one
// deviation (two_layer_mixture.h), from the runs' medians, and each flat run's outputs move
// by the mixture's mean less the run's median, d, shrunk to d^3 / (d^2 + (2 se)^2) by the
// mean's standard error se (kMixtureMoveStandardErrors): where the layers are already right,
// the fit's own noise would otherwise move them, and the scores' variance reads low where the
// layers overlap (with d^3 / (d^2 + se^2), sheets 1.9 deviations apart at 50K and 3% came out
// at P2M 0.707 against 0.692). Only where the mixture reads as two layers of noise:
//   - its means at least kMinMixtureSeparation of its deviations apart: nearer, a mixture's
//     means are poorly determined;
//   - its deviation under kMaxMixtureDeviationRatio times the inputs' offsets' deviation: two
//     layers of noise read 0.99-1.13 times it on the sheets and 1.02-1.27 on the plates, the
//     higher toward their rims (10K 2-3%, 5th to 95th percentile of the centres); the layers
//     the test finds on meshes read wider (1.2-1.5 on cheburashka at 2%, 1.6-1.8 on JOINT).
//     Where kMinMixtureShare of the centres read mixtures whose means lie apart (a thin part
//     over the cloud: the benchmark's plates and sheets whose sides lie 2.8-6 deviations
//     apart, 0.67-1.0 of their centres; its meshes 0.19 at most), the bar is against the
//     median of those mixtures' deviations instead: where the outputs keep part of their
//     inputs' noise the offsets read low (sheets 2.8 deviations apart at 50K and 2%: 0.5-0.7
//     of the noise, the mixtures 1.4-2.1 times them, and no layer moved).
// All the inputs take part: leaving out those whose outputs lie off the runs (a plate's
// wall at its rim) cut the noise's tails, as the outputs keep part of their inputs' offsets,
// and moved a plate's layers out by 0.07 deviations at 50K points and 2%. Curved layers keep
// their fields.
//
// The layers are read and their points moved kBetweenLayerPasses times: the moves leave
// cleaner runs, and more centres pass the separation test the second time. The later passes
// keep the first's layer normals and reaches, and where the deviation stayed the same they
// read again only the centres whose reach held or holds a moved output (the others would read
// the same outputs: JOINT at 10K points and 2%, one output moved, 137 of 1,248 centres read
// again, the step 0.10 -> 0.07 s; docs/performance.md).
//
// The final step moves points between the layers only where the probe reads the noise wider
// than kMoveBetweenReadRatio spacings, where the split leaves such points. Below it the moves
// cost more than they gain: at 10K points and 2%, moved, cheburashka (0.89 spacings) and the
// thicker plate (0.90) came out at P2M 1.03 and 1.58 instead of 0.83 and 1.39, and
// cheburashka at 2.5% (1.004) 1.39 instead of 1.30. From 1.05 to 1.15 spacings, the
// benchmark's and the held-out cells that read there gain 2-50% in P2M or stay the same, but
// two that lose up to 0.5% (docs/method.md, "Points between the layers from 1.05 spacings").
// It reads the layers and corrects their heights there and where kThinCloudShare or more
// of the probe's regions split, the cloud's evidence of thin parts (the benchmark's
// sheets and plates at 10K 2% read 0.26-0.77 and JOINT 0.33, cheburashka 0.076 and the
// meshes at 50K 1% under 0.01), which spares the others the search.
//
// Layers clearly apart. Below that ratio the points between two layers still move where the
// runs lie kClearLayerGapDeviations deviations apart or more: no noise draw spans such a gap,
// and the outputs between are the noise's tails that the solve left off their side (sheets
// 5.6 noise deviations apart at 50K points and 1%, read at 0.85 spacings: 2.8% of the points,
// two thirds of the squared error). A thin part's rim is surface between its layers, so two
// guards keep it where it is. The centre's footprint must be balanced: the centroid of the
// kLayerNeighbors outputs read lies within kMaxClearLayerAsymmetry of their farthest distance
// across from the centre (a straight rim through the centre: 0.42). And kMinClearLayerShare
// of the centres must read such layers: the sheets and plates read 0.89-0.90 and JOINT 0.25,
// but cheburashka at 10K 1.5% reads 0.07-0.08, at its ears, whose rims lie inside one
// footprint (moved there, its P2M went 0.54 -> 0.60; docs/method.md, "Layers clearly apart").
#ifndef LPD_SOLVERS_BETWEEN_LAYERS_H_
#define LPD_SOLVERS_BETWEEN_LAYERS_H_

#include <cstdint>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

constexpr int kLayerNeighbors = 400;
constexpr double kMoveBetweenReadRatio = 1.05;
constexpr double kLayerReachSquared = 2.0;
// The layers are read around every kLayerCentreStride-th output; each output is tested
// against those of its nearest centre.
constexpr int kLayerCentreStride = 8;
constexpr double kMinLayerShare = 0.15;
constexpr double kMinLayerGapDeviations = 2.0;
constexpr double kMaxLayerGapDeviations = 8.0;
constexpr double kMinLayerSeparation = 4.0;
constexpr double kMaxLayerFootprintDifference = 0.5;
constexpr double kBetweenLayerSpreads = 1.5;
constexpr double kBetweenLayerGapShare = 0.2;
constexpr double kMaxFlatLayerBend = 0.5;
constexpr double kMinCurvedLayerGapShare = 0.5;
constexpr int kBetweenLayerPasses = 2;
constexpr double kMinMixtureSeparation = 2.5;
constexpr double kMaxMixtureDeviationRatio = 1.15;
constexpr double kMixtureMoveStandardErrors = 2.0;
constexpr double kMinMixtureShare = 0.5;
constexpr double kClearLayerGapDeviations = 4.0;
constexpr double kMaxClearLayerAsymmetry = 0.2;
constexpr double kMinClearLayerShare = 0.15;

// `outputs` (the projections of `inputs`, same order, with unit or zero `normals`) with each
// movable output with a normal on two flat layers moved to its inputs' layer, and each that
// lies between two layers (above) moved onto the layer nearer to its input: with
// `move_between` everywhere, without it where the layers lie clearly apart. The layers are
// read from the movable outputs with a normal (the anchors), all before any of a pass's
// moves. Unchanged where fewer than kLayerNeighbors anchors take part. `moved` (optional):
// how many points moved. Deterministic for any thread count.
energy::PointList MoveBetweenLayerPointsOntoLayers(const energy::PointList& inputs,
                                                   const energy::PointList& outputs,
                                                   const energy::PointList& normals,
                                                   const std::vector<uint8_t>& movable,
                                                   bool move_between, int num_threads,
                                                   int* moved = nullptr);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_BETWEEN_LAYERS_H_
