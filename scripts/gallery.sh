#!/usr/bin/env bash
# Installs what is missing, builds, and renders every graph of graphs/ into
# out/gallery/ (PNG files and an index.html with each image, its graph name
# and its render time).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
mkdir -p out/gallery
index=out/gallery/index.html
{
  echo '<!doctype html><meta charset="utf-8"><title>shadetree gallery</title>'
  echo '<style>body{font-family:sans-serif;background:#222;color:#eee}figure{display:inline-block;margin:12px}'
  echo 'img{width:384px;height:auto;display:block}figcaption{margin-top:4px}</style><h1>shadetree gallery</h1>'
} > "$index"
for graph in graphs/*.json; do
  name=$(basename "$graph" .json)
  # The render's own summary line says how long the render took.
  if ! summary=$(build/shadetree render "$graph" -o "out/gallery/$name.png" 2>&1); then
    echo "$summary" >&2
    exit 1
  fi
  echo "$summary"
  seconds=$(echo "$summary" | sed -nE 's/.* in ([0-9.]+) s .*/\1/p')
  echo "<figure><img src=\"$name.png\" alt=\"$name\"><figcaption>$name &mdash; rendered in ${seconds} s</figcaption></figure>" >> "$index"
done
echo "gallery: $(ls out/gallery/*.png | wc -l) images in out/gallery/index.html"
