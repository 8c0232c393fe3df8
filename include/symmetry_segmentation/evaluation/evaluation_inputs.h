#pragma once
// Locating evaluation inputs on disk: labelled scene directories and stored segments.json files.

#include <string>
#include <vector>

namespace symmetry_segmentation {

/// Each argument is a scene directory (one holding labels.txt), a .pcd file (labelled in its own
/// "label" field, as OSD frames are), or a parent directory whose subdirectories holding
/// labels.txt are scenes, else whose .pcd files are (sorted by name, digit runs by value:
/// learn2 before learn10). Throws InputError naming the argument when it does not exist or
/// yields no scene.
std::vector<std::string> findSceneDirectories(const std::vector<std::string>& arguments);

/// The scenes of one data set: the argument itself when it is a scene (a cloud file, or a
/// directory holding labels.txt or a cloud file), else as findSceneDirectories finds them in
/// it. Throws InputError naming the argument when there is none.
std::vector<std::string> findDataSetScenes(const std::string& argument);

/// `directory`/<scene>/segments.json, else `directory`/<scene>.json. Throws InputError when
/// neither exists.
std::string findSegmentsFile(const std::string& directory, const std::string& scene_name);

}  // namespace symmetry_segmentation
