#pragma once
// The kinds of synthetic tabletop scene, each stressing one segmentation difficulty.

#include <string>
#include <vector>

namespace symmetry_segmentation {
namespace synthetic {

enum class SceneKind {
  Isolated,   ///< 3-5 well separated objects.
  Touching,   ///< Objects pushed flush side by side, including a row of boxes.
  Stacked,    ///< Objects standing on other objects.
  Occluded,   ///< An object split in pieces by a tall thin occluder in front of it.
  NonConvex,  ///< Mugs, bowls, L and U shapes.
  Clutter     ///< 8-12 mixed objects close together.
};

/// "isolated", "touching", "stacked", "occluded", "nonconvex", "clutter".
std::string toString(SceneKind kind);
/// Inverse of toString (also accepts "non_convex" / "non-convex"); throws InputError otherwise.
SceneKind parseSceneKind(const std::string& name);
const std::vector<SceneKind>& allSceneKinds();

}  // namespace synthetic
}  // namespace symmetry_segmentation
