#pragma once
// Stage 5d (our addition): objects that meet flush, told apart by their colour.
//
// A box on a box of the same footprint, or boxes of one depth pushed into a row, share flat
// faces that run straight on from one object into the next, and often a symmetry plane too: to
// the geometry they are one taller (or wider) box, and no cut or crease test can part them.
// Their colours can. A segment whose surface falls into a few large regions of uniform colour
// (a region: points linked through neighbours of nearly the same colour) is split into them when
// the regions meet across flat links along a seam running right across both - a colour edge
// over a flat face where nothing in the shape changes - or where a good share of the seam is a
// concave crease between two sizeable regions (a bowl on a box, which the cut took together).
// Colour edges that follow one object's convex edges (a can's lid) or ring a narrow part (a
// bottle's cap) keep the regions together; a printed, textured object falls into many small
// regions and is left alone.
// Each part keeps the plane, among the segment's and those found on the part, that the part
// contradicts least (reflections into free space or onto points outside it).
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/composite_segments.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

struct ColorSeamParams {
  float max_link_difference = 15.0f;  ///< CIELAB colour difference (lightness at half weight, so
                                      ///< shading matters less than hue) up to which linked points
                                      ///< are one colour region.
  float min_part_fraction = 0.1f;     ///< Regions with at least this share of the segment (and
  int min_part_points = 40;           ///< this many points) are candidate objects.
  float min_coverage = 0.8f;          ///< Those regions cover at least this share (else textured).
  float flat_link_angle_deg = 15.0f;  ///< Links whose normals differ by less are flat.
  float min_flat_seam_fraction = 0.5f;///< Two regions stay apart if this share of the flat and
                                      ///< convex links between them is flat, else they are one
                                      ///< object's parts (concave links are neutral).
  int min_seam_links = 5;             ///< Regions linked by fewer links do not meet; a seam
                                      ///< with fewer flat links is not flat.
  float min_concave_seam_fraction = 0.3f;   ///< Regions meeting with this share of concave
  float min_touching_part_fraction = 0.25f;  ///< links (a bowl on a box) are two objects when
                                             ///< the smaller has this share (a handle has less).
  float min_seam_span = 0.7f;         ///< A seam between objects spans at least this share of
                                      ///< each one's extent along one of the seam's axes.
  float min_plane_share = 0.3f;       ///< A found segment's plane is tried on a part it covers this
                                      ///< share of.
};

/// Replaces each segment of `segments` that is several flush objects of different colours
/// (`cloud`'s RGB) by those objects, each with the plane (the segment's, or that of a segment
/// of `found` covering a good share of it) it contradicts least, scored by `score`.
/// `neighbours[i]`: the working-cloud points linked to point i. Returns how many were split.
std::size_t splitAtColorSeams(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& found,
                              const Cloud& cloud, const std::vector<std::vector<int>>& neighbours,
                              const ReflectionMatch& match, const SegmentScorer& score,
                              const ColorSeamParams& params = {});

}  // namespace symmetry_segmentation
