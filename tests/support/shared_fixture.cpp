#include "tests/support/shared_fixture.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <span>

#include "core/crc32.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {
namespace {

namespace fs = std::filesystem;

// A readable, collision-safe folder name: the key's first letters and its CRC-32.
std::string folderName(const std::string& key) {
  std::string name;
  for (char c : key.substr(0, 40)) {
    name += std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' ? c : '_';
  }
  const auto bytes = std::as_bytes(std::span(key.data(), key.size()));
  char hash[16];
  std::snprintf(hash, sizeof hash, "-%08x", core::crc32(bytes));
  return name + hash;
}

// Holds an exclusive flock on a file while it lives.
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_CREAT | O_RDWR, 0644)) {
    if (fd_ >= 0) locked_ = ::flock(fd_, LOCK_EX) == 0;
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool locked() const { return locked_; }

 private:
  int fd_;
  bool locked_ = false;
};

}  // namespace

fs::path sharedFixture(const std::string& key, const std::function<bool(const fs::path&)>& build) {
  const std::string name = folderName(key);
  const char* root = std::getenv("GLOBE_TEST_FIXTURES");
  if (root == nullptr || *root == '\0') {
    const fs::path dir = freshTempDir("fixture-" + name) / "fixture";
    if (!build(dir)) ADD_FAILURE() << "could not make the test fixture " << key;
    return dir;
  }
  const fs::path folder = fs::path(root) / name;
  // The marker lies beside the fixture, not in it: tests compare fixtures file by file.
  const fs::path done = fs::path(root) / (name + ".done");
  std::error_code error;
  fs::create_directories(root, error);
  const FileLock lock(fs::path(root) / (name + ".lock"));
  if (!lock.locked()) {
    ADD_FAILURE() << "cannot lock " << folder << " for the test fixture " << key;
    return folder;
  }
  if (fs::exists(done, error)) return folder;
  const fs::path partial = fs::path(root) / (name + ".partial");
  fs::remove_all(partial, error);
  fs::remove_all(folder, error);
  if (!build(partial)) {
    ADD_FAILURE() << "could not make the test fixture " << key;
    fs::remove_all(partial, error);
    return folder;
  }
  fs::rename(partial, folder, error);
  if (error) {
    ADD_FAILURE() << "cannot rename " << partial << " to " << folder << ": " << error.message();
    return folder;
  }
  std::ofstream(done) << key << "\n";
  return folder;
}

}  // namespace globe::testing
