// Points left between two output layers against their known sides: outputs between two layers
// three noise deviations apart move onto a layer, most onto their own, also where the layers
// are as far apart as the neighbourhood reaches; points on a layer, one
// flat sheet with the residual of a denoised output, and a curved cap sampled far finer than
// its curvature do not move; points between two bent layers move onto one; two layers the
// solve pulled toward each other move back out to their inputs' layers, right ones barely
// move; without move_between the points between stay, unless the layers lie clearly apart
// (not at a plate's rim wall, nor where few centres read such layers); the result does not
// depend on the thread count.
#include "solvers/between_layers.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lpd::solvers {
namespace {

// Two layers z = +-half_gap on a 60 x 60 grid each (spacing 0.01, interleaved), inputs at
// their side + noise of deviation sigma; every fifth point's output lies between the layers,
// uniform in height over the middle 60% of the gap, the others on their side.
struct Layered {
  energy::PointList inputs, outputs, normals;
  std::vector<double> side;
  std::vector<uint8_t> between;
};

Layered TwoLayers(double half_gap, double sigma, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::uniform_real_distribution<double> middle(-0.6 * half_gap, 0.6 * half_gap);
  Layered m;
  int index = 0;
  for (int a = 0; a < 60; ++a) {
    for (int b = 0; b < 60; ++b) {
      for (const double side : {-half_gap, half_gap}) {
        const double x = 0.01 * a + (side > 0.0 ? 0.005 : 0.0), y = 0.01 * b;
        const bool between = index++ % 5 == 0;
        m.side.push_back(side);
        m.between.push_back(between);
        m.inputs.emplace_back(x, y, side + noise(random));
        m.outputs.emplace_back(x, y, between ? middle(random) : side);
        m.normals.emplace_back(0.0, 0.0, side > 0.0 ? 1.0 : -1.0);
      }
    }
  }
  return m;
}

// Of the TwoLayers points between (the first of m's points; any added after them are not),
// those whose output lies inside the grid, x and y in [0.1, far], and how many of them the
// result puts within half a sigma of their own layer.
struct InnerBetween {
  int between = 0, on_own = 0;
};

InnerBetween CountInnerBetween(const Layered& m, const energy::PointList& result, double far,
                               double sigma) {
  InnerBetween inner;
  for (size_t i = 0; i < m.between.size(); ++i) {
    const energy::Point3& o = m.outputs[i];
    if (!m.between[i] || std::min(o.x(), o.y()) < 0.1 || std::max(o.x(), o.y()) > far) continue;
    ++inner.between;
    inner.on_own += std::abs(result[i].z() - m.side[i]) < 0.5 * sigma;
  }
  return inner;
}

TEST(MoveBetweenLayerPointsOntoLayers, PointsBetweenTwoLayersMoveOntoALayerMostlyTheirOwn) {
  const double sigma = 0.01;
  const Layered m = TwoLayers(1.5 * sigma, sigma, 5);
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  int moved = 0;
  const energy::PointList result = MoveBetweenLayerPointsOntoLayers(
      m.inputs, m.outputs, m.normals, movable, true, 2, &moved);
  EXPECT_EQ(MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, true, 1),
            result);
  // The layers' heights are corrected from the inputs, by the mixture's noise where the
  // outputs' layers are right (up to 0.45 sigma over one patch of this draw, 0.05 sigma on
  // average): a point counts as on a layer within 0.5 sigma of it.
  int between = 0, on_a_layer = 0, on_own = 0, on_layer = 0;
  double on_layer_move = 0.0;
  for (size_t i = 0; i < result.size(); ++i) {
    EXPECT_EQ(result[i].x(), m.outputs[i].x());
    EXPECT_EQ(result[i].y(), m.outputs[i].y());
    if (!m.between[i]) {
      const double move = std::abs(result[i].z() - m.outputs[i].z());
      EXPECT_LT(move, 0.5 * sigma) << "a point on its layer moved off it: " << i;
      on_layer_move += move;
      ++on_layer;
      continue;
    }
    ++between;
    on_a_layer += std::abs(std::abs(result[i].z()) - 1.5 * sigma) < 0.5 * sigma;
    on_own += std::abs(result[i].z() - m.side[i]) < 0.5 * sigma;
  }
  EXPECT_LT(on_layer_move / on_layer, 0.08 * sigma);
  EXPECT_GE(moved, on_a_layer);
  // Some in-between points lie within a fifth of the gap of a layer and stay (the middle 60%
  // of the gap: 2 / 3 of them lie farther).
  EXPECT_GT(on_a_layer, 0.6 * between);
  // The input picks the wrong side with probability Phi(-1.5) = 6.7%.
  EXPECT_GT(on_own, 0.88 * on_a_layer);
}

// Layers 0.1 apart (three noise deviations), as far as the 400 nearest outputs reach (0.11):
// around a point on a layer, the nearest in space cover a disk of radius 0.04 only of the
// other layer, and the two runs' footprints differ as a curved patch's middle and rim do
// (with them, 44% of the points between move). The nearest across the normal cover the same
// disk on both layers.
TEST(MoveBetweenLayerPointsOntoLayers, LayersAsFarApartAsTheNeighbourhoodReachesAreRead) {
  const double half_gap = 0.05, sigma = 0.1 / 3.0;
  const Layered m = TwoLayers(half_gap, sigma, 7);
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, true, 2);
  int between = 0, on_a_layer = 0;
  for (size_t i = 0; i < result.size(); ++i) {
    if (!m.between[i]) continue;
    ++between;
    on_a_layer += std::abs(std::abs(result[i].z()) - half_gap) < 0.5 * sigma;
  }
  EXPECT_GT(on_a_layer, 0.9 * between);
}

TEST(MoveBetweenLayerPointsOntoLayers, OneSheetDoesNotMove) {
  // A flat sheet whose outputs keep a residual of a third of the noise, and a cap of a sphere
  // of radius 0.3 sampled 0.005 apart with noise 1e-4: its middle and rim part into runs 20
  // noise deviations and more apart.
  std::mt19937_64 random(9);
  for (const bool curved : {false, true}) {
    const double sigma = curved ? 1e-4 : 0.01;
    std::normal_distribution<double> noise(0.0, sigma);
    energy::PointList inputs, outputs, normals;
    for (int a = 0; a < 70; ++a) {
      for (int b = 0; b < 70; ++b) {
        const double x = 0.005 * (a - 35), y = 0.005 * (b - 35);
        energy::Point3 surface(x, y, 0.0), normal(0.0, 0.0, 1.0);
        if (curved) {
          normal = energy::Point3(x, y, std::sqrt(0.09 - x * x - y * y)).normalized();
          surface = 0.3 * normal;
        }
        outputs.push_back(surface + (curved ? 0.0 : noise(random) / 3.0) * normal);
        inputs.push_back(surface + noise(random) * normal);
        normals.push_back(normal);
      }
    }
    const std::vector<uint8_t> movable(outputs.size(), 1);
    int moved = -1;
    EXPECT_EQ(
        MoveBetweenLayerPointsOntoLayers(inputs, outputs, normals, movable, true, 2, &moved),
        outputs)
        << (curved ? "curved cap" : "flat sheet");
    EXPECT_EQ(moved, 0);
  }
}

// Two bent layers z = kappa x^2 / 2 and that plus g (kappa g = 1.5, over the bar of 0.5), on
// grids 0.002 apart, g three noise deviations, every fifth output between them (uniform over
// the middle 60% of the gap) and the inputs on their own layer plus noise. Most of those
// between land within a twentieth of the gap of a layer (the
// fitted fields follow the layers' bend; against the runs' medians 46% do). The points on the
// layers barely move (0.016 sigma on average, 0.31 at most, where a centre reads its layers
// flat and corrects their heights).
TEST(MoveBetweenLayerPointsOntoLayers, PointsBetweenBentLayersMoveOntoALayer) {
  const double gap = 0.025, kappa = 1.5 / gap, spacing = 0.002, sigma = gap / 3.0;
  std::mt19937_64 random(11);
  std::normal_distribution<double> noise(0.0, sigma);
  std::uniform_real_distribution<double> middle(0.2 * gap, 0.8 * gap);
  energy::PointList inputs, outputs, normals;
  std::vector<uint8_t> between;
  int index = 0;
  const auto layer = [&](double x, double side) { return kappa * x * x / 2.0 + side; };
  for (int a = -30; a <= 30; ++a) {
    for (int b = 0; b < 60; ++b) {
      for (const double side : {0.0, gap}) {
        const double x = spacing * (a + (side > 0.0 ? 0.5 : 0.0)), y = spacing * b;
        const bool is_between = index++ % 5 == 0;
        between.push_back(is_between);
        inputs.emplace_back(x, y, layer(x, side) + noise(random));
        outputs.emplace_back(x, y, layer(x, 0.0) + (is_between ? middle(random) : side));
        normals.push_back(energy::Point3(-kappa * x, 0.0, 1.0).normalized());
      }
    }
  }
  const std::vector<uint8_t> movable(outputs.size(), 1);
  int moved = 0;
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(inputs, outputs, normals, movable, true, 2, &moved);
  // The vertical distance to the nearer layer, over the points away from the grid's rim.
  const auto off_layers = [&](const energy::Point3& o) {
    return std::min(std::abs(o.z() - layer(o.x(), 0.0)), std::abs(o.z() - layer(o.x(), gap)));
  };
  int inner_between = 0, on_a_layer = 0, layer_points = 0;
  double layer_points_move = 0.0, largest_move = 0.0;
  for (size_t i = 0; i < result.size(); ++i) {
    if (std::abs(outputs[i].x()) > 0.04 || outputs[i].y() < 0.02 || outputs[i].y() > 0.1) {
      continue;
    }
    if (!between[i]) {
      const double move = (result[i] - outputs[i]).norm();
      layer_points_move += move;
      largest_move = std::max(largest_move, move);
      ++layer_points;
      continue;
    }
    ++inner_between;
    on_a_layer += off_layers(result[i]) < 0.05 * gap;
  }
  EXPECT_LT(layer_points_move / layer_points, 0.05 * sigma);
  EXPECT_LT(largest_move, 0.5 * sigma);
  EXPECT_GT(on_a_layer, 0.55 * inner_between) << on_a_layer << " of " << inner_between;
}

// A rod of radius r along y (34 points around, 0.0055 apart: the benchmark's rod at 10K
// points), its outputs on its surface, denser toward +-z so that its two halves pass the
// separation test (evenly spaced, a circle's halves read 3.4, under 4), and its inputs a
// noise deviation 0.4 r off it; every tenth output lies a tenth of r from the axis, on its
// input's side. Against the halves' medians the flanks, where the halves meet, lie between
// them and move off the surface; against the fitted fields they stay, and the points near
// the axis move out toward the surface.
TEST(MoveBetweenLayerPointsOntoLayers, ARodsFlanksStayAndPointsNearItsAxisMoveOut) {
  const double r = 0.03, spacing = 0.0055, sigma = 0.4 * r;
  const int around = 34;  // 2 pi r / spacing
  std::mt19937_64 random(11);
  std::normal_distribution<double> noise(0.0, sigma);
  energy::PointList inputs, outputs, normals;
  std::vector<uint8_t> near_axis;
  for (int a = 0; a < 200; ++a) {
    for (int b = 0; b < around; ++b) {
      const double even = 2.0 * M_PI * (b + 0.5 * (a % 2)) / around;
      const double angle = even + 0.35 * std::sin(2.0 * even);
      const energy::Point3 radial(std::cos(angle), 0.0, std::sin(angle));
      const energy::Point3 axis_point(0.0, spacing * a, 0.0);
      const bool inside = (a * around + b) % 10 == 0;
      near_axis.push_back(inside);
      inputs.push_back(axis_point + (r + noise(random)) * radial);
      outputs.push_back(axis_point + (inside ? 0.1 * r : r) * radial);
      normals.push_back(radial);
    }
  }
  const std::vector<uint8_t> movable(outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(inputs, outputs, normals, movable, true, 2);
  // How far the outputs lie from the surface, away from the rod's ends.
  double surface_after = 0.0, axis_before = 0.0, axis_after = 0.0;
  int on_surface = 0, inside = 0;
  const auto off_surface = [&](const energy::Point3& o) {
    return std::abs(std::hypot(o.x(), o.z()) - r);
  };
  for (size_t i = 0; i < result.size(); ++i) {
    if (outputs[i].y() < 0.2 || outputs[i].y() > 0.9) continue;
    if (near_axis[i]) {
      axis_before += off_surface(outputs[i]);
      axis_after += off_surface(result[i]);
      ++inside;
    } else {
      surface_after += off_surface(result[i]);
      ++on_surface;
    }
  }
  EXPECT_LT(surface_after / on_surface, 0.02 * r) << "the flanks left the surface";
  EXPECT_LT(axis_after, 0.5 * axis_before) << "the points near the axis did not move out";
}

// The mean distance of the outputs of `result` from the mid-plane between m's layers (on
// whichever layer they lie), away from the grid's rim.
double MeanOutwardHeight(const Layered& m, const energy::PointList& result) {
  double outward = 0.0;
  int count = 0;
  for (size_t i = 0; i < result.size(); ++i) {
    if (std::min(m.outputs[i].x(), m.outputs[i].y()) < 0.1 ||
        std::max(m.outputs[i].x(), m.outputs[i].y()) > 0.5) {
      continue;
    }
    outward += std::abs(result[i].z());
    ++count;
  }
  return outward / count;
}

// Two layers 2.8 noise deviations apart whose outputs the solve pulled 0.15 deviations toward
// each other (each output keeping a third of its noise): the mixture fitted to the inputs
// moves them back out, with or without the points between moved. Where the outputs' layers
// are right, they barely move.
TEST(MoveBetweenLayerPointsOntoLayers, LayersPulledTogetherMoveBackOut) {
  const double sigma = 0.01, half_gap = 1.4 * sigma;
  for (const double pulled : {0.15 * sigma, 0.0}) {
    for (const bool move_between : {false, true}) {
      Layered m = TwoLayers(half_gap, sigma, 13);
      std::mt19937_64 random(17);
      std::normal_distribution<double> residual(0.0, sigma / 3.0);
      for (size_t i = 0; i < m.outputs.size(); ++i) {
        const double side = m.side[i] > 0.0 ? 1.0 : -1.0;
        m.outputs[i].z() = side * (half_gap - pulled) + residual(random);
      }
      const std::vector<uint8_t> movable(m.outputs.size(), 1);
      const energy::PointList result = MoveBetweenLayerPointsOntoLayers(
          m.inputs, m.outputs, m.normals, movable, move_between, 2);
      // Shrunk by the mixture's standard error, the moves take back 70% of the pull.
      EXPECT_NEAR(MeanOutwardHeight(m, result), half_gap,
                  pulled > 0.0 ? 0.5 * pulled : 0.03 * sigma)
          << "pulled in by " << pulled / sigma << " sigma, move_between " << move_between;
    }
  }
}

// The same layers pulled in, where each output keeps 45% of its own input's noise: the
// inputs' offsets from their outputs read about 0.55 noise deviations, and the mixtures' 1.8
// times that. Every centre reads a mixture whose means lie apart, so the mixtures are held
// to their own median deviation, not to the offsets', and the layers move back out.
TEST(MoveBetweenLayerPointsOntoLayers, OutputsKeepingTheirNoiseMoveOutWhereMostCentresReadLayers) {
  const double sigma = 0.01, half_gap = 1.4 * sigma, pulled = 0.15 * sigma;
  Layered m = TwoLayers(half_gap, sigma, 13);
  for (size_t i = 0; i < m.outputs.size(); ++i) {
    const double noise = m.inputs[i].z() - m.side[i];
    m.outputs[i].z() = (m.side[i] > 0.0 ? 1.0 : -1.0) * (half_gap - pulled) + 0.45 * noise;
  }
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, false, 2);
  EXPECT_NEAR(MeanOutwardHeight(m, result), half_gap, 0.5 * pulled);
}

// Without move_between, the points between two layers stay between them.
TEST(MoveBetweenLayerPointsOntoLayers, WithoutMoveBetweenThePointsBetweenStay) {
  const double sigma = 0.01;
  const Layered m = TwoLayers(1.5 * sigma, sigma, 5);
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, false, 2);
  for (size_t i = 0; i < result.size(); ++i) {
    EXPECT_LT(std::abs(result[i].z() - m.outputs[i].z()), 0.5 * sigma) << i;
  }
}

// Layers six noise deviations apart (over four of the inputs' offsets' deviations, which
// the points between widen): without move_between, the points between move onto a layer
// all the same, onto their own, except near the grid's rim, where the centres' footprints
// are one-sided.
TEST(MoveBetweenLayerPointsOntoLayers, PointsBetweenLayersClearlyApartMoveWithoutMoveBetween) {
  const double sigma = 0.01, half_gap = 3.0 * sigma;
  const Layered m = TwoLayers(half_gap, sigma, 23);
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, false, 2);
  const InnerBetween inner = CountInnerBetween(m, result, 0.5, sigma);
  ASSERT_GT(inner.between, 300);
  // Inside, only those already within a fifth of the gap of a layer may stay (none of the
  // middle 60%); an input picks the wrong side with probability Phi(-3) = 0.1%.
  EXPECT_GT(inner.on_own, 0.97 * inner.between);
}

// A plate's two layers six noise deviations apart with a wall at its rim x = 0.6: the wall's
// outputs lie between the layers, on the surface, and stay (without the footprint's balance
// test, 2.3 sigma moves); the points between the layers away from the rim still move.
TEST(MoveBetweenLayerPointsOntoLayers, APlatesRimWallStays) {
  const double sigma = 0.01, half_gap = 3.0 * sigma;
  Layered m = TwoLayers(half_gap, sigma, 29);
  std::mt19937_64 random(31);
  std::normal_distribution<double> noise(0.0, sigma);
  const size_t layer_points = m.outputs.size();
  for (int b = 0; b < 120; ++b) {
    for (int level = 1; level < 6; ++level) {
      const energy::Point3 wall(0.6, 0.005 * b, half_gap * (level / 3.0 - 1.0));
      m.outputs.push_back(wall);
      m.inputs.push_back(wall + energy::Point3(noise(random), 0.0, 0.0));
      m.normals.emplace_back(1.0, 0.0, 0.0);
    }
  }
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, false, 2);
  // Onto a layer a wall point would move a sigma or more; the layers' height corrections
  // (from the inputs' mixture, as on any flat layers) move them 0.74 sigma at most here.
  for (size_t i = layer_points; i < result.size(); ++i) {
    EXPECT_LT(std::abs(result[i].z() - m.outputs[i].z()), 0.9 * sigma) << "wall point " << i;
  }
  const InnerBetween inner = CountInnerBetween(m, result, 0.45, sigma);
  EXPECT_GT(inner.on_own, 0.97 * inner.between);
}

// One flat layer of 120 x 120 points with a second layer six noise deviations above it over
// a corner of 20 x 20 (an ear): too few centres read layers clearly apart, so without
// move_between the points between the two there stay.
TEST(MoveBetweenLayerPointsOntoLayers, AFewLayersClearlyApartMoveNothing) {
  const double sigma = 0.01, gap = 6.0 * sigma;
  std::mt19937_64 random(37);
  std::normal_distribution<double> noise(0.0, sigma);
  energy::PointList inputs, outputs, normals;
  std::vector<uint8_t> between;
  for (int a = 0; a < 120; ++a) {
    for (int b = 0; b < 120; ++b) {
      const bool ear = a < 20 && b < 20;
      for (const double height : {0.0, gap}) {
        if (height > 0.0 && !ear) continue;
        const bool stuck = ear && (a * 20 + b) % 5 == 0;
        const double x = 0.01 * a + (height > 0.0 ? 0.005 : 0.0), y = 0.01 * b;
        inputs.emplace_back(x, y, height + noise(random));
        outputs.emplace_back(x, y, stuck ? 0.5 * gap : height);
        normals.emplace_back(0.0, 0.0, 1.0);
        between.push_back(stuck);
      }
    }
  }
  const std::vector<uint8_t> movable(outputs.size(), 1);
  const energy::PointList result =
      MoveBetweenLayerPointsOntoLayers(inputs, outputs, normals, movable, false, 2);
  int stuck = 0;
  for (size_t i = 0; i < result.size(); ++i) {
    if (!between[i]) continue;
    ++stuck;
    EXPECT_LT(std::abs(result[i].z() - outputs[i].z()), 0.5 * sigma) << i;
  }
  EXPECT_GT(stuck, 100);
}

TEST(MoveBetweenLayerPointsOntoLayers, FewerPointsThanANeighbourhoodStay) {
  Layered m = TwoLayers(0.015, 0.01, 3);
  m.inputs.resize(kLayerNeighbors - 1);
  m.outputs.resize(kLayerNeighbors - 1);
  m.normals.resize(kLayerNeighbors - 1);
  const std::vector<uint8_t> movable(m.outputs.size(), 1);
  EXPECT_EQ(MoveBetweenLayerPointsOntoLayers(m.inputs, m.outputs, m.normals, movable, true, 2),
            m.outputs);
}

}  // namespace
}  // namespace lpd::solvers
