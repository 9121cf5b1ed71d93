// lpd: a sum of outer products d d^T of 3-vectors (a scatter or second-moment matrix), kept as
// the six scalars of its lower triangle.
//
// `m += d * d.transpose()` on an Eigen::Matrix3d writes the outer product to a temporary on the
// stack and adds it from there, and the 16-byte loads of values just stored as 8-byte halves
// stall (over half of the sheet split's own time at 50K points, docs/performance.md). The sums
// here add the same products in the same order (d_r d_c and d_c d_r are the same number), so
// Matrix() holds the same bits as the Eigen expression would.
//
// LeastSquaresPlaneNormal fits the plane through a set of points from that sum: the probe's
// planes, the sheet split's and the junctions' share it.
#ifndef LPD_ENERGY_SCATTER_SUM_H_
#define LPD_ENERGY_SCATTER_SUM_H_

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace lpd::energy {

class ScatterSum {
 public:
  void Add(const Eigen::Vector3d& d) {
    xx_ += d.x() * d.x();
    yx_ += d.y() * d.x();
    zx_ += d.z() * d.x();
    yy_ += d.y() * d.y();
    zy_ += d.z() * d.y();
    zz_ += d.z() * d.z();
  }

  // The full symmetric matrix.
  Eigen::Matrix3d Matrix() const {
    Eigen::Matrix3d m;
    m << xx_, yx_, zx_, yx_, yy_, zy_, zx_, zy_, zz_;
    return m;
  }

 private:
  double xx_ = 0.0, yx_ = 0.0, zx_ = 0.0, yy_ = 0.0, zy_ = 0.0, zz_ = 0.0;
};

// The unit normal of the least-squares plane through point_at(0), ..., point_at(count - 1)
// (count >= 1), with their centroid in *mean: the eigenvector of the smallest eigenvalue of
// their scatter about the centroid.
template <typename PointAt>
Eigen::Vector3d LeastSquaresPlaneNormal(int count, const PointAt& point_at,
                                        Eigen::Vector3d* mean) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int a = 0; a < count; ++a) sum += point_at(a);
  *mean = sum / count;
  ScatterSum scatter;
  for (int a = 0; a < count; ++a) scatter.Add(point_at(a) - *mean);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter.Matrix()).eigenvectors().col(0);
}

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SCATTER_SUM_H_
