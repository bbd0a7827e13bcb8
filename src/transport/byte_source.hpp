// Where a pyramid's or an imagery layer's files come from: a local directory, or the same
// directory on any static web server read with HTTP range requests (a transport::Network,
// transport/network_settings.hpp).
// The stores read manifests whole and packs by range through this, so they never know which.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::transport {

// One open file: its size is known, any range of it can be read. Thread-safe.
class ByteFile {
 public:
  virtual ~ByteFile() = default;
  virtual uint64_t sizeBytes() const = 0;
  // Exactly out.size() bytes at offset, or an error naming the file or URL and the problem.
  virtual Result<void> read(std::span<std::byte> out, uint64_t offset) const = 0;
  // The same for adjacent pieces (say, the blocks of neighbouring tiles) read together: out
  // holds pieceBytes[0] bytes at offset, then pieceBytes[1] after them, and so on (their sum is
  // out.size()). Over HTTP: one range request for the pieces the disk cache lacks, each piece
  // cached on its own, so that later reads find it whatever it is read with.
  virtual Result<void> readPieces(std::span<std::byte> out, uint64_t offset,
                                  std::span<const uint32_t> pieceBytes) const {
    (void)pieceBytes;
    return read(out, offset);
  }
  virtual const std::string& location() const = 0;
};

struct OpenedFile {
  std::shared_ptr<const ByteFile> file;
  std::vector<std::byte> head;  // its first bytes (fewer than asked when the file is shorter)
};

// A directory of files, named by '/'-separated relative names ("L3/0_1.pack"). Thread-safe.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  // A whole small file (a manifest) of at most maxBytes; nullopt when there is no such file.
  virtual Result<std::optional<std::vector<std::byte>>> readWhole(const std::string& name,
                                                                  size_t maxBytes) = 0;
  // The same for a file whose name never changes content (a versioned tile URL: a new version of
  // the data is published under new names): over HTTP a cached copy is used without asking the
  // server again. Locally the same as readWhole.
  virtual Result<std::optional<std::vector<std::byte>>> readWholeImmutable(const std::string& name,
                                                                           size_t maxBytes) {
    return readWhole(name, maxBytes);
  }
  // Opens a file and reads its first headBytes (one request over HTTP: a pack's header and index).
  virtual Result<OpenedFile> open(const std::string& name, size_t headBytes) = 0;
  // The path or URL of a file, for messages.
  virtual std::string locationOf(const std::string& name) const = 0;
  // The directory's path or URL.
  virtual const std::string& location() const = 0;
  virtual bool remote() const { return false; }
};

// A local directory.
std::shared_ptr<ByteSource> localByteSource(const std::filesystem::path& dir);

class Network;  // transport/network_settings.hpp

// A local directory, or an http:// / https:// URL of the same directory on a static server read
// through `network` (Network::open). Without a network (nullptr) only local directories open: a
// URL is an error naming it.
Result<std::shared_ptr<ByteSource>> openByteSource(const std::string& location, Network* network);

}  // namespace globe::transport
