#include "symmetry_segmentation/synthetic/scene_kind.h"

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace synthetic {

std::string toString(SceneKind kind) {
  switch (kind) {
    case SceneKind::Isolated: return "isolated";
    case SceneKind::Touching: return "touching";
    case SceneKind::Stacked: return "stacked";
    case SceneKind::Occluded: return "occluded";
    case SceneKind::NonConvex: return "nonconvex";
    case SceneKind::Clutter: return "clutter";
  }
  return "unknown";
}

SceneKind parseSceneKind(const std::string& name) {
  for (SceneKind kind : allSceneKinds()) {
    if (name == toString(kind)) return kind;
  }
  if (name == "non_convex" || name == "non-convex") return SceneKind::NonConvex;
  std::string known;
  for (SceneKind kind : allSceneKinds()) known += (known.empty() ? "" : ", ") + toString(kind);
  throw InputError("unknown scene kind '" + name + "' (expected one of: " + known + ")");
}

const std::vector<SceneKind>& allSceneKinds() {
  static const std::vector<SceneKind> kinds = {SceneKind::Isolated, SceneKind::Touching,  SceneKind::Stacked,
                                               SceneKind::Occluded, SceneKind::NonConvex, SceneKind::Clutter};
  return kinds;
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
