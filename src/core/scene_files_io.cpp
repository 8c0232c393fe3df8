// The small side files of a scene: OctoMap, supporting plane, ground-truth labels.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <boost/filesystem.hpp>
#include <octomap/AbstractOcTree.h>
#include <octomap/OcTree.h>

#include "symmetry_segmentation/scene_io.h"

namespace symmetry_segmentation {
namespace {

std::string readWholeFile(const std::string& path) {
  boost::system::error_code ec;
  if (!boost::filesystem::exists(path, ec)) throw InputError(path, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// OctoMap's readers trust the stream: a truncated tree parses "successfully" into a partial
// map, but the reads past the end leave the stream failed.
void checkStreamComplete(const std::string& path, const std::istream& stream) {
  if (stream.fail()) throw InputError(path, "truncated OctoMap data");
}

// The .bt header ("# Octomap OcTree binary file", "id OcTree", "size N", "res R", "data"),
// parsed here because OctoMap's own reader chats on stderr and accepts nonsense resolutions.
std::shared_ptr<octomap::OcTree> readBinaryTree(const std::string& path, std::istream& stream) {
  std::string line, id;
  double resolution = 0.0;
  long long size = -1;
  bool have_data = false;
  for (int i = 0; i < 100 && std::getline(stream, line); ++i) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string key;
    fields >> key;
    if (key == "id") {
      fields >> id;
    } else if (key == "size") {
      fields >> size;
    } else if (key == "res") {
      fields >> resolution;
    } else if (key == "data") {
      have_data = true;
      break;
    }
  }
  if (!have_data) throw InputError(path, "corrupt OctoMap header (no 'data' line)");
  if (id != "OcTree") throw InputError(path, "unsupported OctoMap tree type '" + id + "' (expected OcTree)");
  if (!(resolution > 0.0) || !std::isfinite(resolution)) throw InputError(path, "OctoMap resolution must be positive");
  if (size < 0) throw InputError(path, "corrupt OctoMap header (no valid 'size' line)");
  auto tree = std::make_shared<octomap::OcTree>(resolution);
  if (size > 0) tree->readBinaryData(stream);  // an empty map has no data at all
  return tree;
}

}  // namespace

std::shared_ptr<octomap::OcTree> loadOctomapFile(const std::string& path) {
  const std::string content = readWholeFile(path);
  if (content.empty()) throw InputError(path, "file is empty");
  const std::string ext = boost::filesystem::path(path).extension().string();
  std::istringstream stream(content);
  if (ext == ".bt") {
    if (!startsWith(content, "# Octomap OcTree binary file")) {
      throw InputError(path, "not a binary OctoMap file (bad header)");
    }
    auto tree = readBinaryTree(path, stream);
    checkStreamComplete(path, stream);
    return tree;
  }
  if (ext == ".ot") {
    if (!startsWith(content, "# Octomap OcTree file")) {
      throw InputError(path, "not an OctoMap .ot file (bad header)");
    }
    std::unique_ptr<octomap::AbstractOcTree> abstract(octomap::AbstractOcTree::read(stream));
    if (!abstract) throw InputError(path, "corrupt or truncated OctoMap data");
    checkStreamComplete(path, stream);
    auto* octree = dynamic_cast<octomap::OcTree*>(abstract.get());
    if (!octree) {
      throw InputError(path, "unsupported OctoMap tree type '" + abstract->getTreeType() +
                                 "' (expected OcTree)");
    }
    abstract.release();
    return std::shared_ptr<octomap::OcTree>(octree);
  }
  throw InputError(path, "unsupported OctoMap extension '" + ext + "' (expected .bt or .ot)");
}

PlaneCoefficients loadPlaneFile(const std::string& path) {
  std::istringstream in(readWholeFile(path));
  PlaneCoefficients plane;
  for (int i = 0; i < 4; ++i) {
    std::string token;
    if (!(in >> token)) throw InputError(path, "expected 4 numbers 'a b c d', found " + std::to_string(i));
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(token.c_str(), &end);
    if (errno != 0 || end == token.c_str() || *end != '\0' || !std::isfinite(value)) {
      throw InputError(path, "'" + token + "' is not a finite number");
    }
    plane[i] = static_cast<float>(value);
  }
  std::string extra;
  if (in >> extra) throw InputError(path, "unexpected text after 'a b c d': '" + extra + "'");
  const float norm = plane.head<3>().norm();
  if (!(norm > 1e-6f)) throw InputError(path, "plane normal (a, b, c) is zero");
  return plane / norm;
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
