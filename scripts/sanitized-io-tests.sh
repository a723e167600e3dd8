#!/usr/bin/env bash
# The readers and their tests (the fuzz test included) built with AddressSanitizer and
# UndefinedBehaviorSanitizer against the plain VTK packages, in build-asan: about a minute on 2
# cores. Run from the repository root after scripts/install-dependencies.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake --build build-asan -j --target FeaturePointsIOCxxTests
ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan -R 'FeaturePoints::TestPointCloud(PLY|Text|PCD|LAS|IO|IOFuzz|IOConcurrent|ReaderWriter)$' --output-on-failure
