#pragma once
// Parameters of the symmetry method (Ecins et al., ICRA 2016). Defaults are the paper's values
// where it gives them ("(paper)" in the docs); the others are documented choices. Each struct's
// parameters are declared once, in its describeParameters (parameter_schema.h).

#include "symmetry_segmentation/parameter_schema.h"

namespace symmetry_segmentation {

/// Stage 1-2: normal-edge curves and symmetry hypotheses.
struct SymmetryDetectionParams {
  float supervoxel_voxel = 0.01f;
  float supervoxel_seed = 0.03f;
  float merge_normal_angle_deg = 12.0f;
  float boundary_radius = 0.015f;
  float curve_link_radius = 0.02f;
  int min_curve_points = 6;
  int tangent_half_window = 2;
  float max_tangent_angle_deg = 6.0f;
  float min_match_distance = 0.02f;
  float max_match_distance = 0.40f;
  float mean_shift_angle_deg = 5.0f;
  float mean_shift_distance = 0.01f;
  int min_plane_support = 4;
  float merge_plane_angle_deg = 6.0f;
  float merge_plane_distance = 0.015f;
  int max_hypotheses = 80;
  bool upright_hypotheses = true;
};

inline void describeParameters(ParameterList<SymmetryDetectionParams>& list) {
  using P = SymmetryDetectionParams;
  list.add("supervoxel_voxel", &P::supervoxel_voxel, 0.002, 0.1, "m", "supervoxel voxel size")
      .add("supervoxel_seed", &P::supervoxel_seed, 0.005, 0.5, "m", "supervoxel seed spacing")
      .add("merge_normal_angle_deg", &P::merge_normal_angle_deg, 0.1, 180.0, "deg",
           "adjacent supervoxels with normals closer than this are merged")
      .add("boundary_radius", &P::boundary_radius, 0.001, 0.2, "m",
           "a point is a boundary point if another merged segment lies within this radius")
      .add("curve_link_radius", &P::curve_link_radius, 0.001, 0.2, "m", "longest spanning-tree edge inside one curve")
      .add("min_curve_points", &P::min_curve_points, 1, 10000, "points", "shorter curves are dropped")
      .add("tangent_half_window", &P::tangent_half_window, 1, 100, "points",
           "tangent from +-this many neighbours along the curve")
      .add("max_tangent_angle_deg", &P::max_tangent_angle_deg, 0.1, 180.0, "deg",
           "reflected vs. matched tangent (paper)")
      .add("min_match_distance", &P::min_match_distance, 0.0, 1.0, "m", "point pairs closer than this define no plane")
      .add("max_match_distance", &P::max_match_distance, 0.01, 5.0, "m",
           "...nor pairs farther apart than any object")
      .add("mean_shift_angle_deg", &P::mean_shift_angle_deg, 0.1, 180.0, "deg", "mean-shift bandwidth on the plane normal")
      .add("mean_shift_distance", &P::mean_shift_distance, 0.001, 0.5, "m", "mean-shift bandwidth on the plane offset")
      .add("min_plane_support", &P::min_plane_support, 1, 100000, "pairs", "matched point pairs a plane needs")
      .add("merge_plane_angle_deg", &P::merge_plane_angle_deg, 0.1, 180.0, "deg",
           "near-equal planes from different curve pairs are merged...")
      .add("merge_plane_distance", &P::merge_plane_distance, 0.001, 0.5, "m", "...when their offsets differ less")
      .add("max_hypotheses", &P::max_hypotheses, 1, 10000, "", "strongest curve hypotheses kept")
      .add("upright_hypotheses", &P::upright_hypotheses,
           "also vertical planes from single surfaces and object footprints (needs the table plane)")
      .rule([](const P& p) { return p.supervoxel_seed > p.supervoxel_voxel ? "" : "needs supervoxel_voxel < supervoxel_seed"; })
      .rule([](const P& p) {
        return p.max_match_distance > p.min_match_distance ? "" : "needs min_match_distance < max_match_distance";
      });
}

/// Stage 3: graph cut per hypothesis (paper eq. 7-12).
struct SymmetryCutParams {
  float dmax = 0.01f;
  float alpha_min_deg = 15.0f;
  float alpha_max_deg = 45.0f;
  float dbuf = 0.03f;
  float sigma_convex_deg = 360.0f;
  float sigma_concave_deg = 30.0f;
  float lambda_smooth = 2.0f;
  float lambda_sym = 2.0f;
  int neighbours = 5;
};

inline void describeParameters(ParameterList<SymmetryCutParams>& list) {
  using P = SymmetryCutParams;
  list.add("dmax", &P::dmax, 0.001, 0.1, "m", "a reflection this close to a point lands on it (paper)")
      .add("alpha_min_deg", &P::alpha_min_deg, 0.1, 180.0, "deg", "normal mismatch below which a match is foreground (paper)")
      .add("alpha_max_deg", &P::alpha_max_deg, 0.1, 180.0, "deg", "...above which it is background (paper)")
      .add("dbuf", &P::dbuf, 0.002, 0.5, "m", "the free-space penalty is full this far from a surface (paper)")
      .add("sigma_convex_deg", &P::sigma_convex_deg, 0.1, 3600.0, "deg", "smoothness decay over convex edges (paper)")
      .add("sigma_concave_deg", &P::sigma_concave_deg, 0.1, 3600.0, "deg", "smoothness decay over concave edges (paper)")
      .add("lambda_smooth", &P::lambda_smooth, 0.0, 20.0, "", "weight of the smoothness term (paper)").live()
      .add("lambda_sym", &P::lambda_sym, 0.0, 20.0, "", "weight of the symmetric-neighbour term (paper)").live()
      .add("neighbours", &P::neighbours, 1, 50, "", "k of the k-nearest-neighbour smoothness graph (paper)")
      .rule([](const P& p) { return p.dmax < p.dbuf ? "" : "needs dmax < dbuf"; })
      .rule([](const P& p) { return p.alpha_min_deg < p.alpha_max_deg ? "" : "needs alpha_min_deg < alpha_max_deg"; });
}

/// Stage 4: refinement of each segment's plane.
struct SymmetryRefinementParams {
  bool enabled = true;
  int icp_iterations = 20;
  float icp_max_correspondence = 0.03f;
};

inline void describeParameters(ParameterList<SymmetryRefinementParams>& list) {
  using P = SymmetryRefinementParams;
  list.add("enabled", &P::enabled, "refine each segment's plane and cut again")
      .add("icp_iterations", &P::icp_iterations, 0, 10000, "", "ICP iterations of the segment with its reflection")
      .add("icp_max_correspondence", &P::icp_max_correspondence, 0.001, 0.5, "m", "ICP correspondence distance");
}

/// Stage 5: which segments are kept (paper eq. 13-14), and de-duplication.
struct SymmetryFilterParams {
  float s_occl = 0.99f;
  float s_smooth = 0.02f;
  float smooth_normal_angle_deg = 15.0f;
  int min_segment_points = 40;
  float duplicate_overlap = 0.7f;
  float seam_crease_angle_deg = 30.0f;
  float island_gap = 0.015f;
  float twin_free_fraction = 0.6f;
  float color_seam_difference = 15.0f;
};

inline void describeParameters(ParameterList<SymmetryFilterParams>& list) {
  using P = SymmetryFilterParams;
  list.add("s_occl", &P::s_occl, 0.0, 1.0, "", "keep segments whose occlusion score exceeds this").live()
      .add("s_smooth", &P::s_smooth, 0.0, 1.0, "", "...and whose smoothness score is below this").live()
      .add("smooth_normal_angle_deg", &P::smooth_normal_angle_deg, 0.1, 180.0, "deg",
           "links with closer normals count as smooth")
      .add("min_segment_points", &P::min_segment_points, 1, 1000000, "points", "in working-cloud points (1 cm voxels)")
      .add("duplicate_overlap", &P::duplicate_overlap, 0.0, 1.0, "",
           "overlap (of the smaller) above which two segments are one object")
      .add("seam_crease_angle_deg", &P::seam_crease_angle_deg, 0.0, 180.0, "deg",
           "a segment of two found objects meeting at concave links whose normals differ by more is split (0: never)")
      .add("island_gap", &P::island_gap, 0.0, 0.2, "m",
           "points this far from all others that a found plane explains whole are proposed as a segment (0: off)")
      .add("twin_free_fraction", &P::twin_free_fraction, 0.0, 1.0, "",
           "a segment in pieces its plane mirrors onto each other, this share of midpoints free, is two objects (0: off)")
      .add("color_seam_difference", &P::color_seam_difference, 0.0, 200.0, "CIELAB",
           "neighbours closer in colour are one region; a segment of large regions meeting flat is split (0: off)");
}

struct SymmetryParams {
  SymmetryDetectionParams detection;
  SymmetryCutParams cut;
  SymmetryRefinementParams refinement;
  SymmetryFilterParams filter;
  int threads = 0;
};

inline void describeParameters(ParameterList<SymmetryParams>& list) {
  list.add("threads", &SymmetryParams::threads, 0, 1024, "", "worker threads for independent hypotheses; 0 = all cores");
}

}  // namespace symmetry_segmentation
