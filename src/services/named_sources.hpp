// Sources a user calls by name (`globe view aws-terrain --layer osm`): presets for the open
// services people use, and the user's own in a TOML file in the XDG config directory
// ($XDG_CONFIG_HOME/globe/sources.toml, else ~/.config/globe/sources.toml), one table each:
//
//   [my-imagery]
//   kind = "imagery"                 # or "terrain"
//   url = "xyz:https://tiles.example/{z}/{x}/{y}.png?maxzoom=17"
//   attribution = "© Example"        # optional
//   description = "what it is"       # optional
//
// A table with a preset's name replaces the preset.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::services {

enum class SourceKind { Terrain, Imagery };

struct NamedSource {
  std::string name;
  SourceKind kind = SourceKind::Imagery;
  std::string url;  // a terrain or imagery argument (quantized-mesh:, xyz:, a directory, ...)
  std::string attribution;
  std::string description;
  bool preset = false;
};

struct NamedSources {
  std::vector<NamedSource> sources;  // presets first, then the file's, by name within each
  std::filesystem::path file;        // the user's file, whether or not it exists
  bool fileRead = false;
};

std::vector<NamedSource> presetSources();
// $XDG_CONFIG_HOME/globe/sources.toml, else $HOME/.config/globe/sources.toml.
std::filesystem::path userSourcesFile();
// The presets and `file`'s sources (a missing file is no error; a malformed one is, naming the
// file, line and problem).
Result<NamedSources> loadNamedSources(const std::filesystem::path& file);

// What `text` names: nullopt when it is no source's name (a path or URL); an error when it names
// a source of the other kind.
Result<std::optional<NamedSource>> findNamedSource(const NamedSources& sources,
                                                   const std::string& text, SourceKind kind);

}  // namespace globe::services
