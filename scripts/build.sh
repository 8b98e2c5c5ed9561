#!/usr/bin/env bash
# Installs what is missing and builds shadetree (Release) into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release --log-level=WARNING
cmake --build build --parallel "$(nproc)"
