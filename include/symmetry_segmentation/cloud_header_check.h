#pragma once
// Checks a PCD or PLY file before PCL reads it. PCL's readers size their buffers from the
// header's point count (a 1 KB file may claim 60M points and cost gigabytes), compute sizes in
// 32 bits, and turn unparsable ASCII values into silent garbage. Parsing the header ourselves,
// with 64-bit arithmetic, and bounding every count by the bytes the file really holds, keeps a
// bad file to a one-line InputError.

#include <cstdint>
#include <string>

namespace symmetry_segmentation {

/// Most points a cloud file may declare: far beyond any tabletop scan, still a few GB of RAM.
constexpr std::uint64_t kMaxCloudPoints = 200000000;

/// Throws InputError unless `path` exists, is not a directory and can be opened for reading.
void checkReadableFile(const std::string& path);

/// What a checked header declares.
struct CloudFileSummary {
  std::uint64_t points = 0;  ///< POINTS of a PCD, `element vertex` count of a PLY (>= 1).
  bool has_camera = false;   ///< PLY only: the header has a `camera` element.
};

/// PCD: FIELDS/SIZE/TYPE/COUNT agree, WIDTH * HEIGHT == POINTS, the data section holds POINTS
/// points (binary, binary_compressed sizes; ASCII: every value a number or nan).
CloudFileSummary checkPcdFile(const std::string& path);

/// PLY: known format and property types, every element fits in the bytes after the header,
/// and ASCII data consists of numbers.
CloudFileSummary checkPlyFile(const std::string& path);

}  // namespace symmetry_segmentation
