# Lagoon: the README's two commands.
#   make run   installs what the `lagoon` command needs, builds only it (Release), renders scenes/default.json
#              to out/default.png
#   make test  installs the rest (demo, tests, fuzzers), builds everything, runs the whole suite (ctest) on
#              lavapipe with validation on
# Other targets: build (everything), test-costs (keep the last run's test times as ctest's seed),
# update-golden (rewrite tests/golden/*.png from the current renderer), update-docs (regenerate the field table
# of docs/scene-format.md), fuzz (every libFuzzer target for FUZZ_SECONDS each, default 60; docs/fuzzing.md),
# test-sanitize (ASan + UBSan build, unit/CLI/GPU suites; docs/sanitizers.md), format, clean.
# docs/building.md has the details and the measured times.
BUILD_DIR ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
# Ninja starts a module's sources as soon as their headers exist (Make waits for whole libraries) and prints
# [built/total] as it goes.
GENERATOR ?= Ninja
# A build folder keeps the generator it was made with (cmake refuses to switch).
generator_flag = $(if $(wildcard $(BUILD_DIR)/CMakeCache.txt),,-G $(GENERATOR))
say = @printf '\n==> %s\n' $(1)

.PHONY: run test build deps deps-run configure configure-run test-costs update-golden update-docs fuzz \
        test-sanitize format clean

run: deps-run configure-run
	$(call say,"building the lagoon command (ninja prints [built/total] steps)")
	cmake --build $(BUILD_DIR) --target lagoon -j $(JOBS)
	$(call say,"rendering scenes/default.json (the first run compiles the shaders it uses)")
	./$(BUILD_DIR)/bin/lagoon render --scene scenes/default.json --out out/default.png

test: build
	$(call say,"running the test suite: ctest -j $(JOBS) (the longest tests start first)")
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

build: configure
	$(call say,"building everything: the command + the demo + the tests + the fuzz targets")
	cmake --build $(BUILD_DIR) -j $(JOBS)

deps:
	$(call say,"checking the Debian packages (tools/install-deps.sh all)")
	@bash tools/install-deps.sh all

deps-run:
	$(call say,"checking the Debian packages the command needs (tools/install-deps.sh run)")
	@bash tools/install-deps.sh run

# Everything on (tests, demo, benchmarks); an existing build folder keeps its objects.
configure: deps
	$(call say,"configuring $(BUILD_DIR)/ with everything")
	cmake -S . -B $(BUILD_DIR) $(generator_flag) $(CMAKE_FLAGS) -DLAGOON_BUILD_TESTS=ON -DLAGOON_BUILD_DEMO=ON \
	  -DLAGOON_BUILD_BENCHMARKS=ON -DLAGOON_BUILD_PYTHON=ON

# A new build folder gets the command alone (install-deps.sh run has not installed what the rest needs); one
# configured before keeps its settings.
configure-run: deps-run
	@if [ -f $(BUILD_DIR)/CMakeCache.txt ]; then echo "configured already: $(BUILD_DIR)/"; else \
	  printf '\n==> %s\n' "configuring $(BUILD_DIR)/ for the lagoon command"; \
	  cmake -S . -B $(BUILD_DIR) -G $(GENERATOR) $(CMAKE_FLAGS) -DLAGOON_BUILD_TESTS=OFF -DLAGOON_BUILD_DEMO=OFF \
	    -DLAGOON_BUILD_BENCHMARKS=OFF -DLAGOON_BUILD_PYTHON=OFF; fi

# Keeps the last run's test costs (build/Testing/Temporary/CTestCostData.txt) as the seed of new build folders,
# so ctest starts the long tests first from the first run on (tests/CMakeLists.txt).
test-costs:
	cd $(BUILD_DIR) && ctest -N | sed -n 's/^ *Test *#[0-9]*: //p' > Testing/Temporary/names.txt
	awk 'NR == FNR { known[$$1] = 1; next } $$1 == "---" { exit } NF == 3 && ($$1 in known) && $$3 > cost[$$1] \
	  { cost[$$1] = $$3 } END { for (t in cost) print t, 1, cost[t] }' $(BUILD_DIR)/Testing/Temporary/names.txt \
	  $(BUILD_DIR)/Testing/Temporary/CTestCostData.txt | sort > tests/test-costs.txt

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
