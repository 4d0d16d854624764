# Entry points for people and CI. `make demo` and `make test` each do all the set-up on a fresh
# Debian 12 machine (install-deps is idempotent).
JOBS ?= $(shell nproc)
PRESET ?= release
BUILD_DIR = build

.PHONY: deps configure build test demo asan bench bench-peers clean

deps:
	./scripts/install-deps

configure: deps
	cmake --preset $(PRESET)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD_DIR) -j $(JOBS) --output-on-failure --timeout 300

demo: build
	$(BUILD_DIR)/bin/ssimarch demo --out out/demo

asan: deps
	cmake --preset dev
	cmake --build build-asan -j $(JOBS)
	ctest --test-dir build-asan -j $(JOBS) --output-on-failure --timeout 1200

bench: deps
	cmake --preset bench
	cmake --build build-bench -j $(JOBS)
	./bench/run-benchmarks

# Side-by-side with OpenCASCADE and SISL (docs/benchmarks.md, "Peers"): an optional build of its own.
bench-peers:
	./scripts/install-deps --peers
	cmake -S . -B build-peers -G Ninja -DCMAKE_BUILD_TYPE=Release -DSSIMARCH_BUILD_TESTS=OFF -DSSIMARCH_BENCH_PEERS=ON
	cmake --build build-peers -j $(JOBS) --target peer_bench
	build-peers/bench/peers/peer_bench --reps 7

clean:
	rm -rf build build-asan build-bench build-peers out
