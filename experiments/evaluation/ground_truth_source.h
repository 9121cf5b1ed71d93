// lpd: a ground truth named on the command line or in a sweep config.
//
//   shape:NAME[:key=value,...]   a procedural shape of the catalogue (shape_catalog.h)
//   FILE.off / .obj / .stl       a triangle mesh (a .ply file too, when it has faces)
//   FILE.xyz / .txt / .pts       a clean point set (a .ply file too, when it has no faces)
#ifndef LPD_EXPERIMENTS_EVALUATION_GROUND_TRUTH_SOURCE_H_
#define LPD_EXPERIMENTS_EVALUATION_GROUND_TRUTH_SOURCE_H_

#include <cstdint>
#include <string>

#include "experiments/evaluation/ground_truth.h"

namespace lpd::experiments {

// Throws std::invalid_argument or std::runtime_error with a one-line reason naming the source.
GroundTruth LoadGroundTruth(const std::string& source, int num_samples = kGroundTruthSamples,
                            uint64_t seed = kGroundTruthSeed);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_EVALUATION_GROUND_TRUTH_SOURCE_H_
