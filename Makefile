# Lagoon: the README's two commands.
#   make run   installs what is missing, builds (Release), renders scenes/default.json to out/default.png
#   make test  the same set-up, then the whole test suite (ctest) on lavapipe with validation on
# Other targets: build, update-golden (rewrite tests/golden/*.png from the current renderer), update-docs
# (regenerate the field table of docs/scene-format.md), fuzz (every libFuzzer target for FUZZ_SECONDS each,
# default 60; docs/fuzzing.md), test-sanitize (ASan + UBSan build, unit/CLI/GPU suites; docs/sanitizers.md),
# format, clean.
BUILD_DIR ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: run test build deps configure update-golden update-docs fuzz test-sanitize format clean

run: build
	./$(BUILD_DIR)/bin/lagoon render --scene scenes/default.json --out out/default.png

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

configure: deps
	cmake -S . -B $(BUILD_DIR) $(CMAKE_FLAGS)

deps:
	@bash tools/install-deps.sh

# Renders every golden image again and overwrites tests/golden/. Review the new images (git diff) before committing.
update-golden: build
	cd $(BUILD_DIR) && LAGOON_UPDATE_GOLDEN=1 ctest -L render --output-on-failure -j $(JOBS)

# Rewrites the generated field table in docs/scene-format.md from the scene loader's field declarations.
update-docs: build
	LAGOON_UPDATE_DOCS=1 ./$(BUILD_DIR)/tests/unit_tests --gtest_filter=SceneRepository.DocsFieldReferenceIsUpToDate

# Runs every fuzz target for FUZZ_SECONDS (default 60) each; crashes land in build-fuzz/crashes/.
FUZZ_SECONDS ?= 60
fuzz: deps
	bash tools/fuzz.sh $(FUZZ_SECONDS)

# Builds with AddressSanitizer + UndefinedBehaviorSanitizer in build-sanitize/ and runs the unit, CLI and GPU
# suites on lavapipe; any sanitizer report fails the run.
test-sanitize: deps
	bash tools/test-sanitize.sh

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf $(BUILD_DIR) build-fuzz build-sanitize out
