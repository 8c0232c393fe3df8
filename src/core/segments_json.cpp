#include "symmetry_segmentation/segments_json.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/object_box.h"

namespace symmetry_segmentation {
using Json = nlohmann::ordered_json;

namespace {

Json boxJson(const ObjectBox& box) {
  Json axes = Json::array();  // one unit direction per row: x, y, z
  for (int k = 0; k < 3; ++k) axes.push_back({box.axes(0, k), box.axes(1, k), box.axes(2, k)});
  return {{"center", {box.center.x(), box.center.y(), box.center.z()}},
          {"axes", axes},
          {"size", {box.size.x(), box.size.y(), box.size.z()}}};
}

}  // namespace

std::string toJson(const SegmentationResult& result) {
  // Hand-laid top level so a person can read it: one segment per line, indices inline.
  std::ostringstream out;
  out << "{\"input_points\": " << result.input_points << ",\n";
  if (result.support) {
    const auto& plane = result.support->plane;
    Json support;
    support["plane"] = {plane[0], plane[1], plane[2], plane[3]};
    support["polygon"] = Json::array();
    for (const auto& corner : result.support->polygon) support["polygon"].push_back({corner.x(), corner.y(), corner.z()});
    support["noise"] = result.support->noise;
    out << " \"support\": " << support.dump() << ",\n";
  }
  out << " \"segments\": [";
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const Segment& segment = result.segments[i];
    Json entry;
    entry["indices"] = segment.indices;
    if (segment.symmetry) {
      const auto& n = segment.symmetry->normal;
      entry["symmetry"] = {{"normal", {n.x(), n.y(), n.z()}}, {"distance", segment.symmetry->distance}};
    }
    if (segment.scores) {
      entry["scores"] = {{"occlusion", segment.scores->occlusion}, {"smoothness", segment.scores->smoothness}};
    }
    if (segment.box) entry["box"] = boxJson(*segment.box);
    if (segment.completion) {
      const SegmentCompletion& completion = *segment.completion;
      const Eigen::Vector3f& p = completion.frame_position;
      const Eigen::Quaternionf& q = completion.frame_orientation;
      entry["completion"] = {{"points", completion.points.size()},
                             {"box", boxJson(completion.box)},
                             {"frame", {{"position", {p.x(), p.y(), p.z()}}, {"orientation", {q.x(), q.y(), q.z(), q.w()}}}}};
    }
    out << (i == 0 ? "\n  " : ",\n  ") << entry.dump();
  }
  Json timing = Json::object();
  for (const auto& [stage, ms] : result.timing_ms) timing[stage] = ms;
  out << "],\n \"timing_ms\": " << timing.dump();
  if (!result.counts.empty()) {
    Json counts = Json::object();
    for (const auto& [name, count] : result.counts) counts[name] = count;
    out << ",\n \"counts\": " << counts.dump();
  }
  out << "}\n";
  return out.str();
}

void writeSegmentsJson(const SegmentationResult& result, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << toJson(result);
  if (!out) throw InputError(path, "cannot write file");
}

namespace {

// nlohmann's get<>() converts silently (3.5 -> 3, -1 -> 2^64-1, 1e300 -> inf as float): every
// value is checked for the exact JSON type instead, and failures name the offending field.
[[noreturn]] void malformed(const std::string& path, const std::string& problem) {
  throw InputError(path, "malformed segments JSON: " + problem);
}

std::uint64_t unsignedInteger(const std::string& path, const Json& value, const std::string& what) {
  if (!value.is_number_unsigned()) malformed(path, what + " must be a non-negative integer");
  return value.get<std::uint64_t>();
}

float finiteFloat(const std::string& path, const Json& value, const std::string& what) {
  if (!value.is_number()) malformed(path, what + " must be a number");
  const float number = value.get<float>();
  if (!std::isfinite(number)) malformed(path, what + " must be finite");
  return number;
}

const Json& member(const std::string& path, const Json& object, const std::string& key, const std::string& what) {
  if (!object.is_object()) malformed(path, what + " must be an object");
  if (!object.contains(key)) malformed(path, what + " lacks '" + key + "'");
  return object.at(key);
}

std::vector<int> segmentIndices(const std::string& path, const Json& indices, std::size_t input_points) {
  if (!indices.is_array()) malformed(path, "'indices' must be an array");
  std::vector<int> result;
  result.reserve(indices.size());
  for (const Json& index : indices) {
    const std::uint64_t value = unsignedInteger(path, index, "segment index");
    if (value >= input_points) {
      throw InputError(path, "segment index " + std::to_string(value) + " outside [0, input_points)");
    }
    result.push_back(static_cast<int>(value));  // < input_points <= INT_MAX
  }
  return result;
}

SymmetryPlane symmetryPlane(const std::string& path, const Json& symmetry) {
  const Json& normal = member(path, symmetry, "normal", "'symmetry'");
  if (!normal.is_array() || normal.size() != 3) malformed(path, "symmetry normal needs 3 numbers");
  SymmetryPlane plane;
  for (int i = 0; i < 3; ++i) plane.normal[i] = finiteFloat(path, normal[i], "symmetry normal");
  plane.distance = finiteFloat(path, member(path, symmetry, "distance", "'symmetry'"), "symmetry distance");
  return plane;
}

SegmentScores segmentScores(const std::string& path, const Json& scores) {
  return SegmentScores{finiteFloat(path, member(path, scores, "occlusion", "'scores'"), "occlusion score"),
                       finiteFloat(path, member(path, scores, "smoothness", "'scores'"), "smoothness score")};
}

std::vector<float> finiteNumbers(const std::string& path, const Json& array, std::size_t size, const std::string& what) {
  if (!array.is_array() || array.size() != size) malformed(path, what + " needs " + std::to_string(size) + " numbers");
  std::vector<float> numbers;
  for (const Json& value : array) numbers.push_back(finiteFloat(path, value, what));
  return numbers;
}

SupportSurface supportSurface(const std::string& path, const Json& support) {
  SupportSurface surface;
  const std::vector<float> plane = finiteNumbers(path, member(path, support, "plane", "'support'"), 4, "support plane");
  surface.plane = Eigen::Vector4f(plane[0], plane[1], plane[2], plane[3]);
  if (!(surface.plane.head<3>().norm() > 0.0f)) malformed(path, "support plane has a zero normal");
  const Json& polygon = member(path, support, "polygon", "'support'");
  if (!polygon.is_array()) malformed(path, "support polygon must be an array");
  for (const Json& corner : polygon) {
    const std::vector<float> xyz = finiteNumbers(path, corner, 3, "support polygon corner");
    surface.polygon.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  if (support.contains("noise")) {  // optional: files written before it
    surface.noise = finiteFloat(path, support["noise"], "support noise");
    if (surface.noise < 0.0f) malformed(path, "support noise must not be negative");
  }
  return surface;
}

ObjectBox objectBox(const std::string& path, const Json& json) {
  ObjectBox box;
  const std::vector<float> center = finiteNumbers(path, member(path, json, "center", "'box'"), 3, "box center");
  const std::vector<float> size = finiteNumbers(path, member(path, json, "size", "'box'"), 3, "box size");
  const Json& axes = member(path, json, "axes", "'box'");
  if (!axes.is_array() || axes.size() != 3) malformed(path, "box axes need 3 rows");
  for (int k = 0; k < 3; ++k) {
    const std::vector<float> axis = finiteNumbers(path, axes[k], 3, "box axis");
    box.axes.col(k) = Eigen::Vector3f(axis[0], axis[1], axis[2]);
  }
  box.center = Eigen::Vector3f(center[0], center[1], center[2]);
  box.size = Eigen::Vector3f(size[0], size[1], size[2]);
  const std::string problem = boxProblem(box);
  if (!problem.empty()) malformed(path, problem);
  return box;
}

Segment readSegment(const std::string& path, const Json& entry, std::size_t input_points) {
  Segment segment;
  segment.indices = segmentIndices(path, member(path, entry, "indices", "each segment"), input_points);
  if (entry.contains("symmetry")) segment.symmetry = symmetryPlane(path, entry["symmetry"]);
  if (entry.contains("scores")) segment.scores = segmentScores(path, entry["scores"]);
  if (entry.contains("box")) segment.box = objectBox(path, entry["box"]);
  return segment;
}

Timings readTimings(const std::string& path, const Json& timing) {
  if (!timing.is_object()) malformed(path, "'timing_ms' must be an object");
  Timings result;
  for (const auto& [stage, ms] : timing.items()) {
    if (!ms.is_number() || !std::isfinite(ms.get<double>())) malformed(path, "timing '" + stage + "' must be a finite number");
    result.emplace_back(stage, ms.get<double>());
  }
  return result;
}

Counts readCounts(const std::string& path, const Json& counts) {
  if (!counts.is_object()) malformed(path, "'counts' must be an object");
  Counts result;
  for (const auto& [name, count] : counts.items()) {
    result.emplace_back(name, static_cast<std::size_t>(unsignedInteger(path, count, "count '" + name + "'")));
  }
  return result;
}

}  // namespace

SegmentationResult readSegmentsJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open file for reading");
  SegmentationResult result;
  try {
    const Json json = Json::parse(in);
    const std::uint64_t input_points = unsignedInteger(path, member(path, json, "input_points", "the top level"), "'input_points'");
    if (input_points > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      malformed(path, "'input_points' is larger than an index can be");
    }
    result.input_points = static_cast<std::size_t>(input_points);
    if (json.contains("support")) result.support = supportSurface(path, json["support"]);
    const Json& segments = member(path, json, "segments", "the top level");
    if (!segments.is_array()) malformed(path, "'segments' must be an array");
    for (const Json& entry : segments) result.segments.push_back(readSegment(path, entry, result.input_points));
    if (json.contains("counts")) result.counts = readCounts(path, json["counts"]);
    if (json.contains("timing_ms")) result.timing_ms = readTimings(path, json["timing_ms"]);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, std::string("malformed segments JSON: ") + e.what());
  }
  return result;
}

}  // namespace symmetry_segmentation
