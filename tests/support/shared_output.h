// Output that several tests compare against and none changes (a reference render, one process's dataset),
// made once per build instead of once per test process. ctest runs each TEST as its own process, so a
// gtest SetUpTestSuite would make it again in every one of them.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

namespace lagoon::test {

// The folder holding what `make` wrote into it for `key`. The first test that asks runs `make` (into a
// fresh folder of the build tree's test artifacts); one asking while that runs waits for it (a file lock);
// later ones reuse it. `key` must name everything the output depends on (the command line, its inputs); the
// built `lagoon`'s size and modification time and the contents of scenes/ are added, so a rebuilt command
// makes it anew. When `make` fails (returns false, or an assertion inside it fails) the folder is not kept
// and the next test tries again; empty is returned.
std::filesystem::path shared_output(const std::string& key,
                                    const std::function<bool(const std::filesystem::path&)>& make);

}  // namespace lagoon::test
