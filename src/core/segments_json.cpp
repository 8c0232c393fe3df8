#include "symmetry_segmentation/segments_json.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
using Json = nlohmann::ordered_json;

std::string toJson(const SegmentationResult& result) {
  // Hand-laid top level so a person can read it: one segment per line, indices inline.
  std::ostringstream out;
  out << "{\"input_points\": " << result.input_points << ",\n \"segments\": [";
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

SegmentationResult readSegmentsJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open file for reading");
  SegmentationResult result;
  try {
    const Json json = Json::parse(in);
    result.input_points = json.at("input_points").get<std::size_t>();
    for (const auto& entry : json.at("segments")) {
      Segment segment;
      segment.indices = entry.at("indices").get<std::vector<int>>();
      for (int index : segment.indices) {
        if (index < 0 || static_cast<std::size_t>(index) >= result.input_points) {
          throw InputError(path, "segment index " + std::to_string(index) + " outside [0, input_points)");
        }
      }
      if (entry.contains("symmetry")) {
        SymmetryPlane plane;
        const auto normal = entry["symmetry"].at("normal").get<std::vector<float>>();
        if (normal.size() != 3) throw InputError(path, "symmetry normal needs 3 numbers");
        plane.normal = Eigen::Vector3f(normal[0], normal[1], normal[2]);
        plane.distance = entry["symmetry"].at("distance").get<float>();
        segment.symmetry = plane;
      }
      if (entry.contains("scores")) {
        segment.scores = SegmentScores{entry["scores"].at("occlusion").get<float>(),
                                       entry["scores"].at("smoothness").get<float>()};
      }
      result.segments.push_back(std::move(segment));
    }
    if (json.contains("counts")) {
      for (const auto& [name, count] : json["counts"].items()) result.counts.emplace_back(name, count.get<std::size_t>());
    }
    if (json.contains("timing_ms")) {
      for (const auto& [stage, ms] : json["timing_ms"].items()) result.timing_ms.emplace_back(stage, ms.get<double>());
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, std::string("malformed segments JSON: ") + e.what());
  }
  return result;
}

}  // namespace symmetry_segmentation
