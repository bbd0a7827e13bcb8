// Fixtures made once per CTest run and shared by every test process that asks for them: the
// bundled pyramid, the imagery layers, the water mask. Each GoogleTest suite runs in a process of
// its own (cmake/GlobeTestGroupsScript.cmake), so a fixture kept in a static would be rebuilt by
// every suite that asks.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace globe::testing {

// The directory `build` filled for `key`. Under CTest (GLOBE_TEST_FIXTURES names a folder that
// the run's setup test empties first and its cleanup test removes last: tests/CMakeLists.txt)
// the first process to ask builds it under a lock while the others wait, into a temporary name
// renamed when `build` returns true; a failed or killed build leaves nothing, and the next asker
// builds again. Without GLOBE_TEST_FIXTURES (a test binary run by hand) each process builds its
// own in a fresh temporary directory. `key` may be any text: it names the folder through a hash.
std::filesystem::path sharedFixture(const std::string& key,
                                    const std::function<bool(const std::filesystem::path&)>& build);

}  // namespace globe::testing
