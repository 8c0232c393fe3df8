#pragma once
// Paper eq. 11, as we read it: the smoothness link between neighbouring points p, q with oriented
// normals n_p, n_q. theta = angle(n_p, n_q) in degrees; the link is convex when the normals
// diverge, (n_p - n_q) . (p - q) > 0, else concave;
//   weight = lambda_smooth * exp(-theta / sigma_convex)   (convex)
//   weight = lambda_smooth * exp(-theta / sigma_concave)  (concave)
// so cuts prefer concave creases, where objects usually meet.

#include <Eigen/Core>

#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

bool isConvexLink(const Eigen::Vector3f& p, const Eigen::Vector3f& n_p, const Eigen::Vector3f& q,
                  const Eigen::Vector3f& n_q);

float smoothnessWeight(const Eigen::Vector3f& p, const Eigen::Vector3f& n_p, const Eigen::Vector3f& q,
                       const Eigen::Vector3f& n_q, const SymmetryCutParams& params);

}  // namespace symmetry_segmentation
