// lpd: the scalar weights of the energy of Eq. (5), with the paper's values (Table 2) except
// mu_m; lpd/presets.h has the paper's setting whole and the data-derived default.
#ifndef LPD_ENERGY_ENERGY_PARAMETERS_H_
#define LPD_ENERGY_ENERGY_PARAMETERS_H_

#include <string>

namespace lpd::energy {

struct EnergyParameters {
  // lambda: weight of the piecewise-smoothness term (paper: 1, 1..2 for heavy noise).
  double lambda = 1.0;
  // eta: weight of the stitching term || h_i - t_i ||^2 (paper: 5000).
  double eta = 5000.0;
  // mu_l: selectivity of the fitting line processes l_ij, a squared distance in the
  // normalized frame (paper: 5e-9).
  double mu_l = 5e-9;
  // mu_m: selectivity of the smoothness line processes m_ij (paper: 0.13, about 1 - cos 30deg;
  // default 1 - cos 20deg: with data-scaled weights the planes stay bound to their data, so
  // an edge is a sum of smaller steps between neighbours than under the paper's weights).
  double mu_m = 0.06030737921409157;

  // True when every weight is finite and > 0; otherwise `error` names the field.
  bool IsValid(std::string* error) const;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_ENERGY_PARAMETERS_H_
