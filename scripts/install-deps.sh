#!/usr/bin/env bash
# Installs the Debian packages shadetree builds and tests with. Idempotent:
# packages already present are skipped, so a second run costs one dpkg query.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  nlohmann-json3-dev libglm-dev libopenimageio-dev openimageio-tools
  libgtest-dev libgmock-dev libbenchmark-dev libtbb-dev libcli11-dev
  libembree-dev libassimp-dev libopenvdb-dev libboost-dev libcpp-httplib-dev libpng-dev libopenexr-dev
  libopenmpi-dev openmpi-bin glslang-tools
  nodejs npm chromium python3-jsonschema
  llvm-19-dev clang-19 libclang-rt-19-dev libzstd-dev zlib1g-dev libedit-dev libxml2-dev libffi-dev libcurl4-openssl-dev
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

# The machine's own Node.js and npm may come from elsewhere than Debian.
if command -v node > /dev/null && command -v npm > /dev/null; then
  kept=()
  for package in "${missing[@]}"; do
    if [ "$package" != nodejs ] && [ "$package" != npm ]; then kept+=("$package"); fi
  done
  missing=("${kept[@]}")
fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The editor's packages (editor/package-lock.json), again only when the
# lock file changed since they were installed.
editor="$(dirname "$0")/../editor"
stamp="$editor/node_modules/.package-lock.json"
if [ ! -f "$stamp" ] || ! cmp -s <(sha256sum < "$editor/package-lock.json") "$editor/node_modules/.shadetree-lock-sum" 2> /dev/null; then
  echo "install-deps: npm ci in editor/" >&2
  (cd "$editor" && npm ci --no-audit --no-fund --loglevel=error)
  sha256sum < "$editor/package-lock.json" > "$editor/node_modules/.shadetree-lock-sum"
fi
