// Encoding `globe play`'s PNG frames into a video with the ffmpeg program, when it is installed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"

namespace globe::app {

// The executable's full path found on $PATH, or nullopt.
std::optional<std::filesystem::path> findExecutable(const std::string& name);

// --codec and --crf: H.264 or H.265 (libx264, libx265; 4:2:0, MP4; crf 0..51, lower is better,
// 18 by default: visually lossless) or Apple ProRes 422 HQ (prores_ks, 10-bit 4:2:2, QuickTime;
// no crf).
enum class VideoCodec { H264, H265, ProRes };
struct VideoSettings {
  VideoCodec codec = VideoCodec::H264;
  int crf = 18;
};
std::optional<VideoCodec> parseVideoCodec(std::string_view text);  // h264 | h265 | prores

// ffmpeg's arguments after its input: the codec, its quality, pixel format and container.
std::vector<std::string> videoCodecArguments(const VideoSettings& settings);

// Runs `ffmpeg -y -loglevel error -framerate FPS -i FRAMES/%05d.png -vf pad=even` and the codec's
// arguments into a temporary file next to `output` and renames it over `output` when ffmpeg
// succeeds (no half-written video otherwise). Errors: no ffmpeg on $PATH, ffmpeg failing (its
// exit status).
Result<void> encodeVideo(const std::filesystem::path& ffmpeg,
                         const std::filesystem::path& framesDir, double framesPerSecond,
                         const std::filesystem::path& output, const VideoSettings& settings = {});

}  // namespace globe::app
