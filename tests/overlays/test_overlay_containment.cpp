// An overlay file reaches nothing but itself: a KMZ (or a KML) whose hrefs climb out of its
// folder with `..`, name absolute paths or file:// URLs, follow a symlink out, or name a FIFO gets
// none of them read, and says so in the document's warnings. inotify watches the folders outside:
// not one file there is opened.
#include <cpl_conv.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>
#include <utility>
#include <vector>

#include "formats/image_io.hpp"
#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

namespace fs = std::filesystem;

std::string pngBytes() {
  const formats::ImageRgba image{2, 2, std::vector<uint8_t>(16, 200)};
  auto png = formats::encodePng(image);
  EXPECT_TRUE(png) << png.error();
  return png ? std::string(reinterpret_cast<const char*>(png->data()), png->size()) : "";
}

std::string groundOverlay(const std::string& name, const std::string& href) {
  return "<GroundOverlay><name>" + name + "</name><Icon><href>" + href +
         "</href></Icon><LatLonBox><north>1</north><south>0</south><east>1</east><west>0</west>"
         "</LatLonBox></GroundOverlay>";
}

// Counts the files opened in a folder while it lives (inotify IN_OPEN).
class OpenWatch {
 public:
  explicit OpenWatch(const fs::path& folder) : fd_(inotify_init1(IN_NONBLOCK)) {
    EXPECT_GE(fd_, 0);
    EXPECT_GE(inotify_add_watch(fd_, folder.c_str(), IN_OPEN | IN_ACCESS), 0);
  }
  ~OpenWatch() { close(fd_); }
  OpenWatch(const OpenWatch&) = delete;
  OpenWatch& operator=(const OpenWatch&) = delete;
  // The names opened since the watch began.
  std::vector<std::string> opened() const {
    std::vector<std::string> names;
    alignas(inotify_event) char buffer[4096];
    for (ssize_t n; (n = read(fd_, buffer, sizeof buffer)) > 0;) {
      for (char* at = buffer; at < buffer + n;) {
        const auto* event = reinterpret_cast<const inotify_event*>(at);
        names.push_back(event->len > 0 ? event->name : "(the folder)");
        at += sizeof(inotify_event) + event->len;
      }
    }
    return names;
  }

 private:
  int fd_;
};

// A folder with the overlay, a sibling folder with a secret image, a subfolder with a good one,
// a symlink out and a FIFO.
struct Layout {
  fs::path overlayFolder, secretFolder;
};

Layout makeLayout(const fs::path& root) {
  Layout layout{root / "overlay", root / "secret"};
  fs::create_directories(layout.overlayFolder / "img");
  fs::create_directories(layout.secretFolder);
  const std::string png = pngBytes();
  std::ofstream(layout.secretFolder / "secret.png", std::ios::binary) << png;
  std::ofstream(layout.overlayFolder / "img" / "ok.png", std::ios::binary) << png;
  fs::create_symlink(layout.secretFolder / "secret.png", layout.overlayFolder / "link.png");
  EXPECT_EQ(mkfifo((layout.overlayFolder / "pipe.png").c_str(), 0600), 0);
  return layout;
}

std::string hostileFeatures(const Layout& layout) {
  const std::string secret = (layout.secretFolder / "secret.png").string();
  return groundOverlay("up", "../secret/secret.png") + groundOverlay("absolute", secret) +
         groundOverlay("url", "file://" + secret) +
         groundOverlay("encoded", "%2E%2E/secret/secret.png") +
         groundOverlay("symlink", "link.png") + groundOverlay("fifo", "pipe.png") +
         groundOverlay("good", "img/ok.png") + groundOverlay("good-dotted", "img/../img/ok.png");
}

void expectContained(const OverlayDocument& document, const std::string& where) {
  SCOPED_TRACE(where);
  ASSERT_EQ(document.groundOverlays.size(), 8u);
  for (const GroundOverlay& overlay : document.groundOverlays) {
    const bool good = overlay.name.starts_with("good");
    EXPECT_EQ(overlay.image != nullptr, good) << overlay.name << ": " << overlay.imageHref;
  }
  std::string all;
  for (const std::string& warning : document.warnings) all += warning + "\n";
  EXPECT_EQ(document.warnings.size(), 6u) << all;
  for (const char* expected :
       {"\"../secret/secret.png\": outside the overlay's folder", "an absolute path",
        "\"%2E%2E/secret/secret.png\": outside", "\"link.png\": leads outside",
        "\"pipe.png\": not a regular file"}) {
    EXPECT_NE(all.find(expected), std::string::npos) << expected << "\n" << all;
  }
}

TEST(OverlayContainment, AKmzReadsNothingOutsideItsArchiveAndFolder) {
  ScratchFolder scratch;
  const Layout layout = makeLayout(scratch.path());
  const fs::path kmz = layout.overlayFolder / "hostile.kmz";
  writeZip(kmz, {{"doc.kml", kml(hostileFeatures(layout))}});
  const OpenWatch watch(layout.secretFolder);
  auto document = readOverlayFile(kmz);
  ASSERT_TRUE(document) << document.error();
  expectContained(*document, "kmz");
  EXPECT_TRUE(watch.opened().empty()) << "a file outside was opened: " << watch.opened()[0];
}

TEST(OverlayContainment, AKmlReadsOnlyItsFolderAndBelow) {
  ScratchFolder scratch;
  const Layout layout = makeLayout(scratch.path());
  const fs::path file = layout.overlayFolder / "hostile.kml";
  std::ofstream(file) << kml(hostileFeatures(layout));
  const OpenWatch watch(layout.secretFolder);
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  expectContained(*document, "kml");
  EXPECT_TRUE(watch.opened().empty()) << "a file outside was opened: " << watch.opened()[0];
  // The same file given by a relative path resolves the same way.
  const fs::path before = fs::current_path();
  fs::current_path(layout.overlayFolder);
  auto relative = readOverlayFile("hostile.kml");
  fs::current_path(before);
  ASSERT_TRUE(relative) << relative.error();
  expectContained(*relative, "kml, relative path");
}

}  // namespace
}  // namespace globe::overlays
