#include "symmetry_segmentation/evaluation/evaluation_inputs.h"

#include <algorithm>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/errors.h"

namespace fs = boost::filesystem;

namespace symmetry_segmentation {

namespace {

bool isLabelledScene(const fs::path& directory) {
  boost::system::error_code error;
  return fs::is_regular_file(directory / "labels.txt", error);
}

}  // namespace

std::vector<std::string> findSceneDirectories(const std::vector<std::string>& arguments) {
  std::vector<std::string> scenes;
  for (const std::string& argument : arguments) {
    const fs::path path(argument);
    boost::system::error_code error;
    if (!fs::exists(path, error)) throw InputError(argument, "no such file or directory");
    if (!fs::is_directory(path, error))
      throw InputError(argument, "not a directory (expected a scene directory with labels.txt)");
    if (isLabelledScene(path)) {
      scenes.push_back(argument);
      continue;
    }
    std::vector<std::string> children;
    for (fs::directory_iterator it(path, error), end; !error && it != end; it.increment(error)) {
      if (fs::is_directory(it->path()) && isLabelledScene(it->path()))
        children.push_back(it->path().string());
    }
    if (error) throw InputError(argument, "cannot list directory: " + error.message());
    if (children.empty())
      throw InputError(argument, "no labels.txt here nor in any subdirectory (no labelled scene)");
    std::sort(children.begin(), children.end());
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
