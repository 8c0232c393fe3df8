#pragma once
// segments.json: {"input_points": N, "support": {...}, "segments": [{"indices": [...],
// "symmetry": {...}, "scores": {...}, "box": {"center": [...], "axes": [[x], [y], [z]],
// "size": [...]}, "completion": {"points": n, "box": {...}, "frame": {"position": [...],
// "orientation": [x, y, z, w]}}}], "timing_ms": {...}, "counts": {...}}. Reading skips
// "completion" (its points are in segments_completed.ply).

#include <string>

#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

std::string toJson(const SegmentationResult& result);
void writeSegmentsJson(const SegmentationResult& result, const std::string& path);
/// Throws InputError on unreadable or malformed files.
SegmentationResult readSegmentsJson(const std::string& path);

}  // namespace symmetry_segmentation
