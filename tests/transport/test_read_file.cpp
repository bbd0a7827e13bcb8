// readFileBounded: the limit holds before and while reading; what is not a regular file is
// refused by name (a device or a FIFO would be read forever or block).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "transport/read_file.hpp"

namespace fs = std::filesystem;
using globe::transport::readFileBounded;

namespace {

class ReadFileBounded : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("globe-read-file-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }
  fs::path dir_;
};

TEST_F(ReadFileBounded, ReadsAFileUpToItsLimitExactly) {
  const std::string bytes(100000, 'x');  // more than one read chunk
  auto text = readFileBounded(write("a", bytes), 100000);
  ASSERT_TRUE(text.ok()) << text.error();
  EXPECT_EQ(*text, bytes);
  auto empty = readFileBounded(write("e", ""), 10);
  ASSERT_TRUE(empty.ok()) << empty.error();
  EXPECT_TRUE(empty->empty());
}

TEST_F(ReadFileBounded, OneByteOverTheLimitIsRefusedByName) {
  const fs::path file = write("big", std::string(1025, 'x'));
  auto text = readFileBounded(file, 1024);
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error(), file.string() + ": larger than the 1024 bytes allowed");
}

TEST_F(ReadFileBounded, AHugeSparseFileIsRefusedBeforeAnyRead) {
  const fs::path file = write("sparse", "");
  fs::resize_file(file, std::uintmax_t{64} << 30);  // 64 GiB of holes: refused, not read
  auto text = readFileBounded(file, 2u << 20);
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error(), file.string() + ": larger than the 2 MiB allowed");
}

TEST_F(ReadFileBounded, WhatIsNotARegularFileIsRefused) {
  EXPECT_EQ(readFileBounded(dir_ / "missing", 10).error(), (dir_ / "missing").string() + ": no such file");
  EXPECT_EQ(readFileBounded(dir_, 10).error(), dir_.string() + ": not a regular file");
  EXPECT_EQ(readFileBounded("/dev/zero", 10).error(), "/dev/zero: not a regular file");
  const fs::path fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(readFileBounded(fifo, 10).error(), fifo.string() + ": not a regular file");
}

}  // namespace
