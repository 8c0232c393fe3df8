#pragma once
// Helpers shared by the libFuzzer targets in this directory.
//
// Contract every target checks: a parser either returns a result that satisfies the invariants
// its callers rely on, or throws symmetry_segmentation::InputError. Anything else (a crash, a
// sanitizer report, another exception type, a hang, a huge allocation) is a finding.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace fuzz_support {

/// A file in a private directory (on /dev/shm when there is one: the parsers under test only
/// take paths, and memory-backed files keep the executions fast). Rewritten on every input.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& name) {
    const char* base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    std::string pattern = std::string(base) + "/symseg_fuzz_XXXXXX";
    if (!mkdtemp(&pattern[0])) {
      std::perror("mkdtemp");
      std::abort();
    }
    dir_ = pattern;
    path_ = dir_ + "/" + name;
  }
  ~ScratchFile() {
    for (const std::string& path : siblings_) std::remove(path.c_str());
    std::remove(path_.c_str());
    rmdir(dir_.c_str());
  }

  /// Path of another file in the same directory, removed with it.
  std::string sibling(const std::string& name) {
    siblings_.push_back(dir_ + "/" + name);
    return siblings_.back();
  }

  const std::string& write(const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", path_.c_str());
      std::abort();
    }
    return path_;
  }

  const std::string& directory() const { return dir_; }
  const std::string& path() const { return path_; }

 private:
  std::string dir_, path_;
  std::vector<std::string> siblings_;
};

/// Reports a broken invariant as a crash, so libFuzzer keeps the input.
[[noreturn]] inline void fail(const char* what) {
  std::fprintf(stderr, "INVARIANT BROKEN: %s\n", what);
  std::abort();
}

#define FUZZ_CHECK(condition)                              \
  do {                                                     \
    if (!(condition)) ::fuzz_support::fail(#condition);    \
  } while (0)

/// Little-endian reader for the structured (non-file) targets: missing bytes read as zero.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t u8() { return cursor_ < size_ ? data_[cursor_++] : 0; }
  std::uint32_t u32() {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value |= static_cast<std::uint32_t>(u8()) << (8 * i);
    return value;
  }
  double f64() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(u8()) << (8 * i);
    double value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
  }
  /// Everything not read yet.
  std::string rest() {
    const std::size_t begin = cursor_ < size_ ? cursor_ : size_;
    cursor_ = size_;
    return std::string(reinterpret_cast<const char*>(data_) + begin, size_ - begin);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t cursor_ = 0;
};

}  // namespace fuzz_support
