// The tiler on a disk that fills up for real: a small tmpfs (mounted in a private mount namespace,
// so a dying test leaks no mount) with a filler file leaving N pages free, and, unprivileged, a
// file-size limit (RLIMIT_FSIZE, write fails with EFBIG). Each run must fail with the file and the
// reason, leave only complete packs and no temporaries, and a re-run with space must give the
// same bytes as an uninterrupted run.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;
using Sums = std::map<std::string, std::pair<uint32_t, size_t>>;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Exit {
  int code = 0;
  std::string stderrText;
};

// Runs argv with stdout discarded and stderr read through a pipe (a file would be cut short by the
// RLIMIT_FSIZE under test); `inChild` runs before exec.
template <class Setup>
Exit runProgram(std::vector<std::string> args, Setup inChild) {
  int pipeFds[2];
  if (::pipe(pipeFds) != 0) return {-1, "pipe failed"};
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDOUT_FILENO);
    ::dup2(pipeFds[1], STDERR_FILENO);
    ::close(pipeFds[0]);
    inChild();
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(pipeFds[1]);
  Exit result;
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipeFds[0], buffer, sizeof buffer)) != 0;) {
    if (n > 0) result.stderrText.append(buffer, static_cast<size_t>(n));
    if (n < 0 && errno != EINTR) break;
  }
  ::close(pipeFds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::vector<std::string> tilerArgs(const fs::path& out) {
  std::vector<std::string> args = {GLOBE_TILER_EXE, "-q", "-o", out.string()};
  for (const std::string& input : globe::testing::bundledInputs()) args.push_back(input);
  return args;
}

// tmpfs allocates whole pages
uint64_t pages(uint64_t bytes) {
  const auto page = static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
  return (bytes + page - 1) / page;
}

// What one failed run left: checked against the uninterrupted run's files.
struct Aftermath {
  std::string failedFile;  // the file the message names, relative to the pyramid
  size_t packs = 0;        // complete packs left
};

// The run failed with "globe-tiler: <pyramid>/<file>: <step> failed: <reason>" and left nothing
// half-written: every file under its final name is byte-identical to the reference, there is no
// manifest (it is written last) and no temporary.
Aftermath expectCleanFailure(int exitCode, const std::string& message, const fs::path& seenAs,
                             const fs::path& left, const Sums& reference, const char* reason) {
  Aftermath after;
  EXPECT_EQ(exitCode, 1) << message;
  const std::string prefix = "globe-tiler: " + seenAs.string() + "/";
  EXPECT_EQ(message.rfind(prefix, 0), 0U) << message;
  EXPECT_NE(message.find(std::string(" failed: ") + reason), std::string::npos) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << "one message: " << message;
  if (message.rfind(prefix, 0) == 0) {
    after.failedFile =
        message.substr(prefix.size(), message.find(':', prefix.size()) - prefix.size());
  }
  EXPECT_TRUE(after.failedFile.ends_with(".pack") || after.failedFile == "manifest.json" ||
              after.failedFile == "tiling-plan.json")
      << message;
  EXPECT_FALSE(fs::exists(left / formats::kManifestFileName));
  for (const auto& [name, sum] : globe::testing::checksums(left)) {
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "temporary left: " << name;
    const auto expected = reference.find(name);
    if (expected == reference.end()) {
      ADD_FAILURE() << "unexpected file " << name;
      continue;
    }
    EXPECT_EQ(sum, expected->second) << name << " differs from an uninterrupted run's";
    if (name.ends_with(".pack")) {
      auto bytes = transport::readWholeFile(left / name, 1ULL << 32);
      EXPECT_TRUE(bytes) << bytes.error();
      auto pack = bytes ? formats::decodePack(*bytes, left / name)
                        : Result<formats::Pack>(Error{bytes.error()});
      EXPECT_TRUE(pack) << pack.error();  // CRC and layout checked
      ++after.packs;
    }
  }
  return after;
}

struct Fixture {
  Sums reference = globe::testing::checksums(globe::testing::bundledPyramid());
  uint64_t pagesBeforeManifest = 0;  // every file of the pyramid but the manifest
  uint64_t packs = 0;
  Fixture() {
    for (const auto& [name, sum] : reference) {
      if (name != formats::kManifestFileName) pagesBeforeManifest += pages(sum.second);
      packs += name.ends_with(".pack") ? 1 : 0;
    }
  }
};

// Mounts a 64 MiB tmpfs at $1 in this (private) mount namespace, leaves $2 pages free with a
// filler, runs the tiler into it, copies what it left to $3, deletes the filler, runs the tiler
// again and copies the result to $4. Logs and exit codes go to $5.
constexpr const char* kTmpfsScript = R"sh(
M=$1 FREE=$2 AFTER=$3 FINAL=$4 LOG=$5; shift 5
mount -t tmpfs -o size=64m globe-test "$M" 2>"$LOG/mount.err" || exit 90
avail=$(stat -f -c %a "$M")
head -c $(( (avail - FREE) * $(stat -f -c %S "$M") )) /dev/zero > "$M/filler" || exit 91
[ "$(stat -f -c %a "$M")" -eq "$FREE" ] || exit 92
"$@" -o "$M/pyramid" >/dev/null 2>"$LOG/first.err"; echo $? > "$LOG/first.rc"
mkdir -p "$M/pyramid" && cp -a "$M/pyramid" "$AFTER" || exit 93
rm "$M/filler"
"$@" -o "$M/pyramid" >/dev/null 2>"$LOG/second.err"; echo $? > "$LOG/second.rc"
cp -a "$M/pyramid" "$FINAL" || exit 94
)sh";

TEST(TilerFullDisk, TmpfsFillingUpAtThePlanInPacksAndAtTheManifest) {
  const Fixture fixture;
  ASSERT_GT(fixture.packs, 20U);
  // Free pages when the run starts: none (the plan fails), one (the plan fits, the first pack
  // runs out mid-write), half the pyramid (a pack of a coarser level runs out), all but the
  // manifest's last page (the manifest runs out mid-write).
  const uint64_t all = fixture.pagesBeforeManifest;
  const std::vector<std::pair<uint64_t, std::string>> levels = {
      {0, "tiling-plan.json"}, {1, ".pack"}, {all / 2, ".pack"}, {all + 1, "manifest.json"}};
  const fs::path scratch = globe::testing::freshTempDir("full-tmpfs");
  for (const auto& [freePages, failing] : levels) {
    SCOPED_TRACE(std::to_string(freePages) + " pages free");
    const fs::path run = scratch / std::to_string(freePages);
    const fs::path mount = run / "mnt", after = run / "after", final = run / "final";
    fs::create_directories(mount);
    std::vector<std::string> args = {"unshare",
                                     "--mount",
                                     "--propagation",
                                     "private",
                                     "sh",
                                     "-c",
                                     kTmpfsScript,
                                     "sh",
                                     mount.string(),
                                     std::to_string(freePages),
                                     after.string(),
                                     final.string(),
                                     run.string()};
    // The tiler's command without its -o: the script adds the tmpfs output.
    std::vector<std::string> tiler = tilerArgs("");
    tiler.erase(tiler.begin() + 2, tiler.begin() + 4);
    args.insert(args.end(), tiler.begin(), tiler.end());
    const Exit script = runProgram(args, [] {});
    if (!fs::exists(run / "first.rc")) {
      // Never a silent pass: say why, and the RLIMIT_FSIZE test below still covers the fault.
      GTEST_SKIP() << "cannot mount a tmpfs here (exit " << script.code
                   << "): " << script.stderrText << readText(run / "mount.err");
    }
    ASSERT_EQ(script.code, 0) << "the script failed at step " << script.code << ": "
                              << script.stderrText;
    const Aftermath left =
        expectCleanFailure(std::stoi(readText(run / "first.rc")), readText(run / "first.err"),
                           mount / "pyramid", after, fixture.reference, "No space left on device");
    EXPECT_TRUE(left.failedFile.ends_with(failing)) << left.failedFile;
    if (failing == ".pack") {
      EXPECT_LT(left.packs, fixture.packs);
    } else if (failing == "manifest.json") {
      EXPECT_EQ(left.packs, fixture.packs);
    }
    std::printf("[ tmpfs    ] %5llu of %llu pages free: failed at %s, %zu complete packs left\n",
                static_cast<unsigned long long>(freePages), static_cast<unsigned long long>(all),
                left.failedFile.c_str(), left.packs);

    EXPECT_EQ(readText(run / "second.rc"), "0\n") << readText(run / "second.err");
    EXPECT_EQ(globe::testing::checksums(final), fixture.reference) << "the resumed run differs";
    fs::remove_all(run);
  }
}

TEST(TilerFullDisk, FileSizeLimitAtThePlanAndInPacks) {
  const Fixture fixture;
  // Per-file limits: under the plan's size, and under the largest packs of the finest level (the
  // first level built, so the smaller packs of that level may be complete).
  const std::vector<std::pair<rlim_t, std::string>> limits = {{100, "tiling-plan.json"},
                                                              {1 << 19, "L14/"}};
  const fs::path scratch = globe::testing::freshTempDir("full-rlimit");
  for (const auto& [limit, failing] : limits) {
    SCOPED_TRACE("RLIMIT_FSIZE " + std::to_string(limit));
    const fs::path out = scratch / std::to_string(limit) / "pyramid";
    fs::create_directories(out.parent_path());
    const Exit first = runProgram(tilerArgs(out), [limit] {
      ::signal(SIGXFSZ, SIG_IGN);  // write then fails with EFBIG instead of killing
      const rlimit fileSize{limit, limit};
      if (::setrlimit(RLIMIT_FSIZE, &fileSize) != 0) ::_exit(126);
    });
    const Aftermath left = expectCleanFailure(first.code, first.stderrText, out, out,
                                              fixture.reference, "File too large");
    EXPECT_NE(left.failedFile.find(failing), std::string::npos) << left.failedFile;
    std::printf("[ rlimit   ] %8llu bytes per file: failed at %s, %zu complete packs left\n",
                static_cast<unsigned long long>(limit), left.failedFile.c_str(), left.packs);

    const Exit second = runProgram(tilerArgs(out), [] {});
    EXPECT_EQ(second.code, 0) << second.stderrText;
    EXPECT_EQ(globe::testing::checksums(out), fixture.reference) << "the resumed run differs";
    fs::remove_all(out.parent_path());
  }
}

}  // namespace
}  // namespace globe::tiling
