#pragma once
// Parameters of the symmetry method (Ecins et al., ICRA 2016). Defaults are the paper's values
// where it gives them; the others are documented choices. Loaded from the `symmetry` section of
// the YAML configuration (config/default.yaml documents each key).

namespace symmetry_segmentation {

/// Stage 1-2: normal-edge curves and symmetry hypotheses.
struct SymmetryDetectionParams {
  float supervoxel_voxel = 0.01f;         ///< Supervoxel voxel size (m), the working-cloud resolution.
  float supervoxel_seed = 0.03f;          ///< Supervoxel seed spacing (m).
  float merge_normal_angle_deg = 12.0f;   ///< Adjacent supervoxels whose normals differ less are merged.
  float boundary_radius = 0.015f;         ///< A point is a boundary point if a point of another merged
                                          ///< segment lies within this radius (m).
  float curve_link_radius = 0.02f;        ///< Longest MST edge between boundary points of one curve (m).
  int min_curve_points = 6;               ///< Shorter curves are dropped.
  int tangent_half_window = 2;            ///< Tangent from +-this many neighbours along the curve.
  float max_tangent_angle_deg = 6.0f;     ///< Reflected tangent vs. matched tangent (paper: 6 deg).
  float min_match_distance = 0.02f;       ///< Point pairs closer than this define no plane (m).
  float max_match_distance = 0.40f;       ///< ...nor pairs farther apart (larger than any object) (m).
  float mean_shift_angle_deg = 5.0f;      ///< Mean-shift bandwidth on the plane normal.
  float mean_shift_distance = 0.01f;      ///< Mean-shift bandwidth on the plane offset (m).
  int min_plane_support = 4;              ///< Matched point pairs a plane needs.
  float merge_plane_angle_deg = 6.0f;     ///< Near-equal planes from different curve pairs are merged.
  float merge_plane_distance = 0.015f;    ///< (m)
  int max_hypotheses = 80;                ///< Strongest curve hypotheses kept.
  bool upright_hypotheses = true;         ///< Also propose vertical planes from single surfaces
                                          ///< (needs the table plane; see upright_hypotheses.h).
};

/// Stage 3: graph cut per hypothesis (paper eq. 7-12).
struct SymmetryCutParams {
  float dmax = 0.01f;              ///< A reflection within this of a scene point lands on it (m).
  float alpha_min_deg = 15.0f;     ///< Normal mismatch below which a match is fully foreground.
  float alpha_max_deg = 45.0f;     ///< ...and above which it is background.
  float dbuf = 0.03f;              ///< Free-space penalty reaches its maximum this far from a surface (m).
  float sigma_convex_deg = 360.0f; ///< Smoothness weight decay over convex edges.
  float sigma_concave_deg = 30.0f; ///< ...and over concave edges.
  float lambda_smooth = 2.0f;
  float lambda_sym = 2.0f;
  int neighbours = 5;              ///< k of the k-NN smoothness graph.
};

/// Stage 4: refinement of each segment's plane.
struct SymmetryRefinementParams {
  bool enabled = true;
  int icp_iterations = 20;
  float icp_max_correspondence = 0.03f;  ///< (m)
};

/// Stage 5: which segments are kept (paper eq. 13-14), and de-duplication.
struct SymmetryFilterParams {
  float s_occl = 0.99f;                 ///< Keep segments whose occlusion score exceeds this.
  float s_smooth = 0.02f;               ///< ...and whose smoothness score is below this.
  float smooth_normal_angle_deg = 15.0f;///< Links with closer normals count as smooth.
  int min_segment_points = 40;          ///< In working-cloud points (1 cm voxels).
  float duplicate_overlap = 0.7f;       ///< Intersection over the smaller segment above which two
                                        ///< segments are the same object.
  float seam_crease_angle_deg = 30.0f;  ///< Concave links whose normals differ by more are creases
                                        ///< where two objects may meet (composite_segments.h);
                                        ///< 0 keeps composite segments whole.
  float island_gap = 0.015f;            ///< Groups of points this far from all others that a
                                        ///< found plane explains whole are proposed as segments
                                        ///< (island_segments.h); 0 = off.
  float twin_free_fraction = 0.6f;      ///< A segment in separate pieces that its plane mirrors
                                        ///< onto each other with at least this share of the
                                        ///< midpoints in observed free space is two objects
                                        ///< (mirror_twins.h); 0 = off.
  float color_seam_difference = 15.0f;  ///< Linked points closer in colour (CIELAB difference,
                                        ///< lightness at half weight) are one colour region; a
                                        ///< segment of large regions meeting over flat faces is
                                        ///< split into them (color_seams.h); 0 = off.
};

struct SymmetryParams {
  SymmetryDetectionParams detection;
  SymmetryCutParams cut;
  SymmetryRefinementParams refinement;
  SymmetryFilterParams filter;
  int threads = 0;  ///< Worker threads for independent hypotheses; 0 = hardware concurrency.
};

}  // namespace symmetry_segmentation
