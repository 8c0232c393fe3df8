// Convexity-aware smoothness weight (paper eq. 11); the formula is in the header.
#include "symmetry_segmentation/symmetry/smoothness_weight.h"

#include <cmath>

#include "symmetry_segmentation/symmetry/reflection_data_term.h"

namespace symmetry_segmentation {

bool isConvexLink(const Eigen::Vector3f& p, const Eigen::Vector3f& n_p, const Eigen::Vector3f& q,
                  const Eigen::Vector3f& n_q) {
  return (n_p - n_q).dot(p - q) > 0.0f;
}

float smoothnessWeight(const Eigen::Vector3f& p, const Eigen::Vector3f& n_p, const Eigen::Vector3f& q,
                       const Eigen::Vector3f& n_q, const SymmetryCutParams& params) {
  const float theta = angleDeg(n_p, n_q);
  const float sigma = isConvexLink(p, n_p, q, n_q) ? params.sigma_convex_deg : params.sigma_concave_deg;
  return params.lambda_smooth * std::exp(-theta / sigma);
}

}  // namespace symmetry_segmentation
