#pragma once
// Parameters of the symmetry method (Ecins et al., ICRA 2016), one struct per stage in the order
// the default list runs them (symmetry.stages), each declared once in its describeParameters
// (parameter_schema.h): key, range, unit, doc; the default is the member's initializer.
// Defaults are the paper's values where it gives them ("(paper)"); the others are our choices.
// Constants that are no tunable of the method (numerical limits, sampling resolutions that a
// parameter's meaning fixes) stay in the code, each with the reason.

#include <string>
#include <vector>

#include "symmetry_segmentation/parameter_schema.h"

namespace symmetry_segmentation {

/// Stage curves: normal-edge curves (paper).
struct NormalEdgeCurveParams {
  float supervoxel_voxel = 0.01f;
  float supervoxel_seed = 0.03f;
  float merge_normal_angle_deg = 12.0f;
  float curved_merge_angle_deg = 30.0f;
  float boundary_radius = 0.015f;
  float curve_link_radius = 0.02f;
  int min_curve_points = 6;
  int tangent_half_window = 2;
  float min_edge_angle_deg = 20.0f;
};

inline void describeParameters(ParameterList<NormalEdgeCurveParams>& list) {
  using P = NormalEdgeCurveParams;
  list.add("supervoxel_voxel", &P::supervoxel_voxel, 0.002, 0.1, "m", "supervoxel voxel size")
      .add("supervoxel_seed", &P::supervoxel_seed, 0.005, 0.5, "m", "supervoxel seed spacing")
      .add("merge_normal_angle_deg", &P::merge_normal_angle_deg, 0.1, 180.0, "deg",
           "touching supervoxels whose mean normals differ less are merged into one surface")
      .add("curved_merge_angle_deg", &P::curved_merge_angle_deg, 0.1, 180.0, "deg",
           "...or whose normals agree where they touch and whose mean normals differ less (curved surfaces)")
      .add("boundary_radius", &P::boundary_radius, 0.001, 0.2, "m",
           "a point is a boundary point if another merged surface lies within this radius")
      .add("curve_link_radius", &P::curve_link_radius, 0.001, 0.2, "m", "longest spanning-tree edge inside one curve")
      .add("min_curve_points", &P::min_curve_points, 1, 10000, "points", "shorter curves are dropped")
      .add("tangent_half_window", &P::tangent_half_window, 1, 100, "points",
           "tangent from +-this many neighbours along the curve")
      .add("min_edge_angle_deg", &P::min_edge_angle_deg, 0.1, 90.0, "deg",
           "where the surfaces meet at more than this, the tangent is their edge direction")
      .rule([](const P& p) { return p.supervoxel_seed > p.supervoxel_voxel ? "" : "needs supervoxel_voxel < supervoxel_seed"; });
}

/// Stage curve_pairs: planes from matched curve pairs (paper).
struct CurvePairParams {
  float max_tangent_angle_deg = 6.0f;
  float min_match_distance = 0.02f;
  float max_match_distance = 0.40f;
  float mean_shift_angle_deg = 5.0f;
  float mean_shift_distance = 0.01f;
  int min_pair_support = 3;
  int min_plane_support = 4;
  float merge_plane_angle_deg = 6.0f;
  float merge_plane_distance = 0.015f;
  int max_hypotheses = 80;
};

inline void describeParameters(ParameterList<CurvePairParams>& list) {
  using P = CurvePairParams;
  list.add("max_tangent_angle_deg", &P::max_tangent_angle_deg, 0.1, 180.0, "deg", "reflected vs. matched tangent (paper)")
      .add("min_match_distance", &P::min_match_distance, 0.0, 1.0, "m", "point pairs closer than this define no plane")
      .add("max_match_distance", &P::max_match_distance, 0.01, 5.0, "m", "...nor pairs farther apart than any object")
      .add("mean_shift_angle_deg", &P::mean_shift_angle_deg, 0.1, 180.0, "deg", "mean-shift bandwidth on the plane normal")
      .add("mean_shift_distance", &P::mean_shift_distance, 0.001, 0.5, "m", "mean-shift bandwidth on the plane offset")
      .add("min_pair_support", &P::min_pair_support, 1, 100000, "pairs",
           "matched point pairs a plane of one curve pair needs (a short curve has ~10 points)")
      .add("min_plane_support", &P::min_plane_support, 1, 100000, "pairs",
           "matched point pairs a plane needs once merged across curve pairs")
      .add("merge_plane_angle_deg", &P::merge_plane_angle_deg, 0.1, 180.0, "deg",
           "near-equal planes from different curve pairs are merged...")
      .add("merge_plane_distance", &P::merge_plane_distance, 0.001, 0.5, "m", "...when their offsets differ less")
      .add("max_hypotheses", &P::max_hypotheses, 1, 10000, "", "strongest curve-pair planes kept")
      .rule([](const P& p) {
        return p.max_match_distance > p.min_match_distance ? "" : "needs min_match_distance < max_match_distance";
      });
}

/// Stage upright: vertical planes proposed by single surfaces (upright_hypotheses.h).
struct UprightHypothesisParams {
  int min_surface_points = 20;
  float flat_curvature = 0.02f;
  float flat_normal_spread_deg = 10.0f;
  float face_tilt_deg = 20.0f;
  float max_axis_residual = 0.01f;
  float max_axis_radius = 0.25f;
  float min_normal_spread_deg = 20.0f;
  int max_axes_per_surface = 3;
  float min_axis_share = 0.3f;
  int axis_plane_angles = 24;
  float column_height_margin = 0.02f;
  float surface_tolerance = 0.01f;
  float attached_reach = 2.0f;
  float contradiction_tolerance = 1.0f;
  float second_plane_contradiction_share = 0.01f;
  float match_tie_break = 0.05f;
  float distinct_angle_deg = 6.0f;
  float distinct_distance = 0.015f;
  float min_mid_height = 0.05f;
};

inline void describeParameters(ParameterList<UprightHypothesisParams>& list) {
  using P = UprightHypothesisParams;
  list.add("min_surface_points", &P::min_surface_points, 1, 100000, "points", "smaller merged surfaces propose nothing")
      .add("flat_curvature", &P::flat_curvature, 0.0, 1.0, "", "surfaces with less PCA curvature propose face planes")
      .add("flat_normal_spread_deg", &P::flat_normal_spread_deg, 0.1, 90.0, "deg",
           "surfaces whose normals spread more propose an axis plane")
      .add("face_tilt_deg", &P::face_tilt_deg, 0.1, 90.0, "deg", "faces within this of vertical / horizontal propose planes")
      .add("max_axis_residual", &P::max_axis_residual, 0.0001, 0.1, "m", "RMS distance of normal lines from the fitted axis")
      .add("max_axis_radius", &P::max_axis_radius, 0.01, 2.0, "m", "farther axes are not an object's")
      .add("min_normal_spread_deg", &P::min_normal_spread_deg, 0.1, 180.0, "deg",
           "normals must turn by about this around an axis to locate it")
      .add("max_axes_per_surface", &P::max_axes_per_surface, 1, 20, "",
           "axes sought in one surface (touching round objects merge into one)")
      .add("min_axis_share", &P::min_axis_share, 0.0, 1.0, "", "an axis explains at least this share of its surface")
      .add("axis_plane_angles", &P::axis_plane_angles, 2, 360, "", "orientations tried for a plane through an axis")
      .add("column_height_margin", &P::column_height_margin, 0.0, 0.5, "m",
           "the points scored around an axis reach this far above and below its surface")
      .add("surface_tolerance", &P::surface_tolerance, 0.0, 0.5, "m",
           "a point this close to a surface of revolution lies on it; the column also reaches this far beyond 1.2 radii")
      .add("attached_reach", &P::attached_reach, 1.2, 5.0, "radii",
           "points out to this many radii from the axis that hang on to the column (a mug's handle) are scored too")
      .add("contradiction_tolerance", &P::contradiction_tolerance, 0.0, 1000.0, "points",
           "orientations whose free-space contradiction is within this of the least are told apart by matches")
      .add("second_plane_contradiction_share", &P::second_plane_contradiction_share, 0.0, 1.0, "",
           "the best-matching orientation within this share of the scored points of the least is proposed too; 0: one plane per axis")
      .add("match_tie_break", &P::match_tie_break, 0.0, 1.0, "",
           "weight of a matched reflection against one contradicted by free space, when orienting")
      .add("distinct_angle_deg", &P::distinct_angle_deg, 0.1, 180.0, "deg",
           "an upright plane within this angle...")
      .add("distinct_distance", &P::distinct_distance, 0.001, 0.5, "m", "...and offset of a plane already proposed is not added")
      .add("min_mid_height", &P::min_mid_height, 0.0, 1.0, "m",
           "a horizontal face at least this high over the table, or over a lower face beside or under it, proposes the horizontal plane halfway down (an object standing on the table or on another is mirror-symmetric about it); 0: none");
}

/// Stage cut: graph cut per hypothesis (paper eq. 7-12); also the data term of every later stage.
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
  float max_neighbour_distance = 0.05f;
  float isolated_radius = 0.025f;
  int unobserved_steps = 0;
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
      .add("max_neighbour_distance", &P::max_neighbour_distance, 0.0, 1.0, "m",
           "...but points farther apart are not neighbours: a speck of noise is no part of the surface nearest to it; 0: no limit")
      .add("isolated_radius", &P::isolated_radius, 0.0, 0.5, "m",
           "a point with no other this close (at least 2 working voxels) is sensor noise (a flying pixel): no links, never foreground; 0: none is")
      .add("unobserved_steps", &P::unobserved_steps, 0, 5, "dmax steps",
           "a reflection into free space within this many dmax steps of unobserved or occupied space is only that far from a surface (the authors' obstacle distance); 0: scene points only")
      .rule([](const P& p) { return p.dmax < p.dbuf ? "" : "needs dmax < dbuf"; })
      .rule([](const P& p) { return p.alpha_min_deg < p.alpha_max_deg ? "" : "needs alpha_min_deg < alpha_max_deg"; });
}

/// Stage refine: ICP of each segment with its reflection, then a second cut (paper).
struct SymmetryRefinementParams {
  int icp_iterations = 20;
  float icp_max_correspondence = 0.03f;
  float min_normal_cos = 0.7f;
  float min_matched_fraction = 0.5f;
  float max_turn_deg = 15.0f;
  int min_points = 10;
};

inline void describeParameters(ParameterList<SymmetryRefinementParams>& list) {
  using P = SymmetryRefinementParams;
  list.add("icp_iterations", &P::icp_iterations, 0, 10000, "", "ICP iterations of the segment with its reflection")
      .add("icp_max_correspondence", &P::icp_max_correspondence, 0.001, 0.5, "m", "ICP correspondence distance")
      .add("min_normal_cos", &P::min_normal_cos, -1.0, 1.0, "",
           "mirrored and matched normals with a smaller cosine are different surfaces (0.7: about 45 deg)")
      .add("min_matched_fraction", &P::min_matched_fraction, 0.0, 1.0, "",
           "share of the mirrored segment that must find counterparts, else the plane stays")
      .add("max_turn_deg", &P::max_turn_deg, 0.0, 90.0, "deg",
           "a refinement turning the plane more found another symmetry: the plane stays")
      .add("min_points", &P::min_points, 1, 100000, "points", "smaller segments keep their plane");
}

/// Stage islands: groups of points apart from all others (island_segments.h, footprint_hypotheses.h).
struct IslandParams {
  float gap = 0.015f;
};

inline void describeParameters(ParameterList<IslandParams>& list) {
  list.add("gap", &IslandParams::gap, 0.001, 0.2, "m", "points this far from all others start another island");
}

/// Stage footprints: planes through the footprint of an island nothing covers.
struct FootprintParams {
  float max_extent = 0.3f;
  float min_island_coverage = 0.9f;
};

inline void describeParameters(ParameterList<FootprintParams>& list) {
  list.add("max_extent", &FootprintParams::max_extent, 0.01, 5.0, "m",
           "islands whose footprint is longer are several objects: no planes")
      .add("min_island_coverage", &FootprintParams::min_island_coverage, 0.0, 1.0, "",
           "an island a passing segment covers to this share needs no planes");
}

/// Stage occluder_gaps: planes across the hidden gap between two pieces of one object.
struct OccluderGapParams {
  float min_gap = 0.02f;
  float max_span = 0.4f;
  float min_piece_coverage = 0.8f;
  float max_turn_deg = 20.0f;
  float turn_step_deg = 10.0f;
  float min_shared_color = 0.2f;
  float max_color_difference = 15.0f;
};

inline void describeParameters(ParameterList<OccluderGapParams>& list) {
  list.add("min_gap", &OccluderGapParams::min_gap, 0.0, 1.0, "m",
           "two pieces closer along the line between them touch: no plane across them")
      .add("max_span", &OccluderGapParams::max_span, 0.01, 5.0, "m", "...nor across pieces longer than this together")
      .add("min_piece_coverage", &OccluderGapParams::min_piece_coverage, 0.0, 1.0, "",
           "the plane's cut is a candidate when it takes this share of each piece")
      .add("max_turn_deg", &OccluderGapParams::max_turn_deg, 0.0, 90.0, "deg",
           "the plane is also tried turned about the up direction by up to this...")
      .add("turn_step_deg", &OccluderGapParams::turn_step_deg, 0.0, 90.0, "deg",
           "...in steps of this (0: not turned); per pair the cut taking most of both pieces counts")
      .add("min_shared_color", &OccluderGapParams::min_shared_color, 0.0, 1.0, "",
           "two pieces of one object show its colours: in a cloud with colour, each piece has at least this share of its points in a colour the other shows too (a green ball and a pink can either side of an occluder are two objects); 0: colour not asked")
      .add("max_color_difference", &OccluderGapParams::max_color_difference, 0.1, 200.0, "CIELAB",
           "...colours closer than this are one (lightness at half weight)");
}

/// Stage filter: the paper's scores (eq. 13-14) and which candidates are kept; the scores and
/// thresholds also judge every segment later stages make.
struct SymmetryFilterParams {
  float s_occl = 0.99f;
  float s_smooth = 0.02f;
  float smooth_normal_angle_deg = 15.0f;
  int min_segment_points = 40;
  float plane_offset_search = 0.012f;
};

inline void describeParameters(ParameterList<SymmetryFilterParams>& list) {
  using P = SymmetryFilterParams;
  list.add("s_occl", &P::s_occl, 0.0, 1.0, "", "keep segments whose occlusion score exceeds this").live()
      .add("s_smooth", &P::s_smooth, 0.0, 1.0, "", "...and whose smoothness score is below this").live()
      .add("smooth_normal_angle_deg", &P::smooth_normal_angle_deg, 0.1, 180.0, "deg",
           "links with closer normals count as smooth")
      .add("min_segment_points", &P::min_segment_points, 1, 1000000, "points",
           "smaller segments, islands and parts are no objects (working-cloud points, 1 cm voxels)")
      .add("plane_offset_search", &P::plane_offset_search, 0.0, 0.05, "m",
           "a candidate failing only s_occl is scored again with its plane moved along its normal by up to "
           "this (2 mm steps), and the best offset stays; 0: off");
}

/// Stage island_segments: an island one found plane explains whole.
struct IslandSegmentParams {
  float min_share_on_island = 0.5f;
  float min_share_of_island = 0.3f;
  float alone_free_factor = 10.0f;
};

inline void describeParameters(ParameterList<IslandSegmentParams>& list) {
  list.add("min_share_on_island", &IslandSegmentParams::min_share_on_island, 0.0, 1.0, "",
           "a segment lends its plane to an island it lies on by this share...")
      .add("min_share_of_island", &IslandSegmentParams::min_share_of_island, 0.0, 1.0, "",
           "...and covers this share of (a piece of the object, not a detail of many)")
      .add("alone_free_factor", &IslandSegmentParams::alone_free_factor, 1.0, 100.0, "",
           "an island no segment covers half of may send this many times the filter's share (1 - s_occl) of its reflections into free space");
}

/// Stage mirror_twins: two like objects the plane between them mirrors onto each other.
struct MirrorTwinParams {
  float min_part_fraction = 0.25f;
  float min_free_fraction = 0.6f;
  int min_pairs = 10;
};

inline void describeParameters(ParameterList<MirrorTwinParams>& list) {
  list.add("min_part_fraction", &MirrorTwinParams::min_part_fraction, 0.0, 1.0, "",
           "pieces with at least this share of the segment are objects")
      .add("min_free_fraction", &MirrorTwinParams::min_free_fraction, 0.0, 1.0, "",
           "share of mirrored pairs across pieces whose midpoint the sensor saw through")
      .add("min_pairs", &MirrorTwinParams::min_pairs, 1, 100000, "pairs", "fewer mirrored pairs across the pieces decide nothing");
}

/// Stage composites: a segment that is two objects meeting at a concave seam.
struct CompositeSegmentParams {
  float crease_angle_deg = 30.0f;
  float joined_angle_deg = 10.0f;
  float min_nested_fraction = 0.8f;
  float min_part_fraction = 0.2f;
  float max_part_fraction = 0.8f;
  float max_part_overlap = 0.1f;
  float min_coverage = 0.85f;
  float min_crease_fraction = 0.5f;
  float min_rest_crease_fraction = 0.9f;
  int min_seam_links = 5;
  float max_swapped_fraction = 0.3f;
  float min_color_difference = 5.0f;
  float min_color_overlap = 0.3f;  // one object's parts 0.3-0.6, touching real objects (OSD) ~0.2
  // From the scene: whether its points carry colour. Not a parameter.
  bool use_color = false;
};

inline void describeParameters(ParameterList<CompositeSegmentParams>& list) {
  using P = CompositeSegmentParams;
  list.add("crease_angle_deg", &P::crease_angle_deg, 0.1, 180.0, "deg",
           "concave links whose normals differ more are creases where two objects may meet")
      .add("joined_angle_deg", &P::joined_angle_deg, 0.1, 180.0, "deg",
           "two parts found alone are one body when a path joins them over links that are convex or "
           "closer than this (at 1 cm a concave corner turns ~15 deg per link)")
      .add("min_nested_fraction", &P::min_nested_fraction, 0.0, 1.0, "", "share of each part inside the composite")
      .add("min_part_fraction", &P::min_part_fraction, 0.0, 1.0, "", "each part has at least this share of the composite...")
      .add("max_part_fraction", &P::max_part_fraction, 0.0, 1.0, "", "...and at most this share")
      .add("max_part_overlap", &P::max_part_overlap, 0.0, 1.0, "", "the parts share at most this share of the smaller")
      .add("min_coverage", &P::min_coverage, 0.0, 1.0, "", "the two parts cover at least this share of the composite")
      .add("min_crease_fraction", &P::min_crease_fraction, 0.0, 1.0, "", "share of the links between the parts on a crease")
      .add("min_rest_crease_fraction", &P::min_rest_crease_fraction, 0.0, 1.0, "",
           "the same for a part not found alone (a flush face running on makes it fall short)")
      .add("min_seam_links", &P::min_seam_links, 1, 100000, "links", "parts linked by fewer links are apart")
      .add("max_swapped_fraction", &P::max_swapped_fraction, 0.0, 1.0, "",
           "parts whose matched reflections land on each other more are mirror halves of one object")
      .add("min_color_difference", &P::min_color_difference, 0.0, 200.0, "CIELAB",
           "parts whose mean colours differ less are one object's (an L-shaped block's slab and upright); clouds with colour only, 0: off")
      .add("min_color_overlap", &P::min_color_overlap, 0.0, 1.0, "",
           "...and so are parts that share this much of their colours (coarse CIELAB histograms): one print over both; 0: off");
}

/// Stage nested: an object the cut glued onto another object's segment.
struct NestedSegmentParams {
  float min_nested_fraction = 0.8f;
  float max_size_ratio = 0.8f;
  float max_explained_fraction = 0.5f;
};

inline void describeParameters(ParameterList<NestedSegmentParams>& list) {
  using P = NestedSegmentParams;
  list.add("min_nested_fraction", &P::min_nested_fraction, 0.0, 1.0, "", "share of the smaller segment inside the larger")
      .add("max_size_ratio", &P::max_size_ratio, 0.0, 1.0, "", "the smaller segment has at most this share of the larger's size")
      .add("max_explained_fraction", &P::max_explained_fraction, 0.0, 1.0, "",
           "below this share of points the larger plane explains, the nested segment is another object");
}

/// Stage color_seams: flush objects of different colours.
struct ColorSeamParams {
  float max_color_difference = 15.0f;
  float min_part_fraction = 0.1f;
  float min_coverage = 0.8f;
  float min_flat_seam_fraction = 0.5f;
  int min_seam_links = 5;
  float min_concave_seam_fraction = 0.3f;
  float min_touching_part_fraction = 0.25f;
  float min_self_mirrored_fraction = 0.7f;
  float max_piece_plane_share = 0.8f;
  float min_seam_span = 0.7f;
  float max_flush_seam_offset = 0.006f;
  float min_plane_share = 0.3f;
  bool split_flush_seams = true;
  // From symmetry.filter (min_segment_points, smooth_normal_angle_deg): not parameters of their own.
  int min_part_points = 40;
  float flat_link_angle_deg = 15.0f;
  // From preprocessing.voxel_size (object_size's onPlaneDistance): points this close to a plane are on it.
  float on_plane_distance = 0.015f;
  // From symmetry.composites (min_color_overlap): parts sharing this much of their colours are one
  // print's, never split. 0 (off) unless the stage sets it.
  float min_color_overlap = 0.0f;
};

inline void describeParameters(ParameterList<ColorSeamParams>& list) {
  using P = ColorSeamParams;
  list.add("max_color_difference", &P::max_color_difference, 0.1, 200.0, "CIELAB",
           "linked points closer in colour (lightness at half weight) are one colour region")
      .add("min_part_fraction", &P::min_part_fraction, 0.0, 1.0, "", "regions with this share of the segment are candidate objects")
      .add("min_coverage", &P::min_coverage, 0.0, 1.0, "", "those regions cover this share, else what they leave is print, its large linked stretches parts too (split from others at concave creases only)")
      .add("min_flat_seam_fraction", &P::min_flat_seam_fraction, 0.0, 1.0, "",
           "share of the flat and convex links between two regions that is flat for a flush seam")
      .add("min_seam_links", &P::min_seam_links, 1, 100000, "links", "regions linked by fewer links do not meet")
      .add("min_concave_seam_fraction", &P::min_concave_seam_fraction, 0.0, 1.0, "",
           "regions meeting with this share of concave links (a bowl on a box)...")
      .add("min_touching_part_fraction", &P::min_touching_part_fraction, 0.0, 1.0, "",
           "...are two objects when the smaller has this share (a handle has less)...")
      .add("min_self_mirrored_fraction", &P::min_self_mirrored_fraction, 0.0, 1.0, "",
           "...or when the smaller is an object of its own: this share of its matched reflections (the segment's plane) land on it, not on the other part (a print patch mirrors onto the rest of its object)...")
      .add("max_piece_plane_share", &P::max_piece_plane_share, 0.0, 1.0, "",
           "...and at most this share of it lies on one plane (one face of a box is no object)")
      .add("min_seam_span", &P::min_seam_span, 0.0, 1.0, "",
           "a flush seam spans this share of each part along one of its axes (a bottle cap's ring does not)")
      .add("max_flush_seam_offset", &P::max_flush_seam_offset, 0.0, 0.1, "m",
           "...and its links' middles lie this close to one plane (RMS), where objects meet; a print's edge steps across faces (0: off)")
      .add("min_plane_share", &P::min_plane_share, 0.0, 1.0, "", "a found segment's plane is tried on a part it covers this share of")
      .add("split_flush_seams", &P::split_flush_seams,
           "also split at flat seams (a box on a box of its footprint, flush boxes of one depth) between parts that each stand alone; false: at concave creases only");
}

/// Stage object_size: only what a robot could grasp is an object.
struct ObjectSizeParams {
  float max_extent = 0.5f;
  float max_plane_extent = 0.4f;
  float min_plane_share = 0.9f;
  float min_top_height = 0.015f;
  float max_table_seen_share = 0.5f;
  // A shelf shades the table under it from a camera over the table's front (shelf boards: seen
  // under 0.19-1.0 of their footprint); what is seen over an occluder has the table hidden under
  // it (0-0.05 on every generated set and OSD learn).
  float min_table_seen_under_raised = 0.15f;
  // ...or the space under it seen free: 0.9-1.0 under shelf boards and a mug's handle found
  // alone, 0-0.03 under what is seen over an occluder (every evaluation set and OSD learn).
  float min_free_under_raised = 0.5f;
  // A chair's back pushed in to the table's end: all its lowest points have a surface seen
  // under the table's top under them; no object of any evaluation set has more than a few.
  float min_seen_below_share = 0.5f;
};

inline void describeParameters(ParameterList<ObjectSizeParams>& list) {
  using P = ObjectSizeParams;
  list.add("max_extent", &P::max_extent, 0.0, 100.0, "m",
           "larger along any axis (height over the table, footprint sides) is not a graspable object; 0: no limit")
      .add("max_plane_extent", &P::max_plane_extent, 0.0, 100.0, "m",
           "a segment mostly on one plane wider than this is a wall or table, not an object; 0: no limit")
      .add("min_plane_share", &P::min_plane_share, 0.0, 1.0, "", "mostly on one plane: this share of its points")
      .add("min_top_height", &P::min_top_height, 0.0, 1.0, "m",
           "a segment whose top (95th percentile) is lower over the table is a scrap of the table's noise (in one camera's view times the square of its median distance over the table's, 1 to 4); a piece of a segment wholly that low, over 2.5 voxels from the rest, is a speck of that noise and leaves it unless it hides the table as below (a segment mostly specks goes); 0: off")
      .add("max_table_seen_share", &P::max_table_seen_share, 0.0, 1.0, "",
           "...unless the table was seen under less than this share of its footprint's inside: a thin object lying on the table hides it, the table's noise has it all through")
      .add("min_table_seen_under_raised", &P::min_table_seen_under_raised, 0.0, 1.0, "",
           "a segment resting on nothing (the gap under it taller than itself, nothing under its footprint) with the table seen under this share of its footprint's inside hangs over the table (a shelf): dropped; 0: off")
      .add("min_free_under_raised", &P::min_free_under_raised, 0.0, 1.0, "",
           "...as does one with the space under it seen free (occupancy) at this share of probes every 3 cm straight under it (a shelf shading the table under it); what is seen over an occluder has that space hidden; 0: off")
      .add("min_seen_below_share", &P::min_seen_below_share, 0.0, 1.0, "",
           "a segment a quarter or more beyond the table's own points with a surface seen 3-6 cm under the table's top under this share of its lowest points rises from below past the table's edge (a chair's back, a carton beside the table): dropped; 0: off");
}

/// Stage dedup: one segment per object.
struct DuplicateParams {
  // An object is in one segment: two that share half the smaller are not two objects (a noisy
  // frame's cuts give unions of two neighbours, each neighbour in two or three of them).
  float max_overlap = 0.5f;
};

inline void describeParameters(ParameterList<DuplicateParams>& list) {
  list.add("max_overlap", &DuplicateParams::max_overlap, 0.0, 1.0, "",
           "segments overlapping more (of the smaller) are one object: the cleanest boundary stays");
}

/// Stage stray_color_pieces: strips of the next object's colour moved to it.
struct StrayColorParams {
  float max_color_difference = 15.0f;
  float min_dominant_share = 0.7f;
  float max_stray_share = 0.3f;
};

inline void describeParameters(ParameterList<StrayColorParams>& list) {
  list.add("max_color_difference", &StrayColorParams::max_color_difference, 0.1, 200.0, "CIELAB",
           "colours closer than this are alike (lightness at half weight)")
      .add("min_dominant_share", &StrayColorParams::min_dominant_share, 0.0, 1.0, "",
           "a segment is mostly one colour when its largest region has this share")
      .add("max_stray_share", &StrayColorParams::max_stray_share, 0.0, 1.0, "", "a stray piece has at most this share of its segment");
}

/// Stage coaxial_pieces: pieces of one surface of revolution seen apart are joined, and so is
/// its handle.
struct CoaxialPieceParams {
  float max_axis_distance = 0.02f;
  float max_gap = 0.04f;
  float min_axis_share = 0.6f;
  float min_height_overlap = 0.5f;
  float max_handle_share = 0.3f;
};

inline void describeParameters(ParameterList<CoaxialPieceParams>& list) {
  list.add("max_axis_distance", &CoaxialPieceParams::max_axis_distance, 0.0, 0.5, "m",
           "two segments whose vertical axes of revolution are closer than this share one...")
      .add("max_gap", &CoaxialPieceParams::max_gap, 0.0, 0.5, "m",
           "...when they come closer than this, with no observed free space where they come closest")
      .add("min_axis_share", &CoaxialPieceParams::min_axis_share, 0.0, 1.0, "",
           "a segment turns about an axis when this share of its side points' normal lines pass it (upright.max_axis_residual)")
      .add("min_height_overlap", &CoaxialPieceParams::min_height_overlap, 0.0, 1.0, "",
           "...and the two span the same heights over this share of the shorter one's height: one object's walls, not one object on another")
      .add("max_handle_share", &CoaxialPieceParams::max_handle_share, 0.0, 1.0, "",
           "a piece beside a segment turning about an axis, at most this share of it and within its heights, that the vertical plane through the axis and the piece mirrors onto itself (a handle, a spout) is joined to it; 0: never");
}

/// Stage completion: each object's unseen side from its symmetry.
struct CompletionParams {
  int revolution_steps = 12;
  bool ground_to_support = true;
  bool rest_on_support = true;
};

inline void describeParameters(ParameterList<CompletionParams>& list) {
  list.add("revolution_steps", &CompletionParams::revolution_steps, 0, 360, "",
           "a segment turning about a vertical axis (coaxial_pieces.min_axis_share) is also completed by copies turned "
           "by this many equal steps about it; 0: by its reflection alone")
      .add("ground_to_support", &CompletionParams::ground_to_support,
           "a side whose lower part is hidden runs on down to the support where all the space under it is unobserved")
      .add("rest_on_support", &CompletionParams::rest_on_support,
           "the completed box of an object whose box ends under two table margins over the support, on no other segment, reaches down to it (the table's cut took its foot)");
}

struct SymmetryParams {
  int threads = 0;
  bool depth_image_occupancy = true;
  std::vector<std::string> stages = {"curves",          "curve_pairs",  "upright",     "cut",        "refine",
                                     "islands",         "footprints",   "cut",         "occluder_gaps", "refine",
                                     "filter",          "island_segments", "mirror_twins", "composites", "color_seams",
                                     "coaxial_pieces",  "object_size",  "dedup",       "object_bottoms", "completion"};
  NormalEdgeCurveParams curves;
  CurvePairParams curve_pairs;
  UprightHypothesisParams upright;
  SymmetryCutParams cut;
  SymmetryRefinementParams refine;
  IslandParams islands;
  FootprintParams footprints;
  OccluderGapParams occluder_gaps;
  SymmetryFilterParams filter;
  IslandSegmentParams island_segments;
  MirrorTwinParams mirror_twins;
  CompositeSegmentParams composites;
  NestedSegmentParams nested;
  ColorSeamParams color_seams;
  CoaxialPieceParams coaxial_pieces;
  ObjectSizeParams object_size;
  CompletionParams completion;
  DuplicateParams dedup;
  StrayColorParams stray_color_pieces;
};

/// Problems of a stage list: unknown names, a stage whose inputs no earlier stage makes, no
/// segments at the end (stage_catalog.cpp). Empty when the list can run.
std::vector<std::string> stageListProblems(const std::vector<std::string>& stages);

inline void describeParameters(ParameterList<SymmetryParams>& list) {
  list.add("threads", &SymmetryParams::threads, 0, 1024, "", "worker threads for independent hypotheses; 0 = all cores")
      .add("depth_image_occupancy", &SymmetryParams::depth_image_occupancy,
           "a camera frame (organized cloud) without a map: free space straight from its depth image (in front of a "
           "pixel's depth = free); false: ray-cast an OctoMap from the cloud")
      .add("stages", &SymmetryParams::stages,
           "what runs, in order (README, 'The symmetry method'); leave a stage out to switch it off")
      .rule([](const SymmetryParams& p) {
        std::string problems;
        for (const std::string& problem : stageListProblems(p.stages)) problems += (problems.empty() ? "" : "; ") + problem;
        return problems;
      });
}

}  // namespace symmetry_segmentation
