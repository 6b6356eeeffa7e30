#!/usr/bin/env bash
# Fuzzes penumbra's loaders with libFuzzer (clang from Debian; see tests/fuzz/CMakeLists.txt).
#   scripts/fuzz.sh [SECONDS]            every target for SECONDS each (default 60)
#   scripts/fuzz.sh --runs N [TARGET..]  until N executions per target (the 1M-run check)
# Targets: scene_file image shader_include model_obj model_gltf model_glb model_ply.
# Corpora grow in build-fuzz/work/<target>; crashes land in build-fuzz/work/artifacts/<target>/.
# Model files on which Assimp hung (refused by the importer's helper after 3 s, so libFuzzer keeps
# no artefact) land in build-fuzz/work/hangs/<target>/: each shows a rule FormatChecks lacks.
# Copy a crash or hang into tests/fuzz/regressions/<target>/ once fixed: the test suite replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --deps-only
cmake -S . -B build-fuzz -G Ninja -DPENUMBRA_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j "$(nproc)"

limit=(-max_total_time="${1:-60}")
targets=(scene_file image shader_include model_obj model_gltf model_glb model_ply)
if [ "${1:-}" = "--runs" ]; then
  limit=(-runs="$2")
  shift 2
  [ $# -gt 0 ] && targets=("$@")
fi
jobs=$(nproc)
printf "%-16s %12s %8s %8s %6s %s\n" target executions cov ft hangs result
status=0
for t in "${targets[@]}"; do
  dict=$(case $t in scene_file) echo scene;; shader_include) echo glsl;; model_glb) echo gltf;; model_*) echo "${t#model_}";; *) echo "";; esac)
  work=build-fuzz/work/$t; art=build-fuzz/work/artifacts/$t/
  hangs=build-fuzz/work/hangs/$t
  mkdir -p "$work" "$art" "$hangs"
  args=(-timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$art")
  [ -n "$dict" ] && args+=(-dict="tests/fuzz/dict/$dict.dict")
  regressions=(); [ -d "tests/fuzz/regressions/$t" ] && regressions=("tests/fuzz/regressions/$t")
  [ "$t" = shader_include ] && regressions+=(shaders)  # the renderer's own GLSL seeds it too
  set +e
  PENUMBRA_FUZZ_HANGS="$hangs" build-fuzz/fuzz_"$t" "${limit[@]}" "${args[@]}" "$work" "tests/fuzz/seeds/$t" "${regressions[@]}" \
    >"build-fuzz/work/$t.log" 2>&1
  rc=$?
  set -e
  runs=$(grep -ao "stat::number_of_executed_units: *[0-9]*" "build-fuzz/work/$t.log" | grep -o "[0-9]*$" | tail -1)
  cov=$(grep -aoE "cov: [0-9]+ ft: [0-9]+" "build-fuzz/work/$t.log" | tail -1)
  result=clean; [ $rc -ne 0 ] && { result="FAILED (exit $rc, see build-fuzz/work/$t.log)"; status=1; }
  printf "%-16s %12s %8s %8s %6s %s\n" "$t" "${runs:-?}" "$(echo "$cov" | awk '{print $2}')" "$(echo "$cov" | awk '{print $4}')" \
    "$(find "$hangs" -type f | wc -l)" "$result"
done
exit $status
