// Header and data-size checks for PCD / PLY clouds, run before PCL sees the file.
#include "symmetry_segmentation/cloud_header_check.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace {

// Real headers are a few hundred bytes; a megabyte without the end line is not a header.
constexpr std::uint64_t kMaxHeaderBytes = 1 << 20;
// Records larger than this are no point clouds (and PCL keeps the record size in 32 bits).
constexpr std::uint64_t kMaxPointBytes = 1 << 16;
// An LZF block spends at least 3 bytes on at most 264 output bytes: it never expands > 88x.
constexpr std::uint64_t kMaxLzfExpansion = 88;
// An ASCII value takes at least one character and one separator.
constexpr std::uint64_t kMinAsciiValueBytes = 2;
constexpr std::uint64_t kMaxUint32 = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kMaxUint64 = std::numeric_limits<std::uint64_t>::max();

using Words = std::vector<std::string>;

// Saturating arithmetic: a product or sum that would wrap becomes "too large" instead.
std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > kMaxUint64 / a) return kMaxUint64;
  return a * b;
}

std::uint64_t saturatingSum(std::uint64_t a, std::uint64_t b) { return a > kMaxUint64 - b ? kMaxUint64 : a + b; }

Words splitWords(const std::string& line) {
  std::istringstream in(line);
  Words words;
  std::string word;
  while (in >> word) words.push_back(word);
  return words;
}

// Decimal digits only (no sign, exponent or trailing text), at most `max`.
bool parseUnsigned(const std::string& text, std::uint64_t max, std::uint64_t& value) {
  if (text.empty() || text.size() > 19) return false;  // 19 digits cannot overflow 64 bits
  value = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return value <= max;
}

std::uint64_t headerInteger(const std::string& path, const std::string& format, const std::string& what,
                            const std::string& text, std::uint64_t max) {
  std::uint64_t value = 0;
  if (!parseUnsigned(text, max, value)) {
    throw InputError(path, format + " header: " + what + " '" + text + "' is not an integer in [0, " +
                               std::to_string(max) + "]");
  }
  return value;
}

std::string shortened(const std::string& text) { return text.size() <= 40 ? text : text.substr(0, 40) + "..."; }

std::uint64_t fileSize(const std::string& path) {
  boost::system::error_code ec;
  const std::uint64_t size = boost::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "cannot determine the file size");
  return size;
}

struct HeaderText {
  Words lines;                    ///< Without line terminators.
  bool complete = false;          ///< The end line was found.
  std::uint64_t data_offset = 0;  ///< First byte after the end line.
  std::uint64_t file_size = 0;
};

// Splits the start of the file into lines up to and including the first line whose first word
// is `end_word`, reading at most kMaxHeaderBytes.
HeaderText readHeaderText(const std::string& path, const std::string& end_word) {
  HeaderText header;
  header.file_size = fileSize(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open file for reading");
  std::string prefix(static_cast<std::size_t>(std::min(header.file_size, kMaxHeaderBytes)), '\0');
  in.read(&prefix[0], static_cast<std::streamsize>(prefix.size()));
  prefix.resize(static_cast<std::size_t>(in.gcount()));
  const bool whole_file = prefix.size() == header.file_size;
  std::size_t begin = 0;
  while (begin < prefix.size()) {
    std::size_t end = prefix.find('\n', begin);
    if (end == std::string::npos) {
      if (!whole_file) break;  // the line goes on past what was read: not a header line
      end = prefix.size();
    }
    std::string line = prefix.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    header.lines.push_back(line);
    begin = end + 1;
    const Words words = splitWords(line);
    if (!words.empty() && words[0] == end_word) {
      header.complete = true;
      header.data_offset = std::min<std::uint64_t>(begin, header.file_size);
      break;
    }
  }
  return header;
}

std::string readFrom(const std::string& path, std::uint64_t offset) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  std::ostringstream data;
  data << in.rdbuf();
  if (in.bad()) throw InputError(path, "cannot read file");
  return data.str();
}

// PCL turns an unparsable ASCII value into NaN or 0 without a word: a typo must be an error.
// Accepts what strtod accepts whole (numbers, nan, inf).
void checkAsciiValues(const std::string& path, const std::string& format, std::uint64_t data_offset,
                      std::size_t first_line) {
  const std::string data = readFrom(path, data_offset);
  const char* cursor = data.c_str();
  const char* const end = cursor + data.size();
  std::size_t line = first_line;
  while (cursor < end) {
    if (std::isspace(static_cast<unsigned char>(*cursor))) {
      if (*cursor == '\n') ++line;
      ++cursor;
      continue;
    }
    const char* token_end = cursor;
    while (token_end < end && !std::isspace(static_cast<unsigned char>(*token_end))) ++token_end;
    char* parsed_end = nullptr;
    std::strtod(cursor, &parsed_end);
    if (parsed_end != token_end) {
      throw InputError(path, "corrupt ASCII " + format + " data: line " + std::to_string(line) + ": '" +
                                 shortened(std::string(cursor, token_end)) + "' is not a number");
    }
    cursor = token_end;
  }
}

// ---- PCD ------------------------------------------------------------------------------------

struct PcdHeader {
  Words fields, sizes, types, counts;
  std::optional<std::uint64_t> width, height, points;
  std::string data_type;
};

void requireValueCount(const std::string& path, const PcdHeader& header, const Words& words) {
  if (header.fields.empty()) throw InputError(path, "PCD header: " + words[0] + " before FIELDS");
  if (words.size() - 1 != header.fields.size()) {
    throw InputError(path, "PCD header: " + words[0] + " has " + std::to_string(words.size() - 1) +
                               " entries for " + std::to_string(header.fields.size()) + " FIELDS");
  }
}

std::uint64_t singlePcdInteger(const std::string& path, const Words& words) {
  if (words.size() != 2) throw InputError(path, "PCD header: " + words[0] + " needs exactly one value");
  return headerInteger(path, "PCD", words[0], words[1], kMaxUint32);  // PCL stores them in 32 bits
}

PcdHeader parsePcdHeader(const std::string& path, const HeaderText& text) {
  PcdHeader header;
  std::set<std::string> seen;
  for (std::size_t number = 0; number < text.lines.size(); ++number) {
    const std::string& line = text.lines[number];
    const Words words = splitWords(line);
    // PCL's reader crashes (null read) on a whitespace-only line such as " " or "\r" at the top
    // (found by fuzzing); no writer puts blank lines into a header, so none may be there.
    if (words.empty()) throw InputError(path, "PCD header: line " + std::to_string(number + 1) + " is blank");
    if (words[0][0] == '#') continue;
    const std::string& key = words[0];
    if (key == "VERSION" || key == "VIEWPOINT") continue;  // PCL parses these; nothing to size
    // A second FIELDS line after SIZE / TYPE / COUNT would leave those lists a different length
    // (found by fuzzing: read past their end); no writer repeats a line, so none may repeat.
    const std::string line_kind = key == "COLUMNS" ? "FIELDS" : key;  // PCL's old name for FIELDS
    if (!seen.insert(line_kind).second) throw InputError(path, "PCD header: " + shortened(line_kind) + " given twice");
    if (key == "FIELDS" || key == "COLUMNS") {
      if (words.size() < 2) throw InputError(path, "PCD header: FIELDS is empty");
      header.fields.assign(words.begin() + 1, words.end());
    } else if (key == "SIZE") {
      requireValueCount(path, header, words);
      header.sizes.assign(words.begin() + 1, words.end());
    } else if (key == "TYPE") {
      requireValueCount(path, header, words);
      header.types.assign(words.begin() + 1, words.end());
    } else if (key == "COUNT") {
      requireValueCount(path, header, words);
      header.counts.assign(words.begin() + 1, words.end());
    } else if (key == "WIDTH") {
      header.width = singlePcdInteger(path, words);
    } else if (key == "HEIGHT") {
      header.height = singlePcdInteger(path, words);
    } else if (key == "POINTS") {
      header.points = singlePcdInteger(path, words);
    } else if (key == "DATA") {
      if (words.size() != 2) throw InputError(path, "PCD header: DATA needs exactly one value");
      header.data_type = words[1];
    } else {
      throw InputError(path, "not a valid PCD header: unexpected line '" + shortened(line) + "'");
    }
  }
  if (!text.complete) throw InputError(path, "not a valid PCD file (header has no DATA line)");
  return header;
}

// The type letters PCL knows and the sizes it reads for each.
bool isValidPcdType(const std::string& type, std::uint64_t size) {
  if (type.size() != 1) return false;
  switch (std::toupper(static_cast<unsigned char>(type[0]))) {
    case 'F': return size == 4 || size == 8;
    case 'I':
    case 'U': return size == 1 || size == 2 || size == 4 || size == 8;
    default: return false;
  }
}

struct PcdRecord {
  std::uint64_t bytes = 0;   ///< point_step: bytes per point in binary data.
  std::uint64_t values = 0;  ///< Numbers per point in ASCII data.
};

PcdRecord pcdRecord(const std::string& path, const PcdHeader& header) {
  if (header.fields.empty()) throw InputError(path, "PCD header has no FIELDS line");
  if (header.sizes.empty()) throw InputError(path, "PCD header has no SIZE line");
  if (header.types.empty()) throw InputError(path, "PCD header has no TYPE line");
  if (header.sizes.size() != header.fields.size() || header.types.size() != header.fields.size() ||
      (!header.counts.empty() && header.counts.size() != header.fields.size())) {
    throw InputError(path, "PCD header: SIZE, TYPE and COUNT must have one entry per field");
  }
  PcdRecord record;
  for (std::size_t i = 0; i < header.fields.size(); ++i) {
    const std::uint64_t size = headerInteger(path, "PCD", "SIZE", header.sizes[i], 8);
    if (!isValidPcdType(header.types[i], size)) {
      throw InputError(path, "PCD header: field '" + header.fields[i] + "' has TYPE '" + header.types[i] +
                                 "' with SIZE " + header.sizes[i] + " (expected F 4|8, I or U 1|2|4|8)");
    }
    const std::uint64_t count =
        header.counts.empty() ? 1 : headerInteger(path, "PCD", "COUNT", header.counts[i], kMaxPointBytes);
    if (count == 0) throw InputError(path, "PCD header: field '" + header.fields[i] + "' has COUNT 0");
    record.bytes += size * count;
    record.values += count;
    if (record.bytes > kMaxPointBytes) {
      throw InputError(path, "PCD header: a point takes more than " + std::to_string(kMaxPointBytes) + " bytes");
    }
  }
  return record;
}

std::uint64_t pcdPointCount(const std::string& path, const PcdHeader& header) {
  if (!header.width) throw InputError(path, "PCD header has no WIDTH line");
  if (!header.points) throw InputError(path, "PCD header has no POINTS line");
  const std::uint64_t height = header.height.value_or(1);
  const std::uint64_t declared = *header.width * height;  // both < 2^32: cannot wrap
  if (declared != *header.points) {
    throw InputError(path, "PCD header: WIDTH x HEIGHT (" + std::to_string(*header.width) + " x " +
                               std::to_string(height) + ") differs from POINTS (" + std::to_string(*header.points) + ")");
  }
  if (declared == 0) throw InputError(path, "cloud has zero points");
  if (declared > kMaxCloudPoints) {
    throw InputError(path, "PCD header declares " + std::to_string(declared) + " points (more than " +
                               std::to_string(kMaxCloudPoints) + ")");
  }
  return declared;
}

std::uint32_t readLittleEndianWord(const unsigned char* bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
         static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
}

// binary_compressed data starts with two 32-bit words: compressed and uncompressed size.
void checkCompressedPcdData(const std::string& path, const HeaderText& text, std::uint64_t needed) {
  const std::uint64_t remaining = text.file_size - text.data_offset;
  if (remaining < 8) throw InputError(path, "truncated compressed PCD data (no size words)");
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(text.data_offset));
  unsigned char words[8] = {};
  if (!in.read(reinterpret_cast<char*>(words), sizeof(words))) throw InputError(path, "cannot read compressed PCD data");
  const std::uint64_t compressed = readLittleEndianWord(words);
  const std::uint64_t uncompressed = readLittleEndianWord(words + 4);
  if (uncompressed != needed) {
    throw InputError(path, "corrupt compressed PCD data (uncompressed size " + std::to_string(uncompressed) +
                               ", the header's points need " + std::to_string(needed) + ")");
  }
  if (compressed > remaining - 8) {
    throw InputError(path, "truncated compressed PCD data (" + std::to_string(remaining - 8) + " bytes for " +
                               std::to_string(compressed) + " expected)");
  }
  if (saturatingProduct(compressed, kMaxLzfExpansion) < uncompressed) {
    throw InputError(path, "corrupt compressed PCD data (" + std::to_string(compressed) +
                               " compressed bytes cannot hold " + std::to_string(uncompressed) + ")");
  }
}

// PCL's header loop does not stop at DATA: it goes on reading the data as header lines, skipping
// empty, comment and VERSION lines, until one whose first word it does not know. Data that starts
// with a header keyword would rewrite the header PCL uses (found by fuzzing: binary data starting
// with "COLUMNS" emptied PCL's field list, which PCL's reader then indexed past its end). No
// writer produces such data by design, and the chance that real binary data spells a keyword is
// negligible, so a file whose data PCL would read as header is rejected.
void checkDataIsNotReadAsHeader(const std::string& path, std::uint64_t data_offset) {
  static const char* const kPclHeaderKeywords[] = {"FIELDS", "COLUMNS", "SIZE",   "TYPE", "COUNT",
                                                   "WIDTH",  "HEIGHT",  "VIEWPOINT", "POINTS", "DATA"};
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(data_offset));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream words(line);
    words.imbue(std::locale::classic());
    std::string first;
    words >> first;  // like PCL: the first whitespace-separated word, matched by prefix
    if (first.compare(0, 1, "#") == 0 || first.compare(0, 7, "VERSION") == 0) continue;
    for (const char* keyword : kPclHeaderKeywords) {
      if (first.compare(0, std::strlen(keyword), keyword) == 0) {
        throw InputError(path, "corrupt PCD data: it starts with the header keyword '" + std::string(keyword) +
                                   "', which PCL would read as part of the header");
      }
    }
    return;
  }
}

void checkPcdData(const std::string& path, const HeaderText& text, const PcdHeader& header,
                  const PcdRecord& record, std::uint64_t points) {
  checkDataIsNotReadAsHeader(path, text.data_offset);
  const std::uint64_t remaining = text.file_size - text.data_offset;
  if (header.data_type == "binary") {
    const std::uint64_t needed = points * record.bytes;  // <= 2e8 * 2^16: no wrap
    if (needed > remaining) {
      throw InputError(path, "truncated binary PCD data (" + std::to_string(remaining) + " bytes for " +
                                 std::to_string(needed) + " expected)");
    }
  } else if (header.data_type == "binary_compressed") {
    checkCompressedPcdData(path, text, points * record.bytes);
  } else if (header.data_type == "ascii") {
    const std::uint64_t needed = points * record.values * kMinAsciiValueBytes;
    if (needed > remaining + 1) {  // the last value may lack its newline
      throw InputError(path, "truncated ASCII PCD data (" + std::to_string(remaining) + " bytes cannot hold " +
                                 std::to_string(points) + " points)");
    }
    checkAsciiValues(path, "PCD", text.data_offset, text.lines.size() + 1);
  } else {
    throw InputError(path, "PCD header: unknown DATA type '" + shortened(header.data_type) +
                               "' (expected ascii, binary or binary_compressed)");
  }
}

// ---- PLY ------------------------------------------------------------------------------------

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::size_t properties = 0;
  std::uint64_t min_binary_bytes = 0;  ///< Scalars' sizes plus list length words (lists may be empty).
  std::uint64_t min_ascii_values = 0;  ///< Scalars plus list lengths.
  Words uint8_scalars;                 ///< Names of the 8-bit unsigned scalar properties, in order.
};

struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
};

// Bytes of a PLY scalar type; 0 for a name PLY does not define.
std::uint64_t plyTypeBytes(const std::string& type) {
  static const std::map<std::string, std::uint64_t> sizes = {
      {"char", 1},  {"int8", 1},   {"uchar", 1}, {"uint8", 1},  {"short", 2},  {"int16", 2},
      {"ushort", 2}, {"uint16", 2}, {"int", 4},   {"int32", 4},  {"uint", 4},   {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

std::uint64_t plyPropertyType(const std::string& path, const std::string& type) {
  const std::uint64_t bytes = plyTypeBytes(type);
  if (bytes == 0) throw InputError(path, "PLY header: unknown property type '" + shortened(type) + "'");
  return bytes;
}

void addPlyProperty(const std::string& path, const Words& words, PlyHeader& header) {
  if (header.elements.empty()) throw InputError(path, "PLY header: property before any element");
  PlyElement& element = header.elements.back();
  if (words.size() == 3) {
    element.min_binary_bytes += plyPropertyType(path, words[1]);
    if (words[1] == "uchar" || words[1] == "uint8") element.uint8_scalars.push_back(words[2]);
    else element.uint8_scalars.push_back("");  // keeps "adjacent" meaning adjacent properties
  } else if (words.size() == 5 && words[1] == "list") {
    // PCL sizes a vertex list field by the first vertex's list and asserts (aborting the
    // process) when a later list is longer (found by fuzzing); point clouds carry no lists.
    if (element.name == "vertex") {
      throw InputError(path, "PLY header: vertex property '" + shortened(words[4]) +
                                 "' is a list; per-point lists are not supported");
    }
    element.min_binary_bytes += plyPropertyType(path, words[2]);
    plyPropertyType(path, words[3]);
    element.uint8_scalars.push_back("");
  } else {
    std::string line;
    for (const std::string& word : words) line += (line.empty() ? "" : " ") + word;
    throw InputError(path, "PLY header: malformed property line '" + shortened(line) + "'");
  }
  element.min_ascii_values += 1;
  ++element.properties;
}

PlyHeader parsePlyHeader(const std::string& path, const HeaderText& text) {
  if (text.lines.empty() || splitWords(text.lines[0]) != Words{"ply"}) {
    throw InputError(path, "not a PLY file (missing 'ply' magic)");
  }
  PlyHeader header;
  for (std::size_t i = 1; i < text.lines.size(); ++i) {
    const Words words = splitWords(text.lines[i]);
    if (words.empty()) continue;
    // PCL finds a line's keyword past leading white space but hands obj_info lines to a callback
    // that splits at spaces and asserts the first piece is "obj_info": a form feed or a space
    // before it aborted the process (found by fuzzing). No writer indents PLY headers.
    if (std::isspace(static_cast<unsigned char>(text.lines[i][0]))) {
      throw InputError(path, "PLY header: line " + std::to_string(i + 1) + " starts with white space");
    }
    const std::string& key = words[0];
    if (key == "comment" || key == "obj_info" || key == "end_header") continue;
    if (key == "format") {
      if (words.size() != 3) throw InputError(path, "PLY header: malformed format line");
      header.format = words[1];
    } else if (key == "element") {
      if (words.size() != 3) throw InputError(path, "PLY header: malformed element line '" + shortened(text.lines[i]) + "'");
      PlyElement element;
      element.name = words[1];
      element.count = headerInteger(path, "PLY", "element " + words[1], words[2], kMaxUint32);
      header.elements.push_back(element);
    } else if (key == "property") {
      addPlyProperty(path, words, header);
    } else {
      throw InputError(path, "PLY header: unexpected line '" + shortened(text.lines[i]) + "'");
    }
  }
  if (!text.complete) throw InputError(path, "corrupt PLY header (no end_header line)");
  if (header.format != "ascii" && header.format != "binary_little_endian" && header.format != "binary_big_endian") {
    throw InputError(path, "PLY header: unknown format '" + shortened(header.format) + "'");
  }
  return header;
}

// PCL reads 8-bit vertex colours into one packed rgb field: red adds the field and remembers
// where it is, blue writes it, alpha widens it to rgba. Any other arrangement writes outside
// the field or the point, and Debian's PCL aborts on an assertion (found by fuzzing: a lone
// blue). Accepted: red, green, blue adjacent and in this order (or the diffuse_ names), then
// optionally alpha, as PCL and other writers save them.
void checkPlyVertexColour(const std::string& path, const PlyElement& vertex) {
  const Words& names = vertex.uint8_scalars;
  const auto is_colour = [](const std::string& name) {
    return name == "red" || name == "green" || name == "blue" || name == "alpha" || name == "diffuse_red" ||
           name == "diffuse_green" || name == "diffuse_blue";
  };
  const std::size_t count = static_cast<std::size_t>(std::count_if(names.begin(), names.end(), is_colour));
  if (count == 0) return;
  const auto first = std::find_if(names.begin(), names.end(), is_colour);
  const std::size_t at = static_cast<std::size_t>(first - names.begin());
  const std::string prefix = names[at].rfind("diffuse_", 0) == 0 ? "diffuse_" : "";
  const bool triple = at + 3 <= names.size() && names[at] == prefix + "red" && names[at + 1] == prefix + "green" &&
                      names[at + 2] == prefix + "blue";
  const bool alpha = triple && at + 3 < names.size() && names[at + 3] == "alpha";
  if (!triple || count != (alpha ? 4u : 3u)) {
    throw InputError(path, "PLY header: 8-bit vertex colour must be the properties red, green, blue in this order "
                           "(optionally then alpha)");
  }
}

std::uint64_t plyVertexCount(const std::string& path, const PlyHeader& header) {
  std::optional<std::uint64_t> vertices;
  for (const PlyElement& element : header.elements) {
    if (element.count > kMaxCloudPoints) {
      throw InputError(path, "PLY header: element '" + element.name + "' declares " + std::to_string(element.count) +
                                 " entries (more than " + std::to_string(kMaxCloudPoints) + ")");
    }
    if (element.count > 0 && element.properties == 0) {
      throw InputError(path, "PLY header: element '" + element.name + "' has entries but no properties");
    }
    if (element.name == "vertex") {
      if (vertices) throw InputError(path, "PLY header: more than one vertex element");
      vertices = element.count;
      checkPlyVertexColour(path, element);
    }
  }
  if (!vertices) throw InputError(path, "PLY header has no vertex element");
  if (*vertices == 0) throw InputError(path, "cloud has zero points");
  return *vertices;
}

void checkPlyData(const std::string& path, const HeaderText& text, const PlyHeader& header) {
  const bool ascii = header.format == "ascii";
  std::uint64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    const std::uint64_t per_entry =
        ascii ? saturatingProduct(element.min_ascii_values, kMinAsciiValueBytes) : element.min_binary_bytes;
    needed = saturatingSum(needed, saturatingProduct(element.count, per_entry));
  }
  const std::uint64_t remaining = text.file_size - text.data_offset;
  if (!ascii && needed > remaining) {
    throw InputError(path, "truncated binary PLY data (" + std::to_string(remaining) + " bytes for at least " +
                               std::to_string(needed) + " expected)");
  }
  if (ascii && needed > saturatingSum(remaining, 1)) {  // the last value may lack its newline
    throw InputError(path, "truncated ASCII PLY data (" + std::to_string(remaining) +
                               " bytes cannot hold the declared elements)");
  }
  if (ascii) checkAsciiValues(path, "PLY", text.data_offset, text.lines.size() + 1);
}

}  // namespace

void checkReadableFile(const std::string& path) {
  namespace fs = boost::filesystem;
  boost::system::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, expected a file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError(path, "cannot open file for reading");
}

CloudFileSummary checkPcdFile(const std::string& path) {
  const HeaderText text = readHeaderText(path, "DATA");
  const PcdHeader header = parsePcdHeader(path, text);
  const PcdRecord record = pcdRecord(path, header);
  CloudFileSummary summary;
  summary.points = pcdPointCount(path, header);
  checkPcdData(path, text, header, record, summary.points);
  return summary;
}

CloudFileSummary checkPlyFile(const std::string& path) {
  const HeaderText text = readHeaderText(path, "end_header");
  const PlyHeader header = parsePlyHeader(path, text);
  CloudFileSummary summary;
  summary.points = plyVertexCount(path, header);
  checkPlyData(path, text, header);
  for (const PlyElement& element : header.elements) {
    if (element.name == "camera") summary.has_camera = true;
  }
  return summary;
}

}  // namespace symmetry_segmentation
