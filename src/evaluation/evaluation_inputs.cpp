#include "symmetry_segmentation/evaluation/evaluation_inputs.h"

#include <algorithm>
#include <cctype>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/errors.h"

namespace fs = boost::filesystem;

namespace symmetry_segmentation {

namespace {

bool isLabelledScene(const fs::path& directory) {
  boost::system::error_code error;
  return fs::is_regular_file(directory / "labels.txt", error);
}

bool isPcdFile(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  boost::system::error_code error;
  return extension == ".pcd" && fs::is_regular_file(path, error);
}

// "learn2" before "learn10": runs of digits compare by value.
bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t end_a = i, end_b = j;
      while (end_a < a.size() && std::isdigit(static_cast<unsigned char>(a[end_a]))) ++end_a;
      while (end_b < b.size() && std::isdigit(static_cast<unsigned char>(b[end_b]))) ++end_b;
      std::string digits_a = a.substr(i, end_a - i), digits_b = b.substr(j, end_b - j);
      digits_a.erase(0, std::min(digits_a.find_first_not_of('0'), digits_a.size()));
      digits_b.erase(0, std::min(digits_b.find_first_not_of('0'), digits_b.size()));
      if (digits_a.size() != digits_b.size()) return digits_a.size() < digits_b.size();
      if (digits_a != digits_b) return digits_a < digits_b;
      i = end_a;
      j = end_b;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j || (a.size() - i == b.size() - j && a < b);
}

}  // namespace

std::vector<std::string> findSceneDirectories(const std::vector<std::string>& arguments) {
  std::vector<std::string> scenes;
  for (const std::string& argument : arguments) {
    const fs::path path(argument);
    boost::system::error_code error;
    if (!fs::exists(path, error)) throw InputError(argument, "no such file or directory");
    if (isPcdFile(path)) {
      scenes.push_back(argument);
      continue;
    }
    if (!fs::is_directory(path, error))
      throw InputError(argument, "not a directory or .pcd file (expected a scene directory with labels.txt)");
    if (isLabelledScene(path)) {
      scenes.push_back(argument);
      continue;
    }
    std::vector<std::string> children;
    std::vector<std::string> pcd_files;
    for (fs::directory_iterator it(path, error), end; !error && it != end; it.increment(error)) {
      if (fs::is_directory(it->path()) && isLabelledScene(it->path()))
        children.push_back(it->path().string());
      else if (isPcdFile(it->path()))
        pcd_files.push_back(it->path().string());
    }
    if (error) throw InputError(argument, "cannot list directory: " + error.message());
    // A directory of frames labelled in their PCD (OSD), not a scene directory without labels.
    const bool scene_directory = fs::exists(path / "cloud.pcd", error) || fs::exists(path / "cloud.ply", error);
    if (children.empty() && !scene_directory) children = pcd_files;
    if (children.empty())
      throw InputError(argument, "no labels.txt here nor in any subdirectory, and no .pcd file (no labelled scene)");
    std::sort(children.begin(), children.end(), naturalLess);
    scenes.insert(scenes.end(), children.begin(), children.end());
  }
  return scenes;
}

std::vector<std::string> findDataSetScenes(const std::string& argument) {
  const fs::path path(argument);
  boost::system::error_code error;
  if (!fs::exists(path, error)) throw InputError(argument, "no such file or directory");
  if (!fs::is_directory(path, error) || isLabelledScene(path)) return {argument};
  for (const char* cloud : {"cloud.ply", "cloud.pcd"}) {
    if (fs::is_regular_file(path / cloud, error)) return {argument};
  }
  return findSceneDirectories({argument});
}

std::string findSegmentsFile(const std::string& directory, const std::string& scene_name) {
  const fs::path nested = fs::path(directory) / scene_name / "segments.json";
  const fs::path flat = fs::path(directory) / (scene_name + ".json");
  boost::system::error_code error;
  if (fs::is_regular_file(nested, error)) return nested.string();
  if (fs::is_regular_file(flat, error)) return flat.string();
  throw InputError(directory, "no segments for scene '" + scene_name + "' (looked for " +
                                  nested.string() + " and " + flat.string() + ")");
}

}  // namespace symmetry_segmentation
