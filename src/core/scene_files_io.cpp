// The small side files of a scene: OctoMap, supporting plane, ground-truth labels.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <boost/filesystem.hpp>
#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>

#include "symmetry_segmentation/cloud_header_check.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/scene_io.h"

namespace symmetry_segmentation {
namespace {

std::string readWholeFile(const std::string& path) {
  checkReadableFile(path);
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path, "cannot read file");
  return buffer.str();
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// OcTree keys have 16 bits per axis: the root is depth 0, the finest voxels depth 16.
constexpr int kOcTreeDepth = 16;
// Resolutions outside this range are not occupancy maps of a tabletop (m).
constexpr double kMinResolution = 1e-4, kMaxResolution = 10.0;

struct OctomapHeader {
  std::string id;
  std::uint64_t size = 0;         ///< Nodes in the tree.
  double resolution = 0.0;
  std::size_t data_offset = 0;    ///< First byte after the "data" line.
};

// Digits only, so "size -1" or "size 1e9" are errors rather than wrapped or truncated numbers.
bool parseNodeCount(const std::string& text, std::uint64_t& value) {
  if (text.empty() || text.size() > 18) return false;
  value = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return true;
}

bool parseResolution(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(value);
}

// The header both formats share: a magic first line, then "id", "size", "res", "data" lines
// (comment lines allowed). Parsed here because OctoMap's own reader chats on stderr and
// accepts nonsense resolutions.
OctomapHeader parseOctomapHeader(const std::string& path, const std::string& content) {
  OctomapHeader header;
  bool have_size = false, have_res = false;
  std::size_t begin = content.find('\n');  // skip the magic line, checked by the caller
  for (int lines = 0; begin != std::string::npos && lines < 100; ++lines) {
    ++begin;
    std::size_t end = content.find('\n', begin);
    if (end == std::string::npos) end = content.size();
    std::istringstream fields(content.substr(begin, end - begin));
    std::string key, value;
    fields >> key >> value;
    if (key == "data") {
      header.data_offset = std::min(end + 1, content.size());
      if (header.id.empty()) throw InputError(path, "corrupt OctoMap header (no 'id' line)");
      if (!have_size) throw InputError(path, "corrupt OctoMap header (no valid 'size' line)");
      if (!have_res) throw InputError(path, "corrupt OctoMap header (no valid 'res' line)");
      return header;
    }
    if (key == "id") {
      header.id = value;
    } else if (key == "size") {
      have_size = parseNodeCount(value, header.size);
      if (!have_size) throw InputError(path, "corrupt OctoMap header (size '" + value + "' is not a node count)");
    } else if (key == "res") {
      have_res = parseResolution(value, header.resolution);
      if (!have_res || header.resolution < kMinResolution || header.resolution > kMaxResolution) {
        throw InputError(path, "OctoMap resolution '" + value + "' must be a number in [1e-4, 10] m");
      }
    } else if (!key.empty() && key[0] != '#') {
      throw InputError(path, "corrupt OctoMap header (unexpected line '" + key + "')");
    }
    begin = end < content.size() ? end : std::string::npos;
  }
  throw InputError(path, "corrupt OctoMap header (no 'data' line)");
}

[[noreturn]] void throwCorruptTree(const std::string& path, const std::string& why) {
  throw InputError(path, "truncated or corrupt OctoMap data (" + why + ")");
}

// Walks the node stream without building anything and returns its node count. OctoMap's
// recursive readers would instead follow garbage child bits past the tree's 16 levels and past
// the end of the data (uninitialised bytes, gigabytes of nodes, stack overflow).
// `node_bytes` is what one node occupies; `children_of` decodes, for the node starting at
// `bytes`, which children exist and which of those are followed by their own nodes.
// `inner_nodes_need_children`: in .bt a followed child is an inner node, which OctoMap only
// writes when it has children.
template <typename ChildDecoder>
std::uint64_t countTreeNodes(const std::string& path, const std::string& data, std::size_t node_bytes,
                             bool inner_nodes_need_children, ChildDecoder children_of) {
  std::uint64_t nodes = 0;
  std::size_t cursor = 0;
  std::vector<int> pending_depths = {0};  // nodes still to read, next one last (pre-order)
  while (!pending_depths.empty()) {
    const int depth = pending_depths.back();
    pending_depths.pop_back();
    if (data.size() - cursor < node_bytes) throwCorruptTree(path, "data ends inside a node");
    int existing = 0, followed = 0;
    children_of(reinterpret_cast<const unsigned char*>(data.data() + cursor), existing, followed);
    cursor += node_bytes;
    ++nodes;
    if (existing != 0 && depth >= kOcTreeDepth) throwCorruptTree(path, "tree deeper than 16 levels");
    if (existing == 0 && depth > 0 && inner_nodes_need_children) throwCorruptTree(path, "inner node without children");
    for (int child = 7; child >= 0; --child) {
      if (followed & (1 << child)) pending_depths.push_back(depth + 1);
    }
    for (int child = 0; child < 8; ++child) {
      if ((existing & (1 << child)) && !(followed & (1 << child))) ++nodes;  // a leaf with no bytes
    }
  }
  if (cursor != data.size()) throwCorruptTree(path, std::to_string(data.size() - cursor) + " bytes after the tree");
  return nodes;
}

// .bt: 2 bytes per inner node, 2 bits per child (10 free leaf, 01 occupied leaf, 11 inner).
std::uint64_t countBinaryTreeNodes(const std::string& path, const std::string& data) {
  return countTreeNodes(path, data, 2, true, [](const unsigned char* bytes, int& existing, int& followed) {
    existing = followed = 0;
    for (int child = 0; child < 8; ++child) {
      const int code = (bytes[child / 4] >> (2 * (child % 4))) & 3;
      if (code != 0) existing |= 1 << child;
      if (code == 3) followed |= 1 << child;
    }
  });
}

// .ot (OcTree): every node is its float log-odds then one byte of child bits; every child is
// followed by its own node. Leaves have no children, so their count is already in the walk.
// ColorOcTree nodes hold 3 colour bytes between the two (`payload_bytes` after the log-odds).
std::uint64_t countFullTreeNodes(const std::string& path, const std::string& data, std::size_t payload_bytes = 0) {
  bool finite = true;
  const std::size_t child_byte = sizeof(float) + payload_bytes;
  const std::uint64_t nodes = countTreeNodes(
      path, data, child_byte + 1, false, [&finite, child_byte](const unsigned char* bytes, int& existing, int& followed) {
        float log_odds = 0.0f;
        std::memcpy(&log_odds, bytes, sizeof(float));
        finite = finite && std::isfinite(log_odds);
        existing = followed = bytes[child_byte];
      });
  if (!finite) throwCorruptTree(path, "non-finite occupancy value");
  return nodes;
}

void requireNodeCount(const std::string& path, std::uint64_t declared, std::uint64_t found) {
  if (declared != found) {
    throwCorruptTree(path, "header says " + std::to_string(declared) + " nodes, data holds " + std::to_string(found));
  }
}

// Reads the (already walked) data with OctoMap. A failing read throws instead of leaving
// OctoMap to continue on uninitialised bytes; the result must hold the nodes the walk counted.
template <typename Tree, typename ReadNodes>
void readNodes(const std::string& path, const std::string& data, std::uint64_t nodes, Tree& tree, ReadNodes read_nodes) {
  std::istringstream stream(data);
  stream.exceptions(std::ios::failbit | std::ios::badbit);
  try {
    read_nodes(tree, stream);
  } catch (const std::ios_base::failure&) {
    throw InputError(path, "truncated or corrupt OctoMap data");
  }
  requireNodeCount(path, nodes, tree.size());
  if (stream.rdbuf()->sgetc() != std::char_traits<char>::eof()) throwCorruptTree(path, "bytes after the tree");
}

std::shared_ptr<octomap::OcTree> loadTree(const std::string& path, const std::string& content, bool binary) {
  const OctomapHeader header = parseOctomapHeader(path, content);
  if (header.id != "OcTree") {
    throw InputError(path, "unsupported OctoMap tree type '" + header.id + "' (expected OcTree)");
  }
  const std::string data = content.substr(header.data_offset);
  // Cheap bound first: a .bt node costs at least 2 bits of its parent's 2 bytes (4 per byte,
  // plus the root), an .ot node exactly 5 bytes.
  const std::uint64_t max_nodes = binary ? 4 * static_cast<std::uint64_t>(data.size()) + 1 : data.size() / 5;
  if (header.size > max_nodes) {
    throwCorruptTree(path, "header says " + std::to_string(header.size) + " nodes, " +
                               std::to_string(data.size()) + " bytes hold at most " + std::to_string(max_nodes));
  }
  if (header.size == 0 && !data.empty()) throwCorruptTree(path, "an empty tree with data");
  auto tree = readOctreeData(path, data, binary ? OctreeEncoding::Binary : OctreeEncoding::Full, header.resolution);
  requireNodeCount(path, header.size, tree->size());
  return tree;
}

}  // namespace

std::shared_ptr<octomap::OcTree> readOctreeData(const std::string& source, const std::string& data,
                                                OctreeEncoding encoding, double resolution) {
  if (!(resolution >= kMinResolution && resolution <= kMaxResolution)) {
    throw InputError(source, "OctoMap resolution " + std::to_string(resolution) + " must be within [1e-4, 10] m");
  }
  auto tree = std::make_shared<octomap::OcTree>(resolution);
  if (data.empty()) return tree;  // an empty map has no data at all
  switch (encoding) {
    case OctreeEncoding::Binary:
      readNodes(source, data, countBinaryTreeNodes(source, data), *tree,
                [](octomap::OcTree& t, std::istream& s) { t.readBinaryData(s); });
      break;
    case OctreeEncoding::Full:
      readNodes(source, data, countFullTreeNodes(source, data), *tree,
                [](octomap::OcTree& t, std::istream& s) { t.readData(s); });
      break;
    case OctreeEncoding::FullColor: {
      // Keep the occupancy, drop the colours: the colour tree's binary form read as an OcTree.
      const std::uint64_t nodes = countFullTreeNodes(source, data, 3);
      octomap::ColorOcTree color(resolution);
      readNodes(source, data, nodes, color, [](octomap::ColorOcTree& t, std::istream& s) { t.readData(s); });
      std::stringstream binary(std::ios::in | std::ios::out | std::ios::binary);
      color.writeBinaryData(binary);
      readNodes(source, binary.str(), nodes, *tree, [](octomap::OcTree& t, std::istream& s) { t.readBinaryData(s); });
      break;
    }
  }
  return tree;
}

std::shared_ptr<octomap::OcTree> loadOctomapFile(const std::string& path) {
  const std::string content = readWholeFile(path);
  if (content.empty()) throw InputError(path, "file is empty");
  const std::string ext = boost::filesystem::path(path).extension().string();
  if (ext == ".bt") {
    if (!startsWith(content, "# Octomap OcTree binary file")) {
      throw InputError(path, "not a binary OctoMap file (bad header)");
    }
    return loadTree(path, content, true);
  }
  if (ext == ".ot") {
    if (!startsWith(content, "# Octomap OcTree file")) {
      throw InputError(path, "not an OctoMap .ot file (bad header)");
    }
    return loadTree(path, content, false);
  }
  throw InputError(path, "unsupported OctoMap extension '" + ext + "' (expected .bt or .ot)");
}

PlaneCoefficients loadPlaneFile(const std::string& path) {
  std::istringstream in(readWholeFile(path));
  Eigen::Vector4d plane;
  for (int i = 0; i < 4; ++i) {
    std::string token;
    if (!(in >> token)) throw InputError(path, "expected 4 numbers 'a b c d', found " + std::to_string(i));
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(token.c_str(), &end);
    if (errno != 0 || end == token.c_str() || *end != '\0' || !std::isfinite(value)) {
      throw InputError(path, "'" + token + "' is not a finite number");
    }
    plane[i] = value;
  }
  std::string extra;
  if (in >> extra) throw InputError(path, "unexpected text after 'a b c d': '" + extra + "'");
  // Normalised in double: float would turn a tiny normal into zero or a huge one into inf.
  const double scale = plane.head<3>().cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) throw InputError(path, "plane normal (a, b, c) is zero");
  plane /= scale;
  plane /= plane.head<3>().norm();
  const PlaneCoefficients result = plane.cast<float>();
  if (!result.allFinite() || std::fabs(result[3]) > kMaxUsableCoordinate) {
    throw InputError(path, "plane offset d / |(a, b, c)| is not finite or farther than 100 km");
  }
  return result;
}

std::vector<int> loadLabelsFile(const std::string& path, std::size_t expected_count) {
  const std::string content = readWholeFile(path);
  std::vector<int> labels;
  labels.reserve(expected_count);
  const char* cursor = content.c_str();
  const char* const end = cursor + content.size();
  std::size_t line = 1;
  while (cursor < end) {
    if (*cursor == '\n') ++line;
    if (std::isspace(static_cast<unsigned char>(*cursor))) {
      ++cursor;
      continue;
    }
    char* token_end = nullptr;
    errno = 0;
    const long value = std::strtol(cursor, &token_end, 10);
    if (token_end == cursor || errno != 0 || value < 0 || value > 1000000000L ||
        (token_end < end && !std::isspace(static_cast<unsigned char>(*token_end)))) {
      throw InputError(path, "line " + std::to_string(line) + ": expected a non-negative integer label");
    }
    labels.push_back(static_cast<int>(value));
    cursor = token_end;
  }
  if (labels.size() != expected_count) {
    throw InputError(path, "has " + std::to_string(labels.size()) + " labels but the cloud has " +
                               std::to_string(expected_count) + " points");
  }
  return labels;
}

}  // namespace symmetry_segmentation
