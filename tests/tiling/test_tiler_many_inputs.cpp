// Thousands of inputs (GLO-30 is 26,000 tiles) under a small file-descriptor limit: the tiler
// keeps no input open between reading its header and conditioning it, and every spilled source
// shares one file, so a run needs a handful of descriptors however many inputs it has. Real data:
// a 3″ SRTM tile cut into 144 pieces (over twice the 64-descriptor limit) that share their edge
// samples, under the 20′ world.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>

#include "rasters/gtopo30.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/source_conditioning.hpp"
#include "tiling/source_set.hpp"

// Its own namespace: the unity build joins this file with the other tiler tests.
namespace globe::tiling::many_inputs {
namespace {

namespace fs = std::filesystem;
using globe::testing::checksums;
using globe::testing::runCommand;

const std::string kTiler = GLOBE_TILER_EXE;
// Far fewer descriptors than inputs (the old tiler held one or two per input).
constexpr int kDescriptorLimit = 64;
constexpr int kPiecesPerSide = 12;

std::string dem(const std::string& name) {
  return std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/gtopo30/" + name;
}

// N50E008 (1201 x 1201) as 20 x 20 GTOPO30 pieces of 61 x 61 samples, neighbours sharing a row or
// column, written once; then the world. Returns the list file and the inputs.
struct ManyInputs {
  fs::path listFile;
  std::vector<std::string> inputs;
};

const ManyInputs& manyInputs() {
  static const ManyInputs many = [] {
    ManyInputs m;
    const fs::path dir = globe::testing::freshTempDir("many-inputs");
    auto whole = rasters::readGtopo30(dem("N50E008.DEM"));
    EXPECT_TRUE(whole) << whole.error();
    if (!whole) return m;
    const rasters::Gtopo30Header& h = whole->header;
    const int64_t side = (h.cols - 1) / kPiecesPerSide + 1;
    for (int pr = 0; pr < kPiecesPerSide; ++pr) {
      for (int pc = 0; pc < kPiecesPerSide; ++pc) {
        rasters::Gtopo30Raster piece;
        piece.header = h;
        piece.header.rows = piece.header.cols = side;
        piece.header.bandRowBytes = piece.header.totalRowBytes = side * 2;
        piece.header.ulxMapDegrees = h.ulxMapDegrees + double(pc * (side - 1)) * h.xDimDegrees;
        piece.header.ulyMapDegrees = h.ulyMapDegrees - double(pr * (side - 1)) * h.yDimDegrees;
        for (int64_t r = 0; r < side; ++r) {
          for (int64_t c = 0; c < side; ++c) {
            piece.heights.push_back(whole->at(pr * (side - 1) + r, pc * (side - 1) + c));
          }
        }
        const fs::path stem = dir / ("P" + std::to_string(pr) + "_" + std::to_string(pc));
        EXPECT_TRUE(rasters::writeGtopo30(stem, piece));
        m.inputs.push_back(stem.string() + ".DEM");
      }
    }
    m.inputs.push_back(dem("ETOPO20.DEM"));
    m.listFile = dir / "inputs.txt";
    std::ofstream list(m.listFile);
    for (const std::string& input : m.inputs) list << input << "\n";
    return m;
  }();
  return many;
}

std::string limited(const std::string& command) {
  return "ulimit -n " + std::to_string(kDescriptorLimit) + " && " + command;
}

TEST(TilerManyInputs, AHundredAndFortyFiveInputsTileUnderASixtyFourDescriptorLimit) {
  const ManyInputs& many = manyInputs();
  ASSERT_EQ(many.inputs.size(), size_t{kPiecesPerSide * kPiecesPerSide + 1});
  const fs::path dir = globe::testing::freshTempDir("many-inputs-runs");
  const std::string options = " -q -j 2 --pack-tiles 8 --inputs " + many.listFile.string();
  const auto free = runCommand(kTiler + options + " -o " + (dir / "free").string());
  ASSERT_EQ(free.exitCode, 0) << free.output;
  const auto limit = runCommand(limited(kTiler + options + " -o " + (dir / "limited").string()));
  ASSERT_EQ(limit.exitCode, 0) << limit.output;
  EXPECT_EQ(checksums(dir / "free"), checksums(dir / "limited"));
  // Shards and the merge open every input's header too.
  const std::string sharded = (dir / "sharded").string();
  for (const char* shard : {"0/3", "1/3", "2/3"}) {
    const auto run = runCommand(limited(kTiler + options + " --shard " + shard + " -o " + sharded));
    ASSERT_EQ(run.exitCode, 0) << shard << ": " << run.output;
  }
  const auto merged = runCommand(limited(kTiler + " merge" + options + " -o " + sharded));
  ASSERT_EQ(merged.exitCode, 0) << merged.output;
  EXPECT_EQ(checksums(dir / "free"), checksums(sharded));
}

// Lowers this process's descriptor limit while it lives.
class DescriptorLimit {
 public:
  explicit DescriptorLimit(rlim_t soft) {
    ::getrlimit(RLIMIT_NOFILE, &saved_);
    rlimit lowered = saved_;
    lowered.rlim_cur = soft;
    ok_ = ::setrlimit(RLIMIT_NOFILE, &lowered) == 0;
  }
  ~DescriptorLimit() { ::setrlimit(RLIMIT_NOFILE, &saved_); }
  bool ok() const { return ok_; }

 private:
  rlimit saved_{};
  bool ok_ = false;
};

TEST(TilerManyInputs, EverySourceSpilledSharesOneFile) {
  // A zero memory budget spills all 144 pieces (the world stays: finer sources read it); two
  // threads condition them together under the limit, and each reads back as conditioned in memory.
  const ManyInputs& many = manyInputs();
  auto inMemory = openSources(many.inputs, {});
  ASSERT_TRUE(inMemory) << inMemory.error();
  ASSERT_TRUE(conditionSources(*inMemory));
  ConditioningOptions options;
  options.threads = 2;
  options.spillDirectory = globe::testing::freshTempDir("many-inputs-spill");
  options.memoryBudgetBytes = 0;
  std::vector<TilerSource> spilled;
  {
    const DescriptorLimit limit(kDescriptorLimit);
    ASSERT_TRUE(limit.ok());
    auto opened = openSources(many.inputs, {});
    ASSERT_TRUE(opened) << opened.error();
    spilled = std::move(*opened);
    auto report = conditionSources(spilled, options);
    ASSERT_TRUE(report) << report.error();
  }
  EXPECT_TRUE(fs::is_empty(options.spillDirectory)) << "the spill file is unlinked";
  ASSERT_EQ(spilled.size(), inMemory->size());
  for (size_t i = 0; i < spilled.size(); ++i) {
    const geo::SampleGrid& g = spilled[i].grid;
    std::vector<int16_t> a(static_cast<size_t>(g.cols)), b(a.size());
    for (int64_t r = 0; r < g.rows; ++r) {
      ASSERT_TRUE((*inMemory)[i].raster->readRow(r, 0, g.cols, a.data()));
      ASSERT_TRUE(spilled[i].raster->readRow(r, 0, g.cols, b.data()));
      ASSERT_EQ(a, b) << spilled[i].argument << " row " << r;
    }
  }
}

TEST(TilerManyInputs, AnInputChangedAfterItsHeaderWasReadIsAnError) {
  // Inputs are opened twice (header, then conditioning): one replaced in between is refused.
  const fs::path dir = globe::testing::freshTempDir("changed-input");
  auto fuji = rasters::readGtopo30(dem("E138N35_FUJI.DEM"));
  ASSERT_TRUE(fuji) << fuji.error();
  ASSERT_TRUE(rasters::writeGtopo30(dir / "FUJI", *fuji));
  auto sources = openSources({(dir / "FUJI.DEM").string()}, {});
  ASSERT_TRUE(sources) << sources.error();
  fuji->header.ulxMapDegrees += 1.0;
  ASSERT_TRUE(rasters::writeGtopo30(dir / "FUJI", *fuji));
  auto conditioned = conditionSources(*sources);
  ASSERT_FALSE(conditioned);
  EXPECT_NE(conditioned.error().find("FUJI.DEM: the raster changed"), std::string::npos)
      << conditioned.error();
}

}  // namespace
}  // namespace globe::tiling::many_inputs
