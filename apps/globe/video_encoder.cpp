// ffmpeg found on $PATH and run without a shell (posix_spawn), writing to a temporary name.
#include "apps/globe/video_encoder.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

extern char** environ;

namespace globe::app {

std::optional<std::filesystem::path> findExecutable(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  const std::string directories = path;
  size_t start = 0;
  for (;;) {
    const size_t end = directories.find(':', start);
    const std::string dir = directories.substr(start, end - start);
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) {
      return candidate;
    }
    if (end == std::string::npos) return std::nullopt;
    start = end + 1;
  }
}

std::optional<VideoCodec> parseVideoCodec(std::string_view text) {
  if (text == "h264") return VideoCodec::H264;
  if (text == "h265") return VideoCodec::H265;
  if (text == "prores") return VideoCodec::ProRes;
  return std::nullopt;
}

std::vector<std::string> videoCodecArguments(const VideoSettings& settings) {
  const std::string crf = std::to_string(settings.crf);
  switch (settings.codec) {
    case VideoCodec::H265:
      return {"-c:v", "libx265", "-crf", crf, "-tag:v", "hvc1", "-pix_fmt", "yuv420p", "-f", "mp4"};
    case VideoCodec::ProRes:
      return {"-c:v", "prores_ks", "-profile:v", "3", "-pix_fmt", "yuv422p10le", "-f", "mov"};
    case VideoCodec::H264:
      break;
  }
  return {"-c:v", "libx264", "-crf", crf, "-pix_fmt", "yuv420p", "-f", "mp4"};
}

Result<void> encodeVideo(const std::filesystem::path& ffmpeg,
                         const std::filesystem::path& framesDir, double framesPerSecond,
                         const std::filesystem::path& output, const VideoSettings& settings) {
  const std::filesystem::path temp = output.string() + ".tmp-" + std::to_string(::getpid());
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.9g", framesPerSecond);
  std::vector<std::string> arguments = {ffmpeg.string(),
                                        "-y",
                                        "-loglevel",
                                        "error",
                                        "-framerate",
                                        rate,
                                        "-i",
                                        (framesDir / "%05d.png").string(),
                                        "-vf",
                                        "pad=ceil(iw/2)*2:ceil(ih/2)*2"};
  for (std::string& argument : videoCodecArguments(settings)) arguments.push_back(argument);
  arguments.push_back(temp.string());
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (const int err = ::posix_spawn(&pid, ffmpeg.c_str(), nullptr, nullptr, argv.data(), environ);
      err != 0) {
    return makeError("cannot run " + ffmpeg.string() + ": " + std::generic_category().message(err));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return makeError("waiting for ffmpeg failed");
  }
  std::error_code ignored;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(temp, ignored);
    return makeError("ffmpeg failed (exit status " +
                     std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ") encoding " +
                     output.string());
  }
  std::error_code renamed;
  std::filesystem::rename(temp, output, renamed);
  if (renamed) {
    std::filesystem::remove(temp, ignored);
    return makeError(output.string() + ": rename failed: " + renamed.message());
  }
  return {};
}

}  // namespace globe::app
