// Regression tests for hostile or broken input files: each one once crashed, hung, allocated
// gigabytes or was silently accepted. Every file is tiny and written by the test itself.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cstring>
#include <functional>

#include <octomap/OcTree.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segmentation_output.h"
#include "symmetry_segmentation/segments_json.h"
#include "symmetry_segmentation/voxel_grid.h"
#include "test_clouds.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;
using test_support::writeTextFile;

namespace {

// The call must throw InputError naming `file` and containing `problem`, and do so quickly:
// the broken files here used to cost tens of seconds and hundreds of megabytes.
void expectInputError(const std::function<void()>& call, const std::string& file, const std::string& problem) {
  const auto start = std::chrono::steady_clock::now();
  try {
    call();
    ADD_FAILURE() << file << ": accepted, expected an error containing '" << problem << "'";
  } catch (const ss::InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0) << file;
}

void expectCloudError(const std::string& path, const std::string& problem) {
  expectInputError([&] { ss::Scene scene; ss::loadCloudFile(path, scene); }, path, problem);
}

ss::Scene loadCloud(const std::string& path) {
  ss::Scene scene;
  ss::loadCloudFile(path, scene);
  return scene;
}

std::string pcdHeader(const std::string& width, const std::string& height, const std::string& points,
                      const std::string& data, const std::string& fields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n") {
  return "# .PCD v0.7\nVERSION 0.7\n" + fields + "WIDTH " + width + "\nHEIGHT " + height +
         "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + points + "\nDATA " + data + "\n";
}

std::string plyHeader(const std::string& format, const std::string& vertices, const std::string& extra = "") {
  return "ply\nformat " + format + " 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\n" + extra + "end_header\n";
}

const std::string kBtMagic = "# Octomap OcTree binary file\n";
const std::string kOtMagic = "# Octomap OcTree file\n";

}  // namespace

// ---- Cloud headers --------------------------------------------------------------------------

TEST(InputHardening, PcdSizesThatOverflow32BitsAreRejected) {
  const std::string dir = test_support::makeTempDir("hardening_pcd_overflow");
  // 2^31 * 2^31 and 2^16 * 2^16 are both 0 in 32 bits: PCL took POINTS 0 at its word and crashed.
  writeTextFile(dir + "/huge.pcd", pcdHeader("2147483648", "2147483648", "0", "binary") + std::string(64, '\0'));
  expectCloudError(dir + "/huge.pcd", "differs from POINTS");
  writeTextFile(dir + "/wrap.pcd", pcdHeader("65536", "65536", "0", "binary") + std::string(64, '\0'));
  expectCloudError(dir + "/wrap.pcd", "differs from POINTS");
  writeTextFile(dir + "/too_wide.pcd", pcdHeader("4294967296", "1", "4294967296", "binary"));
  expectCloudError(dir + "/too_wide.pcd", "WIDTH '4294967296'");
  writeTextFile(dir + "/absurd.pcd", pcdHeader("300000000", "1", "300000000", "binary"));
  expectCloudError(dir + "/absurd.pcd", "more than 200000000");
}

TEST(InputHardening, PcdClaimingMorePointsThanItHoldsIsRejectedBeforeAllocating) {
  const std::string dir = test_support::makeTempDir("hardening_pcd_claims");
  writeTextFile(dir + "/binary.pcd", pcdHeader("60000000", "1", "60000000", "binary") + std::string(1000, '\1'));
  expectCloudError(dir + "/binary.pcd", "truncated binary PCD data");
  std::string ascii = pcdHeader("60000000", "1", "60000000", "ascii");
  for (int i = 0; i < 50; ++i) ascii += "0 0 1\n";
  writeTextFile(dir + "/ascii.pcd", ascii);
  expectCloudError(dir + "/ascii.pcd", "truncated ASCII PCD data");

  // binary_compressed: the size words must agree with the header and the file.
  auto compressed = [&](std::uint32_t compressed_size, std::uint32_t uncompressed_size) {
    std::string words(8, '\0');
    std::memcpy(&words[0], &compressed_size, 4);
    std::memcpy(&words[4], &uncompressed_size, 4);
    return pcdHeader("1000", "1", "1000", "binary_compressed") + words + std::string(100, '\0');
  };
  writeTextFile(dir + "/lying_uncompressed.pcd", compressed(100, 720000000));
  expectCloudError(dir + "/lying_uncompressed.pcd", "uncompressed size");
  writeTextFile(dir + "/lying_compressed.pcd", compressed(100000, 12000));
  expectCloudError(dir + "/lying_compressed.pcd", "truncated compressed PCD data");
  writeTextFile(dir + "/overexpanded.pcd", compressed(10, 12000));
  expectCloudError(dir + "/overexpanded.pcd", "cannot hold");
}

TEST(InputHardening, PcdFieldDescriptionsMustAgree) {
  const std::string dir = test_support::makeTempDir("hardening_pcd_fields");
  const std::pair<const char*, const char*> cases[] = {
      {"FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\nCOUNT 1 1 1\n", "TYPE 'F' with SIZE 2"},
      {"FIELDS x y z\nSIZE 4 4 3\nTYPE F F U\nCOUNT 1 1 1\n", "TYPE 'U' with SIZE 3"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\nCOUNT 1 1 1\n", "TYPE 'Q'"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 0\n", "COUNT 0"},
      {"FIELDS x y z\nSIZE 4 4\nTYPE F F F\nCOUNT 1 1 1\n", "SIZE has 2 entries for 3 FIELDS"},
      {"FIELDS x y z\nTYPE F F F\nCOUNT 1 1 1\n", "no SIZE line"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 20000\n", "more than 65536 bytes"},
  };
  for (const auto& [fields, problem] : cases) {
    writeTextFile(dir + "/fields.pcd", pcdHeader("1", "1", "1", "ascii", fields) + "0 0 1\n");
    expectCloudError(dir + "/fields.pcd", problem);
  }
  writeTextFile(dir + "/data.pcd", pcdHeader("1", "1", "1", "zipped") + "0 0 1\n");
  expectCloudError(dir + "/data.pcd", "unknown DATA type 'zipped'");
}

// Found by fuzzing (test/fuzz/corpus/pcd_file/crash_fields_twice.pcd): a second FIELDS line
// after SIZE / TYPE / COUNT made the checker read past the end of the SIZE list.
TEST(InputHardening, PcdHeaderLinesMustNotRepeat) {
  const std::string dir = test_support::makeTempDir("hardening_pcd_repeats");
  const std::string fields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::pair<std::string, const char*> cases[] = {
      {fields + "FIELDS x y z intensity\n", "FIELDS given twice"},
      {fields + "COLUMNS x y\n", "FIELDS given twice"},
      {fields + "SIZE 4 4 4\n", "SIZE given twice"},
      {fields + "COUNT 1 1 1\n", "COUNT given twice"},
  };
  for (const auto& [header_fields, problem] : cases) {
    writeTextFile(dir + "/repeat.pcd", pcdHeader("1", "1", "1", "ascii", header_fields) + "0 0 1\n");
    expectCloudError(dir + "/repeat.pcd", problem);
  }
  writeTextFile(dir + "/width.pcd", "VERSION 0.7\n" + fields + "WIDTH 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0 0 1\n");
  expectCloudError(dir + "/width.pcd", "WIDTH given twice");
  // Found by fuzzing (corpus/pcd_file/crash_blank_cr_line.pcd): PCL's reader dereferenced null
  // on a whitespace-only line at the top of the header.
  for (const char* blank : {"\r\n", " \n", "\n"}) {
    writeTextFile(dir + "/blank.pcd", blank + pcdHeader("1", "1", "1", "ascii", fields) + "0 0 1\n");
    expectCloudError(dir + "/blank.pcd", "line 1 is blank");
  }
  writeTextFile(dir + "/blank_cr.pcd",
                test_support::readTextFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/pcd_file/crash_blank_cr_line.pcd"));
  expectCloudError(dir + "/blank_cr.pcd", "is blank");
  // The fuzzer's input itself.
  const std::string found = test_support::readTextFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/pcd_file/crash_fields_twice.pcd");
  writeTextFile(dir + "/found.pcd", found);
  expectCloudError(dir + "/found.pcd", "FIELDS given twice");
  // The unrepeated header still loads.
  writeTextFile(dir + "/once.pcd", pcdHeader("1", "1", "1", "ascii", fields) + "0 0 1\n");
  EXPECT_EQ(loadCloud(dir + "/once.pcd").cloud->size(), 1u);
}

// Found by fuzzing (test/fuzz/corpus/pcd_file/crash_data_read_as_header*.pcd): PCL reads past
// DATA as header lines while they are empty, comments or keywords; binary data starting with
// "COLUMNS" emptied its field list and its reader then read past the end of that list.
TEST(InputHardening, PcdDataThatPclWouldReadAsHeaderIsRejected) {
  const std::string dir = test_support::makeTempDir("hardening_pcd_data_header");
  const std::string points(3 * 12, '\0');
  const std::pair<std::string, const char*> cases[] = {
      {"COLUMNS\n", "header keyword 'COLUMNS'"},
      {"WIDTH 1\n", "header keyword 'WIDTH'"},
      {"\n#x\nVERSION 3\n \tDATAxyz\n", "header keyword 'DATA'"},  // skipped lines, then a keyword
      {"POINTSy", "header keyword 'POINTS'"},                          // matched by prefix, like PCL
  };
  for (const auto& [start, problem] : cases) {
    writeTextFile(dir + "/keyword.pcd", pcdHeader("3", "1", "3", "binary") + start + points);
    expectCloudError(dir + "/keyword.pcd", problem);
  }
  for (const char* found : {"crash_data_read_as_header.pcd", "crash_data_read_as_header_2.pcd"}) {
    writeTextFile(dir + "/found.pcd",
                  test_support::readTextFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/pcd_file/" + found));
    expectCloudError(dir + "/found.pcd", "header keyword 'COLUMNS'");
  }
  // Data that only looks like a comment, or starts with a word PCL does not know, still loads.
  for (const std::string start : {"#abc\n", "VERSION\nabc", "COLUMN"}) {
    std::string data = start + points;
    data.resize(points.size());
    writeTextFile(dir + "/fine.pcd", pcdHeader("3", "1", "3", "binary") + data);
    EXPECT_EQ(loadCloud(dir + "/fine.pcd").cloud->size(), 3u) << start;
  }
}

// Found by fuzzing (test/fuzz/corpus/ply_file/crash_vertex_list.ply): PCL sizes a per-vertex
// list by the first vertex and aborts on an assertion when a later list is longer.
TEST(InputHardening, PlyVertexListsAreRejected) {
  const std::string dir = test_support::makeTempDir("hardening_ply_vertex_list");
  const std::string lists = "property list uchar int view_indices\n";
  writeTextFile(dir + "/lists.ply", plyHeader("ascii", "2", lists) + "0 0 1 1 7\n1 0 1 3 7 8 9\n");
  expectCloudError(dir + "/lists.ply", "vertex property 'view_indices' is a list");
  writeTextFile(dir + "/found.ply",
                test_support::readTextFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/ply_file/crash_vertex_list.ply"));
  expectCloudError(dir + "/found.ply", "is a list");
  // Lists on other elements (faces) are fine: the cloud is the vertices.
  writeTextFile(dir + "/faces.ply", plyHeader("ascii", "3", "element face 1\nproperty list uchar int vertex_indices\n") +
                                        "0 0 1\n1 0 1\n0 1 1\n3 0 1 2\n");
  EXPECT_EQ(loadCloud(dir + "/faces.ply").cloud->size(), 3u);
}

// Found by fuzzing (test/fuzz/corpus/ply_file/crash_indented_obj_info.ply): PCL hands an obj_info
// line to a callback that asserts the line starts with "obj_info"; a form feed (or a space)
// before it aborted the process.
TEST(InputHardening, IndentedPlyHeaderLinesAreRejected) {
  const std::string dir = test_support::makeTempDir("hardening_ply_indented");
  for (const char* indent : {"\f", " ", "\t"}) {
    writeTextFile(dir + "/indented.ply", plyHeader("ascii", "1", std::string(indent) + "obj_info scanner\n") + "0 0 1\n");
    expectCloudError(dir + "/indented.ply", "starts with white space");
  }
  writeTextFile(dir + "/found.ply",
                test_support::readTextFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/ply_file/crash_indented_obj_info.ply"));
  expectCloudError(dir + "/found.ply", "starts with white space");
  writeTextFile(dir + "/plain.ply", plyHeader("ascii", "1", "obj_info scanner\ncomment  two  spaces\n") + "0 0 1\n");
  EXPECT_EQ(loadCloud(dir + "/plain.ply").cloud->size(), 1u);
}

// Found by fuzzing (test/fuzz/corpus/ply_file/crash_lone_blue.ply): PCL packs 8-bit colours
// into one rgb field that only "red" creates; a vertex with "blue" but no "red" made Debian's PCL
// abort on an assertion (the whole process, not just the load).
TEST(InputHardening, PlyVertexColourMustBeRedGreenBlue) {
  const std::string dir = test_support::makeTempDir("hardening_ply_colour");
  const char* const problem = "8-bit vertex colour must be the properties red, green, blue";
  const std::pair<const char*, const char*> cases[] = {
      {"property uchar blue\n", "7"},
      {"property uchar green\nproperty uchar blue\n", "7 8"},
      {"property uchar red\nproperty uchar green\n", "7 8"},
      {"property uchar blue\nproperty uchar green\nproperty uchar red\n", "7 8 9"},
      {"property uchar red\nproperty float intensity\nproperty uchar green\nproperty uchar blue\n", "7 0.5 8 9"},
      {"property uchar alpha\n", "7"},
      {"property uchar red\nproperty uchar green\nproperty uchar diffuse_blue\n", "7 8 9"},
  };
  for (const auto& [properties, values] : cases) {
    writeTextFile(dir + "/colour.ply", plyHeader("ascii", "1", properties) + "0 0 1 " + values + "\n");
    expectCloudError(dir + "/colour.ply", problem);
  }
  const std::string found = test_support::readTextFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/ply_file/crash_lone_blue.ply");
  writeTextFile(dir + "/found.ply", found);
  expectCloudError(dir + "/found.ply", problem);
  // What PCL and other writers save still loads, with its colour.
  writeTextFile(dir + "/rgb.ply", plyHeader("ascii", "1", "property uchar red\nproperty uchar green\nproperty uchar blue\n") +
                                      "0 0 1 10 20 30\n");
  const ss::Scene rgb = loadCloud(dir + "/rgb.ply");
  EXPECT_TRUE(rgb.has_color);
  EXPECT_EQ(rgb.cloud->points[0].r, 10);
  EXPECT_EQ(rgb.cloud->points[0].b, 30);
  writeTextFile(dir + "/rgba.ply", plyHeader("ascii", "1", "property uchar diffuse_red\nproperty uchar diffuse_green\n"
                                                           "property uchar diffuse_blue\nproperty uchar alpha\n") +
                                       "0 0 1 10 20 30 255\n");
  EXPECT_EQ(loadCloud(dir + "/rgba.ply").cloud->points[0].g, 20);
}

TEST(InputHardening, PlyClaimingMoreVerticesThanItHoldsIsRejectedBeforeAllocating) {
  const std::string dir = test_support::makeTempDir("hardening_ply_claims");
  writeTextFile(dir + "/binary.ply", plyHeader("binary_little_endian", "60000000") + std::string(1000, '\1'));
  expectCloudError(dir + "/binary.ply", "truncated binary PLY data");
  std::string ascii = plyHeader("ascii", "60000000");
  for (int i = 0; i < 50; ++i) ascii += "0 0 1\n";
  writeTextFile(dir + "/ascii.ply", ascii);
  expectCloudError(dir + "/ascii.ply", "truncated ASCII PLY data");
  // Other elements count too: PCL reserves memory for every face.
  writeTextFile(dir + "/faces.ply", plyHeader("binary_little_endian", "1",
                                              "element face 100000000\nproperty list uchar int vertex_indices\n") +
                                        std::string(12, '\0'));
  expectCloudError(dir + "/faces.ply", "truncated binary PLY data");
  writeTextFile(dir + "/absurd.ply", plyHeader("binary_little_endian", "4000000000") + std::string(12, '\0'));
  expectCloudError(dir + "/absurd.ply", "more than 200000000");
  writeTextFile(dir + "/type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                   "property quad z\nend_header\n0 0 1\n");
  expectCloudError(dir + "/type.ply", "unknown property type 'quad'");
  writeTextFile(dir + "/format.ply", plyHeader("binary_middle_endian", "1") + std::string(12, '\0'));
  expectCloudError(dir + "/format.ply", "unknown format");
}

TEST(InputHardening, NonNumericAsciiValuesAreErrors) {
  const std::string dir = test_support::makeTempDir("hardening_ascii_tokens");
  writeTextFile(dir + "/word.pcd", pcdHeader("2", "1", "2", "ascii") + "0 0 1\n0 abc 1\n");
  expectCloudError(dir + "/word.pcd", "line 13: 'abc' is not a number");
  writeTextFile(dir + "/suffix.ply", plyHeader("ascii", "2") + "0 0 1\n0 0 1x\n");
  expectCloudError(dir + "/suffix.ply", "line 9: '1x' is not a number");
  // nan is how PCL writes missing points: still accepted.
  writeTextFile(dir + "/nan.pcd", pcdHeader("2", "1", "2", "ascii") + "nan nan nan\n0 0 1e-1\n");
  EXPECT_EQ(loadCloud(dir + "/nan.pcd").size(), 2u);
}

TEST(InputHardening, CloudsWithoutPointsWithin100KmAreRejected) {
  const std::string dir = test_support::makeTempDir("hardening_far_points");
  writeTextFile(dir + "/far.pcd", pcdHeader("2", "1", "2", "ascii") + "1e30 0 1\n0 2e5 0\n");
  expectCloudError(dir + "/far.pcd", "no finite points within 100 km");
  writeTextFile(dir + "/mixed.pcd", pcdHeader("2", "1", "2", "ascii") + "1e30 0 1\n0 0 1\n");
  EXPECT_EQ(loadCloud(dir + "/mixed.pcd").size(), 2u);
}

TEST(InputHardening, ValidFilesOfEveryEncodingStillLoad) {
  const std::string dir = test_support::makeTempDir("hardening_valid_clouds");
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {0, 0, 0}, {0.05f, 0.05f, 0.05f}, 0.01f);
  ASSERT_EQ(pcl::io::savePCDFileASCII(dir + "/ascii.pcd", cloud), 0);
  ASSERT_EQ(pcl::io::savePCDFileBinary(dir + "/binary.pcd", cloud), 0);
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(dir + "/compressed.pcd", cloud), 0);
  ASSERT_EQ(pcl::io::savePLYFileASCII(dir + "/ascii.ply", cloud), 0);
  ASSERT_EQ(pcl::io::savePLYFileBinary(dir + "/binary.ply", cloud), 0);
  for (const char* name : {"ascii.pcd", "binary.pcd", "compressed.pcd", "ascii.ply", "binary.ply"}) {
    const ss::Scene scene = loadCloud(dir + "/" + name);
    ASSERT_EQ(scene.size(), cloud.size()) << name;
    EXPECT_NEAR(scene.cloud->points[7].z, cloud.points[7].z, 1e-6f) << name;
    EXPECT_TRUE(scene.has_normals) << name;
  }
}

TEST(InputHardening, PlyCameraAtTheDefaultPoseIsNoSensorOrigin) {
  const std::string dir = test_support::makeTempDir("hardening_ply_camera");
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {0, 0, 0}, {0.05f, 0.05f, 0.05f}, 0.01f);
  // PCL writes a camera element into every PLY, even for a cloud that never had a viewpoint
  // (and PCL 1.13's reader hands back the default pose whatever the element says).
  ASSERT_EQ(pcl::io::savePLYFileBinary(dir + "/default.ply", cloud), 0);
  ASSERT_NE(test_support::readTextFile(dir + "/default.ply").find("element camera"), std::string::npos);
  EXPECT_TRUE(loadCloud(dir + "/default.ply").sensor_origins.empty());
}

// ---- OctoMap ----------------------------------------------------------------------------------

TEST(InputHardening, OctomapGarbageIsRejectedQuickly) {
  const std::string dir = test_support::makeTempDir("hardening_octomap");
  // OctoMap's readers follow garbage child bits past the end of the data: 100 KB of 0xff cost
  // 20 s and 720 MB, 1 KB of junk in a .bt was accepted.
  writeTextFile(dir + "/ff.ot", kOtMagic + "id OcTree\nsize 20000\nres 0.01\ndata\n" + std::string(100000, '\xff'));
  expectInputError([&] { ss::loadOctomapFile(dir + "/ff.ot"); }, dir + "/ff.ot", "OctoMap data");
  writeTextFile(dir + "/junk.bt", kBtMagic + "id OcTree\nsize 100\nres 0.01\ndata\n" + std::string(1000, '\x5a'));
  expectInputError([&] { ss::loadOctomapFile(dir + "/junk.bt"); }, dir + "/junk.bt", "OctoMap data");
  writeTextFile(dir + "/deep.bt", kBtMagic + "id OcTree\nsize 100\nres 0.01\ndata\n" + std::string(1000, '\xff'));
  expectInputError([&] { ss::loadOctomapFile(dir + "/deep.bt"); }, dir + "/deep.bt", "OctoMap data");
  writeTextFile(dir + "/huge_size.bt", kBtMagic + "id OcTree\nsize 99999999999\nres 0.01\ndata\n" + std::string(4, '\0'));
  expectInputError([&] { ss::loadOctomapFile(dir + "/huge_size.bt"); }, dir + "/huge_size.bt", "hold at most");
}

TEST(InputHardening, OctomapHeaderAndNodeCountMustMatchTheData) {
  const std::string dir = test_support::makeTempDir("hardening_octomap_counts");
  octomap::OcTree tree(0.05);
  for (int i = 0; i < 50; ++i) tree.updateNode(octomap::point3d(0.05f * i, 0.0f, 0.3f), i % 2 == 0);
  ASSERT_TRUE(tree.writeBinaryConst(dir + "/map.bt"));
  ASSERT_TRUE(tree.write(dir + "/map.ot"));
  for (const std::string ext : {".bt", ".ot"}) {
    const std::string whole = test_support::readTextFile(dir + "/map" + ext);
    EXPECT_EQ(ss::loadOctomapFile(dir + "/map" + ext)->size(), tree.size()) << ext;
    writeTextFile(dir + "/trailing" + ext, whole + "extra bytes");
    expectInputError([&] { ss::loadOctomapFile(dir + "/trailing" + ext); }, dir + "/trailing" + ext, "after the tree");
    std::string wrong_size = whole;
    const std::string size_line = "size " + std::to_string(tree.size()) + "\n";
    wrong_size.replace(wrong_size.find(size_line), size_line.size(), "size " + std::to_string(tree.size() - 1) + "\n");
    writeTextFile(dir + "/wrong_size" + ext, wrong_size);
    expectInputError([&] { ss::loadOctomapFile(dir + "/wrong_size" + ext); }, dir + "/wrong_size" + ext, "nodes");
  }
  writeTextFile(dir + "/color.ot", kOtMagic + "id ColorOcTree\nsize 1\nres 0.01\ndata\n" + std::string(8, '\0'));
  expectInputError([&] { ss::loadOctomapFile(dir + "/color.ot"); }, dir + "/color.ot", "unsupported OctoMap tree type");
  for (const char* res : {"100", "0.00001", "nan", "0.01abc"}) {
    writeTextFile(dir + "/res.ot", kOtMagic + "id OcTree\nsize 0\nres " + res + "\ndata\n");
    expectInputError([&] { ss::loadOctomapFile(dir + "/res.ot"); }, dir + "/res.ot", "resolution");
  }
  writeTextFile(dir + "/empty.ot", kOtMagic + "id OcTree\nsize 0\nres 0.02\ndata\n");
  EXPECT_EQ(ss::loadOctomapFile(dir + "/empty.ot")->size(), 0u);
}

// ---- Side files --------------------------------------------------------------------------------

TEST(InputHardening, PlaneIsNormalisedInDouble) {
  const std::string dir = test_support::makeTempDir("hardening_plane");
  // In float, 1e300 becomes inf and the "normalised" plane came out as all zeros.
  writeTextFile(dir + "/big.txt", "0 0 1e300 -2e300\n");
  const auto plane = ss::loadPlaneFile(dir + "/big.txt");
  EXPECT_FLOAT_EQ(plane[2], 1.0f);
  EXPECT_FLOAT_EQ(plane[3], -2.0f);
  writeTextFile(dir + "/tiny.txt", "0 1e-20 0 1e-20\n");
  EXPECT_FLOAT_EQ(ss::loadPlaneFile(dir + "/tiny.txt")[3], 1.0f);
  writeTextFile(dir + "/far.txt", "0 0 1e-30 1\n");
  expectInputError([&] { ss::loadPlaneFile(dir + "/far.txt"); }, dir + "/far.txt", "farther than 100 km");
  writeTextFile(dir + "/zero.txt", "0 0 0 1\n");
  expectInputError([&] { ss::loadPlaneFile(dir + "/zero.txt"); }, dir + "/zero.txt", "plane normal (a, b, c) is zero");
}

TEST(InputHardening, SceneInfoIsValidated) {
  const std::string dir = test_support::makeTempDir("hardening_scene_info");
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  test_clouds::addBox(*scene.cloud, {0, 0, 0}, {0.05f, 0.05f, 0.05f}, 0.01f);
  ss::saveScene(scene, dir + "/scene");  // no origins: the file must not hold an empty list
  EXPECT_TRUE(ss::loadScene(dir + "/scene").sensor_origins.empty());
  const std::pair<const char*, const char*> cases[] = {
      {"- 1\n- 2\n", "expected a map"},
      {"sensor_origins: 5\n", "non-empty list"},
      {"sensor_origins: []\n", "non-empty list"},
      {"sensor_origins: [[1, 2, 3], {a: 1}]\n", "3 numbers"},
      {"sensor_origins: [[1, 2, .nan]]\n", "finite"},
      {"sensor_origins: [[1, 2, [3]]]\n", "3 numbers"},
      {"kind: [a, b]\n", "'kind'"},
      {"kind: overall\n", "reserved for the total"},
      {"kind: \"two words\"\n", "single word"},
      {"kind: \"\"\n", "single word"},
  };
  const std::string info = dir + "/scene/scene_info.yaml";
  for (const auto& [content, problem] : cases) {
    writeTextFile(info, content);
    expectInputError([&] { ss::loadScene(dir + "/scene"); }, info, problem);
  }
  writeTextFile(info, "kind: my_scenes-2\n");
  EXPECT_EQ(ss::loadScene(dir + "/scene").kind, "my_scenes-2");
}

// ---- segments.json -----------------------------------------------------------------------------

TEST(InputHardening, SegmentsJsonValuesMustHaveExactTypes) {
  const std::string dir = test_support::makeTempDir("hardening_segments_json");
  const std::string path = dir + "/s.json";
  const std::pair<const char*, const char*> cases[] = {
      {R"({"input_points": 3.5, "segments": []})", "'input_points' must be a non-negative integer"},
      {R"({"input_points": -3, "segments": []})", "'input_points' must be a non-negative integer"},
      {R"({"input_points": 3, "segments": {}})", "'segments' must be an array"},
      {R"({"input_points": 3, "segments": [{"indices": [1.5]}]})", "segment index must be"},
      {R"({"input_points": 3, "segments": [{"indices": [4294967296]}]})", "outside [0, input_points)"},
      {R"({"input_points": 3, "segments": [{"indices": [-1]}]})", "segment index must be"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "symmetry": {"normal": [1, 0, 1e300], "distance": 0}}]})",
       "symmetry normal must be finite"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "symmetry": {"normal": [1, 0, "x"], "distance": 0}}]})",
       "symmetry normal must be a number"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "scores": {"occlusion": 1e300, "smoothness": 0}}]})",
       "occlusion score must be finite"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "box": {"center": [0, 0, 0], "size": [1, 1, 1]}}]})",
       "'box' lacks 'axes'"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "box": {"center": [0, 0, 0], "size": [1, 1, 1],
          "axes": [[1, 0, 0], [0, 2, 0], [0, 0, 1]]}}]})", "box axes must be unit, orthogonal and right-handed"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "box": {"center": [0, 0, 0], "size": [1, 1, 1],
          "axes": [[1, 0, 0], [1, 0, 0], [0, 0, 1]]}}]})", "box axes must be unit, orthogonal and right-handed"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "box": {"center": [0, 0, 0], "size": [1, 1, 1],
          "axes": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}}]})", "box axes must be unit, orthogonal and right-handed"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "box": {"center": [0, 0, 0], "size": [1, -1, 1],
          "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}}]})", "box size must not be negative"},
      {R"({"input_points": 3, "segments": [{"indices": [1], "box": {"center": [0, 1e300, 0], "size": [1, 1, 1],
          "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}}]})", "box center must be finite"},
      {R"({"input_points": 3, "segments": [], "timing_ms": [1, 2]})", "'timing_ms' must be an object"},
      {R"({"input_points": 3, "segments": [], "timing_ms": {"total": "fast"}})", "timing 'total'"},
      {R"({"input_points": 3, "segments": [], "counts": {"hypotheses": -1}})", "count 'hypotheses'"},
      {R"({"input_points": 3, "segments": [], "counts": {"hypotheses": 2.5}})", "count 'hypotheses'"},
  };
  for (const auto& [content, problem] : cases) {
    writeTextFile(path, content);
    expectInputError([&] { ss::readSegmentsJson(path); }, path, problem);
  }
  writeTextFile(path, R"({"input_points": 3, "segments": [{"indices": [0, 2]}], "timing_ms": {"total": 1},
                          "counts": {"hypotheses": 4}})");
  const auto result = ss::readSegmentsJson(path);
  EXPECT_EQ(result.segments.at(0).indices, (std::vector<int>{0, 2}));
  EXPECT_EQ(result.counts.at(0).second, 4u);
}

// ---- Configuration -----------------------------------------------------------------------------

TEST(InputHardening, ConfigurationCyclesAndOddKeysAreErrors) {
  const std::string dir = test_support::makeTempDir("hardening_config");
  const std::pair<const char*, const char*> cases[] = {
      {"symmetry: &a {filter: *a}\n", "nested deeper than 4 levels"},
      {"? [a]\n: {x: 1}\n", "keys must be plain names"},
      {"lccp: {? [a] : 1}\n", "keys must be plain names"},
      {"lccp: {concavity_tolerance: &b [*b]}\n", "invalid value (a list)"},
  };
  for (const auto& [content, problem] : cases) {
    writeTextFile(dir + "/c.yaml", content);
    expectInputError([&] { ss::loadConfigFile(dir + "/c.yaml"); }, dir + "/c.yaml", problem);
  }
}

TEST(InputHardening, ConfigurationValuesMustBeInRange) {
  const std::pair<const char*, const char*> cases[] = {
      {"preprocessing.voxel_size", "5"},          {"preprocessing.voxel_size", ".nan"},
      {"preprocessing.voxel_size", "0.0001"},     {"preprocessing.table_margin", "-1"},
      {"preprocessing.table_margin", ".inf"},     {"preprocessing.ransac_iterations", "0"},
      {"preprocessing.max_range", "-2"},          {"euclidean.min_cluster_size", "0"},
      {"euclidean.max_cluster_size", "10"},       {"euclidean.cluster_tolerance", ".inf"},
      {"lccp.concavity_tolerance", "-5"},         {"lccp.normal_importance", ".nan"},
      {"symmetry.filter.s_occl", "1.5"},          {"symmetry.filter.s_smooth", "-0.1"},
      {"symmetry.dedup.max_overlap", "2"},       {"symmetry.filter.min_segment_points", "0"},
      {"symmetry.curve_pairs.max_hypotheses", "0"}, {"symmetry.curve_pairs.max_tangent_angle_deg", "0"},
      {"symmetry.curves.merge_normal_angle_deg", "200"}, {"symmetry.refine.icp_iterations", "-1"},
      {"symmetry.curves.boundary_radius", "0"}, {"symmetry.cut.lambda_sym", ".nan"},
      {"symmetry.stages", "[curves, cut, filter]"}, {"symmetry.stages", "[curve_pairs, cut, filter]"},
  };
  for (const auto& [key, value] : cases) {
    ss::SegmentationConfig config;
    try {
      ss::setConfigValue(config, key, value);
      ADD_FAILURE() << key << " = " << value << " accepted";
    } catch (const ss::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  ss::SegmentationConfig config;
  ss::setConfigValue(config, "symmetry.refine.icp_iterations", "0");  // no refinement is fine
  ss::setConfigValue(config, "preprocessing.table_margin", "0");
  EXPECT_EQ(config.symmetry.refine.icp_iterations, 0);
}

// ---- Pipeline guards ---------------------------------------------------------------------------

TEST(InputHardening, VoxelGridSkipsPointsBeyond100Km) {
  ss::Cloud cloud;
  ss::PointT near, far, nan;
  near.x = near.y = near.z = 0.001f;
  far.x = 1e30f;  // floor(1e30 / leaf) does not fit in int64: undefined behaviour before
  far.y = far.z = 0.0f;
  nan.x = nan.y = nan.z = std::numeric_limits<float>::quiet_NaN();
  cloud.push_back(near);
  cloud.push_back(far);
  cloud.push_back(nan);
  const auto grid = ss::voxelDownsample(cloud, {0, 1, 2}, 0.01f, false);
  ASSERT_EQ(grid.members.size(), 1u);
  EXPECT_EQ(grid.members[0], (std::vector<int>{0}));
}

TEST(InputHardening, UnwritablePngIsAnError) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  pcl::PointXYZRGB point;
  point.x = point.y = 0.0f;
  point.z = 1.0f;
  cloud.push_back(point);
  const ss::View view{Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitZ(), -Eigen::Vector3f::UnitY()};
  const std::string path = test_support::makeTempDir("hardening_png") + "/missing_dir/picture.png";
  expectInputError([&] { ss::renderPng(cloud, view, path, {}, 32, 24); }, path, "cannot write PNG");
}
