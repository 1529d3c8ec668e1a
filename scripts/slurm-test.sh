#!/usr/bin/env bash
# The Slurm path of docs/batch.md, end to end on a one-node Slurm started on
# localhost in a private temporary folder:
#  1. installs Debian's slurm-wlm and munge when missing (apt-get);
#  2. starts munged (its own key, socket, pid and log files) and slurmctld +
#     slurmd on a slurm.conf written here (one node: localhost with the CPUs
#     nproc gives, partition debug, free ports), waits until sinfo shows the
#     node idle;
#  3. writes 11 synthetic AMASS-style motions (8 in MOTIONS/, 3 in
#     MOTIONS/sub/, one of them long) from the fixtures and converts them with
#     one smpl-export process per folder (the reference outputs and manifests);
#  4. submits the job script of docs/batch.md (the block after the
#     "slurm-job-script" marker, verbatim) as `sbatch --array=0-3 bake.sh 4
#     MODEL MOTIONS baked`;
#  5. cancels task 1 while it converts its long motion (after its first output
#     is written), checks it was cancelled with its work unfinished, and
#     resubmits it (`sbatch --array=1 ...`); waits for every task (bounded);
#  6. compares every file under baked/ byte for byte with the reference and
#     the shards' manifests, concatenated and sorted as docs/batch.md says,
#     with the reference's: input, output (relative to the output folder),
#     bytes, sha256 must be equal and the status the same, except that a
#     motion the cancelled attempt finished is "up-to-date" in the resumed
#     task; "seconds" (each run's time) is not compared.
# Exit 0 when all is equal; otherwise 1 with one line per difference. Slurm,
# munge and everything in the temporary folder are stopped and removed at
# exit, also on failure (--keep keeps the folder). Needs root (munged and
# slurmd run as root here; CI runs as root): not root is a failure.
#
#   scripts/slurm-test.sh [--exe PATH] [--fixtures DIR] [--docs FILE] [--keep]
#
# --exe: smpl-export (default build/cli/smpl-export); --fixtures: the synthetic
# fixtures (default build/fixtures, `cmake --build build --target fixtures`);
# --docs: the page holding the job script (default docs/batch.md).
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=$root/build/cli/smpl-export
fixtures=$root/build/fixtures
docs=$root/docs/batch.md
keep=0
while (($#)); do
  case $1 in
    --exe) exe=$2; shift 2 ;;
    --fixtures) fixtures=$2; shift 2 ;;
    --docs) docs=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    *) echo "slurm-test: unknown option '$1' (see scripts/slurm-test.sh --help)" >&2; exit 2 ;;
  esac
done
fail() { echo "slurm-test: $*" >&2; exit 1; }
say() { echo "slurm-test: $*"; }

[[ $(id -u) -eq 0 ]] || fail "needs root (munged and slurmd run as root here; CI runs as root): run it as root"
[[ -x $exe ]] || fail "$exe: not an executable (cmake --build build --target smpl-export)"
[[ -f $fixtures/models/smplh_small.npz ]] || fail "$fixtures: no synthetic fixtures (cmake --build build --target fixtures)"
[[ -f $docs ]] || fail "$docs: no such page (--docs)"
exe=$(realpath "$exe")
fixtures=$(realpath "$fixtures")
docs=$(realpath "$docs")

# 1. Slurm and munge (also in scripts/setup-deps.sh's test packages).
missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  say "installing ${missing[*]}"
  lock=(-o DPkg::Lock::Timeout=600)
  apt-get "${lock[@]}" update -qq && DEBIAN_FRONTEND=noninteractive apt-get "${lock[@]}" install -y -qq \
    --no-install-recommends "${missing[@]}" >/dev/null || fail "apt-get could not install ${missing[*]}"
fi

# 2. A private one-node cluster; the trap stops it and removes the folder.
tmp=$(mktemp -d /tmp/slurm-test.XXXXXX)
chmod 711 "$tmp"  # munged wants its socket's folders searchable
pids=()
cleanup() {
  local rc=$?
  if [[ -n ${SLURM_CONF:-} && -f $SLURM_CONF ]]; then
    scancel --quiet --user=root >/dev/null 2>&1
    for _ in $(seq 50); do [[ -z $(squeue -h 2>/dev/null) ]] && break; sleep 0.2; done
  fi
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
  if ((keep)); then echo "slurm-test: kept $tmp"; else rm -rf "$tmp"; fi
  exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT TERM
mkdir -p "$tmp"/{munge,state,spool,log,run,work,bin}

# Log tails for a failure of the cluster itself.
logs() {
  for f in "$tmp"/log/*; do echo "--- ${f##*/} (last 15 lines)"; tail -n 15 "$f"; done >&2
}

mungekey --create --keyfile="$tmp/munge/munge.key" 2>/dev/null ||
  dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 600 "$tmp/munge/munge.key"
munged --foreground --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/run/munged.pid" --log-file="$tmp/log/munged.log" --seed-file="$tmp/munge/seed" \
  >"$tmp/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [[ -S $tmp/munge/munge.socket ]] && break; sleep 0.1; done
[[ -S $tmp/munge/munge.socket ]] || { logs; fail "munged did not create its socket within 5 s"; }

read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
cpus=$(nproc)
free_mb=$(awk '/MemAvailable/ { print int($2 / 1024) }' /proc/meminfo)
mem=$((free_mb > 2048 ? free_mb - 1024 : free_mb / 2))
export SLURM_CONF=$tmp/slurm.conf
cat >"$SLURM_CONF" <<EOF
ClusterName=smpltest
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
MinJobAge=600
KillWait=5
InactiveLimit=0
NodeName=localhost NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -c -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N localhost >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 150); do
  state=$(sinfo -h -n localhost -o %T 2>/dev/null)
  [[ $state == idle ]] && break
  sleep 0.2
done
[[ $state == idle ]] || { logs; fail "node localhost not idle within 30 s (sinfo: '${state:-no answer}')"; }
say "one-node Slurm up ($cpus CPUs, ${mem} MB, $tmp)"

# 3. Motions: AMASS-style (poses (T,156), trans, betas, gender,
# mocap_framerate) varied from the fixture; s05 (task 1's second motion) long.
work=$tmp/work
/usr/bin/python3 - "$fixtures/motions/amass_smplh.npz" "$work/MOTIONS" <<'EOF' || fail "could not write the motions"
import os, sys
import numpy as np
src = dict(np.load(sys.argv[1]))
out = sys.argv[2]
os.makedirs(os.path.join(out, "sub"))
names = [f"s{i:02d}_poses.npz" for i in range(8)] + [f"sub/t{i}_poses.npz" for i in range(3)]
for k, name in enumerate(names):
    frames = 7200 if name == "s05_poses.npz" else 40 + 15 * k
    reps = -(-frames // len(src["poses"]))
    poses = np.tile(src["poses"], (reps, 1))[:frames] * (0.6 + 0.05 * k)
    trans = np.tile(src["trans"], (reps, 1))[:frames] + 0.01 * k
    np.savez(os.path.join(out, name), poses=poses, trans=trans, betas=src["betas"] * (1 - 0.1 * k),
             gender=src["gender"], mocap_framerate=src["mocap_framerate"])
EOF
cp "$fixtures/models/smplh_small.npz" "$work/SMPLH_NEUTRAL.npz"
ln -s "$exe" "$tmp/bin/smpl-export"
export PATH=$tmp/bin:$PATH
cd "$work" || fail "no $work"
while IFS= read -r dir; do
  rel=${dir#MOTIONS}; rel=${rel#/}; sub=${rel:+/$rel}
  mkdir -p "ref-manifests$sub"
  smpl-export --model SMPLH_NEUTRAL.npz --motion-dir "$dir" --out-dir "ref$sub" --format glb -q \
    --manifest "ref-manifests$sub/all.jsonl" >/dev/null ||
    fail "the one-process batch of $dir failed"
done < <(find MOTIONS -name '*.npz' -printf '%h\n' | LC_ALL=C sort -u)
say "one-process batch: $(find ref -name '*.glb' | wc -l) outputs"

# 4. The docs' job script, verbatim.
awk '/<!-- slurm-job-script/ { m = 1; next } m && /^```/ { if (f) exit; f = 1; next } f' "$docs" >bake.sh
grep -q -- '--shard' bake.sh || fail "$docs: no job script after the 'slurm-job-script' marker"
chmod +x bake.sh
submit() {  # submit ARRAY -> job id
  sbatch --parsable --array="$1" bake.sh 4 SMPLH_NEUTRAL.npz MOTIONS baked | cut -d';' -f1
}
job=$(submit 0-3) || { logs; fail "sbatch --array=0-3 failed"; }
say "submitted array job $job (tasks 0-3)"

# 5. Cancel task 1 between its first output (s01) and its long motion (s05).
deadline=$((SECONDS + 120))
until [[ -f baked/s01_poses.glb.smpl.json ]]; do
  ((SECONDS < deadline)) || { logs; fail "task 1 wrote no output within 120 s"; }
  sleep 0.05
done
scancel "${job}_1"
task_state() { squeue -h -t all -j "$1" -o '%i %T' 2>/dev/null | awk -v id="$1" '$1 == id { print $2 }'; }
deadline=$((SECONDS + 60))
until [[ $(task_state "${job}_1") == CANCELLED ]]; do
  s=$(task_state "${job}_1")
  [[ $s == COMPLETED || $s == FAILED ]] && fail "task 1 ended $s before it was cancelled (its long motion converted too fast)"
  ((SECONDS < deadline)) || { logs; fail "task 1 not cancelled within 60 s (state '$s')"; }
  sleep 0.2
done
[[ ! -f baked/s05_poses.glb && ! -f manifests/shard1.jsonl ]] ||
  fail "task 1 had finished its long motion when cancelled: not a midway cancel"
say "task ${job}_1 cancelled midway (s01 written, s05 not)"
job2=$(submit 1) || { logs; fail "sbatch --array=1 failed"; }
say "resubmitted task 1 as job $job2"
deadline=$((SECONDS + 150))
while [[ -n $(squeue -h -j "$job,$job2" -t PENDING,RUNNING,CONFIGURING,COMPLETING,SUSPENDED 2>/dev/null) ]]; do
  ((SECONDS < deadline)) || { squeue -j "$job,$job2" >&2; logs; fail "the array tasks did not finish within 150 s"; }
  sleep 0.5
done
for t in "${job}_0" "${job}_2" "${job}_3" "${job2}_1"; do
  s=$(task_state "$t")
  if [[ $s != COMPLETED ]]; then
    cat slurm-*.out >&2
    fail "task $t ended '${s:-unknown}', not COMPLETED"
  fi
done
say "all tasks completed"

# 6. Same files, same bytes; same manifest but for the fields that differ legitimately.
status=0
diff <(cd ref && find . -type f -print | LC_ALL=C sort) \
  <(cd baked && find . -type f -print | LC_ALL=C sort) >files.diff ||
  { echo "slurm-test: the file lists of ref/ and baked/ differ:"; cat files.diff; status=1; } >&2
while IFS= read -r f; do
  [[ -f baked/$f ]] || continue
  cmp -s "ref/$f" "baked/$f" || { echo "slurm-test: baked/$f differs from the one-process batch's ref/$f" >&2; status=1; }
done < <(cd ref && find . -type f -print | sed 's|^\./||' | LC_ALL=C sort)
# docs/batch.md's concatenation; the reference folders' manifests in input order.
find manifests -name '*.jsonl' -exec cat {} + | LC_ALL=C sort >batch.jsonl
find ref-manifests -name '*.jsonl' -exec cat {} + | LC_ALL=C sort >ref.jsonl
/usr/bin/python3 - ref.jsonl batch.jsonl <<'EOF' || status=1
import json, sys
ref = [json.loads(l) for l in open(sys.argv[1])]
got = [json.loads(l) for l in open(sys.argv[2])]
bad = 0
def rel(path, top):
    return path[len(top) + 1:] if path and path.startswith(top + "/") else path
if [r["input"] for r in ref] != [g["input"] for g in got]:
    a, b = [r["input"] for r in ref], [g["input"] for g in got]
    print("slurm-test: the concatenated manifests' inputs (sorted) differ from the one-process manifest's:"
          f" missing {sorted(set(a) - set(b))}, extra {sorted(set(b) - set(a))},"
          f" {len(b)} lines for {len(a)} motions", file=sys.stderr)
    sys.exit(1)
resumed = 0
for r, g in zip(ref, got):
    for key in ("bytes", "sha256"):
        if r[key] != g[key]:
            print(f"slurm-test: manifest {r['input']}: {key} {g[key]} (shards) != {r[key]} (one process)", file=sys.stderr)
            bad = 1
    if rel(r["output"], "ref") != rel(g["output"], "baked"):
        print(f"slurm-test: manifest {r['input']}: output {g['output']} != {r['output']}", file=sys.stderr)
        bad = 1
    if (r["status"], g["status"]) == ("converted", "up-to-date"):
        resumed += 1
    elif r["status"] != g["status"]:
        print(f"slurm-test: manifest {r['input']}: status {g['status']} != {r['status']}", file=sys.stderr)
        bad = 1
if not bad:
    print(f"slurm-test: manifest: {len(got)} lines equal in input, output, bytes, sha256, status"
          f" ({resumed} up-to-date in the resumed task); seconds not compared")
sys.exit(bad)
EOF
if ((status == 0)); then
  say "PASS: $(find baked -type f | wc -l) files byte-identical to the one-process batch"
else
  say "FAIL: the Slurm batch differs from the one-process batch"
fi
exit $status
