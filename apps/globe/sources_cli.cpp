// `globe sources [--json]`: the named sources a user can give by name (presets and their own
// sources.toml), and where that file is.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

const char* kindName(services::SourceKind kind) {
  return kind == services::SourceKind::Terrain ? "terrain" : "imagery";
}

int runSourcesCommand(bool json, const CommonArguments& common) {
  const services::NamedSources& sources = *common.sources;
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const services::NamedSource& s : sources.sources) {
      list.push_back({{"name", s.name},
                      {"kind", kindName(s.kind)},
                      {"url", s.url},
                      {"attribution", s.attribution},
                      {"description", s.description},
                      {"preset", s.preset}});
    }
    const nlohmann::json out{
        {"file", sources.file.string()}, {"fileRead", sources.fileRead}, {"sources", list}};
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf("named sources: `globe view NAME --layer NAME`; yours in %s (%s)\n\n",
              sources.file.string().c_str(), sources.fileRead ? "read" : "none there");
  for (const services::NamedSource& s : sources.sources) {
    std::printf("%-14s %-8s %s%s\n", s.name.c_str(), kindName(s.kind), s.url.c_str(),
                s.preset ? "" : "  (yours)");
    if (!s.description.empty()) std::printf("%-23s %s\n", "", s.description.c_str());
    if (!s.attribution.empty()) std::printf("%-23s from: %s\n", "", s.attribution.c_str());
  }
  return 0;
}

}  // namespace

Subcommand addSourcesCommand(CLI::App& app, CommonArguments& common) {
  CLI::App* sources = app.add_subcommand(
      "sources", "list the terrain and imagery sources you can give by name (presets and yours)");
  auto json = std::make_shared<bool>(false);
  sources->add_flag("--json", *json, "machine-readable output");
  return {sources,
          [json, &common](const CommandContext&) { return runSourcesCommand(*json, common); }};
}

}  // namespace globe::app
