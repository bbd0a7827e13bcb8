#include "tiling/shard_files.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "tiling/write_failed.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;
constexpr char kFragmentMagic[8] = {'G', 'L', 'B', 'S', 'M', 'P', 'L', '1'};
constexpr size_t kFragmentHeaderBytes = 8 + 4 + 8;
constexpr size_t kRecordBytes = 4 + 4 + 2;
constexpr uint64_t kMaxFragmentBytes = uint64_t{1} << 32;
constexpr const char* kSummarySuffix = ".json";

void putLittle(std::vector<std::byte>& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::byte>((value >> (8 * i)) & 0xFF));
}

uint64_t getLittle(const std::byte* in, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= uint64_t{std::to_integer<uint8_t>(in[i])} << (8 * i);
  return value;
}

fs::path fragmentFolder(const fs::path& outputDir, const formats::PackId& pack) {
  return shardFolder(outputDir) / "samples" / std::to_string(pack.level) / std::to_string(pack.x) /
         std::to_string(pack.y);
}

fs::path summaryPath(const fs::path& outputDir, uint32_t index, uint32_t count) {
  return shardFolder(outputDir) /
         (std::to_string(index) + "-of-" + std::to_string(count) + kSummarySuffix);
}

nlohmann::json conditioningJson(const formats::SourceConditioning& c) {
  return {c.noDataSamples,       c.seaSamples,         c.voidSamples,
          c.interpolatedSamples, c.fromCoarserSamples, c.unfilledSamples,
          c.outsideSamples,      c.bendMarginDegrees,  c.noDataIsWater};
}

formats::SourceConditioning conditioningOf(const nlohmann::json& j) {
  return {j.at(0).get<uint64_t>(), j.at(1).get<uint64_t>(), j.at(2).get<uint64_t>(),
          j.at(3).get<uint64_t>(), j.at(4).get<uint64_t>(), j.at(5).get<uint64_t>(),
          j.at(6).get<uint64_t>(), j.at(7).get<double>(),   j.at(8).get<bool>()};
}

Result<ShardSummary> parseSummary(const fs::path& path) {
  auto bytes = transport::readWholeFile(path, uint64_t{1} << 30);
  if (!bytes) return Error{bytes.error()};
  try {
    const auto j =
        nlohmann::json::parse(reinterpret_cast<const char*>(bytes->data()),
                              reinterpret_cast<const char*>(bytes->data()) + bytes->size());
    ShardSummary s;
    s.index = j.at("shard").get<uint32_t>();
    s.count = j.at("shards").get<uint32_t>();
    s.level = j.at("shardLevel").get<uint32_t>();
    s.planFingerprint = j.at("plan").get<std::string>();
    for (const auto& p : j.at("packs")) {
      PackSummary summary;
      const formats::PackId id{p.at(0).get<uint32_t>(), p.at(1).get<uint32_t>(),
                               p.at(2).get<uint32_t>()};
      summary.tiles = p.at(3).get<uint64_t>();
      summary.bounds = {p.at(4).get<double>(), p.at(5).get<double>(), p.at(6).get<double>(),
                        p.at(7).get<double>()};
      summary.range = {p.at(8).get<int16_t>(), p.at(9).get<int16_t>()};
      summary.indexBytes = p.at(10).get<uint32_t>();
      s.packs.emplace_back(id, summary);
    }
    for (const auto& c : j.at("conditioning")) {
      s.conditioning.emplace_back(c.at(0).get<size_t>(), conditioningOf(c.at(1)));
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    return makeError(path.string() + ": not a shard summary: " + e.what());
  }
}

}  // namespace

fs::path shardFolder(const fs::path& outputDir) { return outputDir / "shards"; }

Result<void> writeSampleFragment(const fs::path& outputDir, const formats::PackId& pack,
                                 uint32_t shardIndex, uint32_t positionsPerTile,
                                 std::vector<SampleRecord> records) {
  std::sort(records.begin(), records.end(), [](const SampleRecord& a, const SampleRecord& b) {
    return a.slot != b.slot ? a.slot < b.slot : a.index < b.index;
  });
  std::vector<std::byte> bytes;
  bytes.reserve(kFragmentHeaderBytes + records.size() * kRecordBytes);
  for (char c : kFragmentMagic) bytes.push_back(static_cast<std::byte>(c));
  putLittle(bytes, positionsPerTile, 4);
  putLittle(bytes, records.size(), 8);
  for (const SampleRecord& r : records) {
    putLittle(bytes, r.slot, 4);
    putLittle(bytes, r.index, 4);
    putLittle(bytes, static_cast<uint16_t>(r.heightCode), 2);
  }
  const fs::path folder = fragmentFolder(outputDir, pack);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) return makeError(folder.string() + ": cannot create: " + error.message());
  if (auto written =
          transport::writeFileAtomically(folder / (std::to_string(shardIndex) + ".bin"), bytes);
      !written) {
    return writeFailed(written.error());
  }
  return {};
}

Result<void> readSampleFragments(const fs::path& outputDir, const formats::PackId& pack,
                                 uint32_t positionsPerTile, SampleTable& table) {
  const fs::path folder = fragmentFolder(outputDir, pack);
  std::error_code error;
  if (!fs::exists(folder, error)) return {};
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.path().extension() == ".bin") files.push_back(entry.path());
  }
  if (error) return makeError(folder.string() + ": cannot list: " + error.message());
  for (const fs::path& file : files) {
    auto bytes = transport::readWholeFile(file, kMaxFragmentBytes);
    if (!bytes) return Error{bytes.error()};
    const std::byte* p = bytes->data();
    if (bytes->size() < kFragmentHeaderBytes || std::memcmp(p, kFragmentMagic, 8) != 0 ||
        getLittle(p + 8, 4) != positionsPerTile) {
      return makeError(file.string() + ": not a sample fragment of this pyramid");
    }
    const uint64_t count = getLittle(p + 12, 8);
    if (bytes->size() != kFragmentHeaderBytes + count * kRecordBytes) {
      return makeError(file.string() + ": truncated sample fragment");
    }
    for (uint64_t i = 0; i < count; ++i) {
      const std::byte* r = p + kFragmentHeaderBytes + i * kRecordBytes;
      const auto value = static_cast<int16_t>(static_cast<uint16_t>(getLittle(r + 8, 2)));
      if (!table.set(getLittle(r, 4), static_cast<uint32_t>(getLittle(r + 4, 4)), value)) {
        return makeError(file.string() + ": a sample outside the pack");
      }
    }
  }
  return {};
}

Result<void> writeShardSummary(const fs::path& outputDir, const ShardSummary& summary) {
  nlohmann::json packs = nlohmann::json::array();
  for (const auto& [id, s] : summary.packs) {
    packs.push_back({id.level, id.x, id.y, s.tiles, s.bounds.west, s.bounds.south, s.bounds.east,
                     s.bounds.north, s.range.minimumMeters, s.range.maximumMeters, s.indexBytes});
  }
  nlohmann::json conditioning = nlohmann::json::array();
  for (const auto& [source, c] : summary.conditioning) {
    conditioning.push_back({source, conditioningJson(c)});
  }
  const nlohmann::json j = {
      {"shard", summary.index},          {"shards", summary.count}, {"shardLevel", summary.level},
      {"plan", summary.planFingerprint}, {"packs", packs},          {"conditioning", conditioning}};
  std::error_code error;
  fs::create_directories(shardFolder(outputDir), error);
  if (error)
    return makeError(shardFolder(outputDir).string() + ": cannot create: " + error.message());
  if (auto written = transport::writeFileAtomically(
          summaryPath(outputDir, summary.index, summary.count), j.dump() + "\n");
      !written) {
    return writeFailed(written.error());
  }
  return {};
}

Result<std::vector<ShardSummary>> readShardSummaries(const fs::path& outputDir,
                                                     const std::string& planFingerprint) {
  const fs::path folder = shardFolder(outputDir);
  std::error_code error;
  std::map<std::string, fs::path> found;
  if (fs::is_directory(folder, error)) {
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      const std::string name = entry.path().filename().string();
      if (name.find("-of-") != std::string::npos && entry.path().extension() == kSummarySuffix) {
        found.emplace(name, entry.path());
      }
    }
  }
  if (found.empty()) {
    return makeError(folder.string() +
                     ": no finished shard: run globe-tiler --shard K/N for every K first");
  }
  auto first = parseSummary(found.begin()->second);
  if (!first) return Error{first.error()};
  const uint32_t count = first->count;
  std::vector<ShardSummary> summaries;
  for (uint32_t k = 0; k < count; ++k) {
    const fs::path path = summaryPath(outputDir, k, count);
    if (!fs::exists(path, error)) {
      return makeError("shard " + std::to_string(k) + "/" + std::to_string(count) +
                       " has not finished (no " + path.string() + "): run it, then merge");
    }
    auto summary = parseSummary(path);
    if (!summary) return Error{summary.error()};
    if (summary->index != k || summary->count != count || summary->level != first->level) {
      return makeError(path.string() + ": disagrees with the other shards (shard count or level)");
    }
    if (summary->planFingerprint != planFingerprint) {
      return makeError(path.string() + ": made from other inputs or options than this merge");
    }
    summaries.push_back(std::move(*summary));
  }
  for (const auto& [name, path] : found) {
    if (name.find("-of-" + std::to_string(count) + kSummarySuffix) == std::string::npos) {
      return makeError(path.string() + ": a shard of another shard count (" +
                       std::to_string(count) + " expected): remove it");
    }
  }
  return summaries;
}

}  // namespace globe::tiling
