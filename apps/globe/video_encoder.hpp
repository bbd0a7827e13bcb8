// Encoding `globe play`'s PNG frames into a video with the ffmpeg program, when it is installed.
#pragma once

#include <filesystem>
#include <optional>

#include "core/result.hpp"

namespace globe::app {

// The executable's full path found on $PATH, or nullopt.
std::optional<std::filesystem::path> findExecutable(const std::string& name);

// Runs `ffmpeg -y -loglevel error -framerate FPS -i FRAMES/%05d.png -vf pad=even -pix_fmt yuv420p`
// into a temporary file next to `output` and renames it over `output` when ffmpeg succeeds (no
// half-written video otherwise). Errors: no ffmpeg on $PATH, ffmpeg failing (its exit status).
Result<void> encodeVideo(const std::filesystem::path& ffmpeg,
                         const std::filesystem::path& framesDir, double framesPerSecond,
                         const std::filesystem::path& output);

}  // namespace globe::app
