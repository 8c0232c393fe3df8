#pragma once
// Analytic surface pieces that synthetic objects are made of, each in the object's local frame
// (z up). A patch reports where a ray first meets it and the true surface normal there, which
// points out of the material toward free space (so open shells get one patch per side).

#include <optional>
#include <variant>

#include <Eigen/Core>

namespace symmetry_segmentation {
namespace synthetic {

/// origin + t * direction; direction need not be unit length (t is in units of it).
struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;
  Eigen::Vector3d at(double t) const { return origin + t * direction; }
};

struct SurfaceHit {
  double t = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit length.
};

/// Solid axis-aligned box; the hit is on the face the ray enters through.
struct BoxSolid {
  Eigen::Vector3d min;
  Eigen::Vector3d max;
};

/// Side of the cylinder of `radius` about the local z axis, z_min <= z <= z_max.
/// Outward normals for an outer wall, inward (toward the axis) for the inside of a cup.
struct CylinderSide {
  double radius = 0.0;
  double z_min = 0.0;
  double z_max = 0.0;
  bool normal_outward = true;
};

/// Flat ring r_inner <= r <= r_outer at height z about the z axis (a disk when r_inner = 0).
struct Annulus {
  double z = 0.0;
  double r_inner = 0.0;
  double r_outer = 0.0;
  bool normal_up = true;
};

/// Side of a cone or frustum about the z axis: radius r_bottom at z_bottom to r_top at z_top
/// (r_top = 0 is a pointed cone). Normals point away from the axis.
struct FrustumSide {
  double z_bottom = 0.0;
  double z_top = 0.0;
  double r_bottom = 0.0;
  double r_top = 0.0;
};

/// The band z_min <= z <= z_max of a sphere; outward normals for the outside of a bowl,
/// inward (toward the centre) for its inside.
struct SphereZone {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
  double z_min = 0.0;
  double z_max = 0.0;
  bool normal_outward = true;
};

using SurfacePatch = std::variant<BoxSolid, CylinderSide, Annulus, FrustumSide, SphereZone>;

/// First intersection with t in [t_min, t_max], if any.
std::optional<SurfaceHit> intersect(const SurfacePatch& patch, const Ray& ray, double t_min, double t_max);

std::optional<SurfaceHit> intersect(const BoxSolid& box, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const CylinderSide& side, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Annulus& ring, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const FrustumSide& side, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const SphereZone& zone, const Ray& ray, double t_min, double t_max);

/// Local-frame axis-aligned bounds of a patch (for culling and footprints).
void patchBounds(const SurfacePatch& patch, Eigen::Vector3d& min, Eigen::Vector3d& max);

}  // namespace synthetic
}  // namespace symmetry_segmentation
