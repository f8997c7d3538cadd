# The two commands of the README: `make run` (the main job) and `make test` (all tests).
# Both install missing Debian packages (packaging/install_deps.sh), configure and build.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CMAKE_ARGS ?=

.PHONY: deps configure build test run models bench clean

deps:
	@bash packaging/install_deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) > $(BUILD_DIR).configure.log 2>&1 \
	  || (cat $(BUILD_DIR).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@cd $(BUILD_DIR) && ctest -j $(JOBS) --output-on-failure --timeout 900

run: build
	@bash packaging/run_main.sh $(BUILD_DIR)

models: build
	@$(BUILD_DIR)/sagrid train --preset default --out resources/models

bench: build
	@for b in $(BUILD_DIR)/tests/benchmarks/*_bench; do $$b --benchmark_repetitions=5 --benchmark_report_aggregates_only=true; done

clean:
	@rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log
