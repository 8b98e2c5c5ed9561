#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang-19, AddressSanitizer and
# UndefinedBehaviorSanitizer into build-fuzz/, and runs them:
# - fuzz/graph_fuzzer.cpp over graph files for SECONDS (default 180),
#   starting from the gallery, fuzz/seeds (surface and volume graphs,
#   functions, every global) and the corpus earlier runs left in
#   build-fuzz/corpus;
# - fuzz/file_fuzzer.cpp over the image and mesh files graphs pull in and
#   the paths requests name, for FILE_SECONDS (default half of SECONDS),
#   from fuzz/file_seeds and build-fuzz/file_corpus.
# A crash, a sanitizer report, a verifier failure or a JIT/interpreter
# mismatch stops it with a non-zero status and leaves the input in
# build-fuzz/artifacts/. For a long run: ./scripts/fuzz.sh 3600 1800
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-180}"
file_seconds="${2:-$((seconds / 2))}"
./scripts/install-deps.sh
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DCMAKE_C_COMPILER=clang-19 -DCMAKE_CXX_COMPILER=clang++-19 -DSHADETREE_FUZZ=ON --log-level=WARNING
cmake --build build-fuzz --parallel "$(nproc)" --target shadetree_fuzz shadetree_file_fuzz
mkdir -p build-fuzz/corpus build-fuzz/file_corpus build-fuzz/artifacts
export ASAN_OPTIONS=detect_leaks=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
build-fuzz/shadetree_fuzz -max_total_time="$seconds" -dict=fuzz/graph.dict -max_len=8192 -timeout=30 \
  -rss_limit_mb=6144 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ build-fuzz/corpus graphs fuzz/seeds
build-fuzz/shadetree_file_fuzz -max_total_time="$file_seconds" -max_len=65536 -timeout=30 -rss_limit_mb=6144 \
  -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ build-fuzz/file_corpus fuzz/file_seeds
