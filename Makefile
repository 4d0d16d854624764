# Entry points for people and CI. `make demo` and `make test` each do all the set-up on a fresh
# Debian 12 machine (install-deps is idempotent).
JOBS ?= $(shell nproc)
PRESET ?= release
BUILD_DIR = build

.PHONY: deps configure build test demo asan asan-fast fuzz bench bench-peers clean

deps:
	./scripts/install-deps

configure: deps
	cmake --preset $(PRESET)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD_DIR) -j $(JOBS) --output-on-failure --timeout 300

# The demo builds what it runs, the CLI with the viewer's script, and nothing else (issue 29: `make
# demo` built all 299 targets first); `make test` builds the rest, the Python module included. Its
# packages are the demo's own (`install-deps --demo`: no Chromium, VTK, OpenMPI or clang-format)
# but include pybind11 and numpy, so that the configure step finds the Python module as `make test`'s
# will (an option left off in the cache would stay off).
demo:
	./scripts/install-deps --demo
	cmake --preset $(PRESET)
	cmake --build $(BUILD_DIR) -j $(JOBS) --target ssimarch_cli
	$(BUILD_DIR)/bin/ssimarch demo --out out/demo

asan: deps
	cmake --preset dev
	cmake --build build-asan -j $(JOBS)
	ctest --test-dir build-asan -j $(JOBS) --output-on-failure --timeout 1200

# The CI sanitizer job (docs/reliability.md, "Sanitizer job"): ASan + UBSan + float-cast-overflow on
# the tests of a tier of modules. ASAN_TIER=core (the default, what .ci/run runs): core and expr, the
# expression compiler every user formula goes through; it fits CI's 25-minute budget beside `make
# test`. ASAN_TIER=wide adds surface, problem, march (with the libraries march's tests link: geometry,
# singular, start, trace) and the porosity kernels and packing readers; measured, it does not fit beside
# `make test`. The whole suite under the sanitizers is `make asan`.
ASAN_TIER ?= core
ASAN_TARGETS_core = core_tests expr_tests
ASAN_TARGETS_wide = $(ASAN_TARGETS_core) surface_tests problem_tests march_tests porosity_kernel_test \
                    porosity_integrals_test porosity_packing_test
asan-fast: deps
	cmake --preset asan-fast
	cmake --build build-asan-fast -j $(JOBS) --target $(ASAN_TARGETS_$(ASAN_TIER))
	# Tests of the tier only (the others are *_NOT_BUILT). Excluded: the stack-depth bound of the
	# expression parser, a property of the optimised build (ASan's redzones enlarge every stack frame).
	ctest --test-dir build-asan-fast -j $(JOBS) --output-on-failure --timeout 600 \
	  -E '^(layers|layers_self_test|ExprErrors.DeepestAcceptedExpressionsFitInASmallStack)$$|_NOT_BUILT$$'

# libFuzzer targets (clang 14; docs/reliability.md): builds build-fuzz/bin/fuzz_*; FUZZ_SECONDS each.
FUZZ_SECONDS ?= 60
fuzz: deps
	cmake --preset fuzz
	cmake --build build-fuzz -j $(JOBS) --target fuzz_expression fuzz_scene fuzz_packing fuzz_trace
	./scripts/run-fuzzers build-fuzz $(FUZZ_SECONDS)

bench: deps
	cmake --preset bench
	cmake --build build-bench -j $(JOBS)
	./bench/run-benchmarks

# Side-by-side with OpenCASCADE and SISL (docs/benchmarks.md, "Peers"): an optional build of its own.
# It also builds build-peers/bin/occt_section, OpenCASCADE's section of a STEP model (docs/cad.md).
bench-peers:
	./scripts/install-deps --peers
	cmake -S . -B build-peers -G Ninja -DCMAKE_BUILD_TYPE=Release -DSSIMARCH_BUILD_TESTS=OFF -DSSIMARCH_BENCH_PEERS=ON
	cmake --build build-peers -j $(JOBS) --target peer_bench ssimarch occt_section ssimarch_cli
	build-peers/bin/peer_bench --reps 7
	bench/peers/process_times --ssimarch build-peers/bin/ssimarch

clean:
	rm -rf build build-asan build-asan-fast build-fuzz build-bench build-peers out
