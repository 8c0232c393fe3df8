#include "symmetry_segmentation/synthetic/synthetic_world.h"

namespace symmetry_segmentation {
namespace synthetic {
namespace {

void keepNearer(const SyntheticObject& object, const Ray& ray, double t_min, std::optional<WorldHit>& best,
                double& t_max) {
  const auto hit = rayIntersect(object, ray, t_min, t_max);
  if (!hit || (best && hit->t >= best->t)) return;
  WorldHit result;
  result.t = hit->t;
  result.point = hit->point;
  result.normal = hit->normal;
  result.label = object.label;
  result.color = surfaceColor(object, hit->point);
  best = result;
  t_max = hit->t;
}

}  // namespace

std::optional<WorldHit> rayIntersect(const SyntheticWorld& world, const Ray& ray, double t_min, double t_max) {
  std::optional<WorldHit> best;
  for (const auto& object : world.objects) keepNearer(object, ray, t_min, best, t_max);
  if (world.table) keepNearer(*world.table, ray, t_min, best, t_max);
  for (const auto& object : world.background) keepNearer(object, ray, t_min, best, t_max);
  return best;
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
