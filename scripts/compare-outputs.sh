#!/usr/bin/env bash
# Behaviour-unchanged proof for refactors: runs a fixed set of README-style
# smpl-export commands with two binaries, each into its own folder, and
# compares the sha256 of every file they wrote (outputs, sidecars
# `<out>.smpl.json`, `.gltf` buffers, batch outputs and the batch manifest).
# Prints one table row per file and exits 1 on any difference, on a file only
# one binary wrote, or on a command whose exit code differs between them.
#
#   scripts/compare-outputs.sh OLD_EXE NEW_EXE [FIXTURE_DIR] [WORK_DIR]
#
# FIXTURE_DIR: the synthetic fixtures (default build/fixtures, made by
# `cmake --build build --target fixtures`). WORK_DIR (default a fresh
# temporary folder) gets old/ and new/. Every input is named by the same
# absolute path in both runs and every output by a relative one, so the
# files may be compared byte for byte. The manifest's "seconds" (wall time)
# is the one field that differs from run to run; it is blanked before hashing
# (the table marks that row "manifest, seconds blanked"). Each command's
# printed summary and notes (stdout) are compared too, with the times
# ("123 ms") blanked: rows "[NAME] stdout" (batch lines sorted: workers
# finish in any order).
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -uo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 OLD_EXE NEW_EXE [FIXTURE_DIR] [WORK_DIR]" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(realpath "$1")
new=$(realpath "$2")
fx=$(realpath "${3:-$root/build/fixtures}")
work=${4:-$(mktemp -d /tmp/compare-outputs.XXXXXX)}
mkdir -p "$work"
work=$(realpath "$work")
for f in "$old" "$new"; do [[ -x "$f" ]] || { echo "not an executable: $f" >&2; exit 2; }; done
[[ -d "$fx/models" ]] || { echo "no fixtures in $fx (cmake --build build --target fixtures)" >&2; exit 2; }

m=$fx/models
mo=$fx/motions
rel=$fx/released
fmt=$fx/formats
dm=$fx/dmpl
in=$work/inputs  # inputs made here, shared by both runs
rm -rf "$in" "$work/old" "$work/new"
mkdir -p "$in"
printf '{"betas": [0.4, -0.8, 0.2, 1.1]}\n' > "$in/betas.json"

# One command per line: NAME|ARGS (ARGS split on spaces; no path has one).
commands=(
  "builtin_glb|--model builtin --out builtin.glb"
  "builtin_fbx|--model builtin --out builtin.fbx"
  "builtin_gltf|--model builtin --out builtin.gltf"
  "builtin_gltf_embed|--model builtin --gltf-embed --out embed.gltf"
  "npz_betas|--model $m/smpl_small.npz --betas 0.5,-1.2,0.3 --out npz_betas.glb"
  "pkl_betas_fbx|--model $m/smpl_small_p2.pkl --betas 0.5,-1.2,0.3 --out pkl_betas.fbx"
  "betas_file_npy|--model $m/smpl_small_p2.pkl --betas-file $rel/betas_rows_differ.npy --out betas_npy.fbx"
  "betas_file_json|--model $m/smpl_small.npz --betas-file $in/betas.json --out betas_json.glb"
  "smplx_expression|--model $m/smplx_small.npz --expression-keys 4 --expression 0.5,-0.5 --max-influences 8 --out face.gltf"
  "shape_keys_truncated_all|--model $m/smplh_small.npz --shape-keys 4 --skin-weights truncated --max-influences all --out shape_keys.glb"
  "motion_fps_frames|--model builtin --motion $mo/smpl_72.npz --fps 30 --frames 0:20 --out motion.glb"
  "two_motions_fbx|--model builtin --motion $mo/smpl_72.npz --motion $mo/plain.json --fps 24 --frames 0:600 --out clips.fbx"
  "amass_smplh|--model $m/smplh_small.npz --motion $mo/amass_smplh.npz --out walk.glb"
  "amass_on_smpl_in_place|--model $m/smpl_small.npz --motion $mo/amass_smplh.npz --root-motion in-place --up z --out walk_smpl.fbx"
  "betas_from_motion|--model $m/smpl_small.npz --motion $rel/betas_rows_differ.npz --betas-from-motion --out fit.glb"
  "source_fps|--model builtin --motion $fmt/no_fps.npz --source-fps 50 --out no_fps.glb"
  "smplcodec|--model $rel/smplx_release.npz --motion $fmt/codec_root.smpl --out dance.glb"
  "fit_pca_flat|--model $rel/smplx_release.npz --motion $fmt/fit_pca.pkl --flat-hand-mean --out pose.glb"
  "aist|--model $m/smpl_small.npz --motion $fmt/aist.pkl --out aist.glb"
  "dmpl_file|--model $dm/amass/smplh/female/model.npz --motion $dm/amass_smplh_dmpl.npz --dmpl $dm/amass/dmpls/female/model.npz --out dmpl.glb"
  "dmpl_dir_regressed_fbx|--model $dm/amass --dmpl $dm/amass --dmpl-count 4 --dmpl-joints regressed --motion $dm/amass_smplh_dmpl.npz --out dmpl_dir.fbx"
  "model_dir_motion|--model $rel/smpl_folder --motion $rel/mixed_gender/f_walk.npz --out folder.glb"
  "model_dir_no_motion|--model $rel/smpl_folder --out folder_neutral.glb"
  "batch_manifest|--model $rel/smpl_folder --motion-dir $rel/mixed_gender --out-dir batch --manifest batch.jsonl --threads 2"
  "batch_fbx_shard|--model $m/smplh_small.npz --motion-dir $fmt/subject --out-dir batch_fbx --format fbx --shard 0/1 --threads 1"
  "batch_gltf|--model builtin --motion-dir $fmt/subject --out-dir batch_gltf --format gltf --max-influences 2"
  "corrective_basis|--model $m/smpl_small.npz --corrective-basis 16 --out basis.glb"
  "corrective_basis_motion_fbx|--model $m/smpl_small.npz --corrective-basis 8 --motion $mo/smpl_72.npz --out basis_motion.fbx"
  "quantize_morphs|--model builtin --quantize-morphs --out quant.glb"
  "gltf_compact|--model $m/smpl_small.npz --quantize-morphs --corrective-epsilon 0.0001 --draco --motion $mo/smpl_72.npz --out compact.glb"
  "unit_weights|--model builtin --corrective-weights unit --out unit.glb"
  "no_correctives|--model builtin --correctives none --name subject --out none.fbx"
  "fbx_options|--model builtin --fbx-units cm --fbx-version 7500 --fbx-compress-level 0 --threads 2 --out units.fbx"
  "uv_npy|--model $rel/smplx_release.npz --uv $rel/smplx_pair_uv.npy --out uv_npy.glb"
  "uv_obj|--model $rel/smplx_release.npz --uv $rel/smplx_release_uv.obj --out uv_obj.fbx"
  "uv_model_file|--model $rel/smplx_release.npz --out uv_model.glb"
  "uv_none|--model $rel/smplx_release.npz --uv none --out uv_none.glb"
)

run_all() {  # EXE DIR -> DIR/exit_codes
  local exe=$1 dir=$2
  mkdir -p "$dir"
  for c in "${commands[@]}"; do
    local name=${c%%|*} args=${c#*|}
    # shellcheck disable=SC2086  # ARGS is a word list by design
    (cd "$dir" && "$exe" $args >"$dir/.$name.stdout" 2>"$dir/.$name.stderr")
    echo "$name $?" >>"$dir/.exit_codes"
  done
}
run_all "$old" "$work/old"
run_all "$new" "$work/new"

status=0
printf '%-52s %-16s %-16s %s\n' "file" "old sha256" "new sha256" "result"
while read -r name code; do
  new_code=$(awk -v n="$name" '$1 == n {print $2}' "$work/new/.exit_codes")
  if [[ "$code" != "$new_code" || "$code" != 0 ]]; then
    printf '%-52s exit %-11s exit %-11s %s\n' "[$name]" "$code" "$new_code" "COMMAND FAILED OR DIFFERS"
    sed 's/^/    old: /' "$work/old/.$name.stderr" | tail -2
    sed 's/^/    new: /' "$work/new/.$name.stderr" | tail -2
    status=1
  fi
done <"$work/old/.exit_codes"

digest() {  # FILE -> sha256 (the manifest with its wall times blanked)
  if [[ "$1" == *.jsonl ]]; then
    sed -E 's/"seconds":[-0-9.eE+]+/"seconds":_/g' "$1" | sha256sum | cut -c1-64
  else
    sha256sum "$1" | cut -c1-64
  fi
}
files=$( (cd "$work/old" && find . -type f ! -name '.*'; cd "$work/new" && find . -type f ! -name '.*') | sort -u)
count=0
same=0
for f in $files; do
  count=$((count + 1))
  a=-; b=-
  [[ -f "$work/old/$f" ]] && a=$(digest "$work/old/$f")
  [[ -f "$work/new/$f" ]] && b=$(digest "$work/new/$f")
  note=identical
  [[ "$f" == *.jsonl ]] && note="identical (manifest, seconds blanked)"
  if [[ "$a" == - || "$b" == - || "$a" != "$b" ]]; then
    note=DIFFERENT
    status=1
  else
    same=$((same + 1))
  fi
  printf '%-52s %-16s %-16s %s\n' "${f#./}" "${a:0:16}" "${b:0:16}" "$note"
done
summary() {  # NAME DIR -> the stdout with times blanked (batch runs: lines sorted)
  if [[ "$1" == batch* ]]; then
    sed -E 's/[0-9]+ ms/_ ms/g' "$2/.$1.stdout" | sort
  else
    sed -E 's/[0-9]+ ms/_ ms/g' "$2/.$1.stdout"
  fi
}
for c in "${commands[@]}"; do
  name=${c%%|*}
  count=$((count + 1))
  a=$(summary "$name" "$work/old" | sha256sum | cut -c1-64)
  b=$(summary "$name" "$work/new" | sha256sum | cut -c1-64)
  note="identical (times blanked)"
  if [[ "$a" != "$b" ]]; then
    note=DIFFERENT
    status=1
    diff <(summary "$name" "$work/old") <(summary "$name" "$work/new") | head -6 | sed 's/^/    /'
  else
    same=$((same + 1))
  fi
  printf '%-52s %-16s %-16s %s\n' "[$name] stdout" "${a:0:16}" "${b:0:16}" "$note"
done
echo "compare-outputs: ${#commands[@]} commands, $count files and summaries, $same identical, $((count - same)) different (work: $work)"
[[ $count -gt 0 ]] || status=1
exit $status
