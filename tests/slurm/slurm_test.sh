#!/usr/bin/env bash
# `sdfreel slurm` on a real single-node Slurm (scripts/slurm-local.sh starts it here and stops it on
# exit): the job array's frames.framemd5 must equal a plain single-process render byte for byte and
# the encode job's video must hold those frames; then again with one task cancelled mid-render and
# requeued. Never skipped: without the daemons (`scripts/slurm-local.sh install`) it fails.
# Usage: slurm_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
sdfreel=$build/sdfreel
fail() {
  echo "FAIL: $*" >&2
  [ -n "${SLURM_CONF:-}" ] && squeue -t all -o '%i %T %r %E' >&2 || true
  exit 1
}

tmp=$(mktemp -d)
cluster=$tmp/cluster
trap '"$src/scripts/slurm-local.sh" stop "$cluster"; rm -rf "$tmp"' EXIT
trap 'exit 1' INT TERM  # ctest's timeout, ^C: still stop the daemons
"$src/scripts/slurm-local.sh" start "$cluster" || fail "cannot start the cluster"
. "$cluster/env"

# 18 frames, 6 per task; enough samples (about 0.5 s a frame) that a task runs for seconds and can
# be cancelled half-way.
cat >"$tmp/t.toml" <<'TOML'
[video]
scene = "sdf_morph"
fps = 10
duration = 1.8
resolution = [64, 36]
samples = 1024
quality = "final"

[output]
dir = "out"
frames = ["png"]
video = "t.mkv"
codec = "ffv1"

[camera]
keys = [
  { t = 0.0, position = [0.0, 1.5, -4.0], target = [0.0, 0.6, 0.0], fov = 40.0 },
  { t = 1.8, position = [3.0, 1.8, -2.5], target = [0.0, 0.7, 0.0], fov = 45.0 },
]

[params]
morph_period = 1.8
TOML
cd "$tmp"
SECONDS=0
"$sdfreel" render t.toml --out plain --no-video 2>/dev/null || fail "plain render"
echo "plain render: ${SECONDS}s"

state() { squeue -h -t all -j "$1" -o %T 2>/dev/null | head -n 1; }

wait_for_state() {  # JOB STATE SECONDS
  local i s=""
  for ((i = 0; i < $3 * 5; ++i)); do
    s=$(state "$1")
    [ "$s" = "$2" ] && return 0
    case $s in FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE)
      [ "$2" = "$s" ] || fail "job $1 is $s, waiting for $2" ;;
    esac
    sleep 0.2
  done
  fail "job $1 still '$s' after $3 s, waiting for $2"
}

submit() {  # OUT -> sets array_job, encode_job
  local ids
  ids=$("$sdfreel" slurm t.toml --tasks 3 --cpus-per-task 1 --out "$1") || fail "sdfreel slurm"
  array_job=$(sed -n 's/^array_job=//p' <<<"$ids")
  encode_job=$(sed -n 's/^encode_job=//p' <<<"$ids")
  [ -n "$array_job" ] && [ -n "$encode_job" ] || fail "no job ids in: $ids"
}

same_as_plain() {  # OUT
  cmp "$1/frames.framemd5" plain/frames.framemd5 || fail "$1/frames.framemd5 differs from the plain render"
  [ -s "$1/t.mkv" ] || fail "no video $1/t.mkv"
  # The video holds exactly those frames (ffv1 is lossless): stock ffmpeg's framemd5 of it.
  ffmpeg -v error -i "$1/t.mkv" -pix_fmt rgb48le -fflags +bitexact -f framemd5 - | grep -v '^#' >"$1.video.md5"
  grep -v '^#' plain/frames.framemd5 | diff -q - "$1.video.md5" >/dev/null ||
    fail "$1/t.mkv does not hold the rendered frames"
  local k
  for k in 0 1 2; do
    scontrol show job "${array_job}_$k" | grep -q 'ExitCode=0:0' || fail "task $k did not exit 0"
    grep -q "^frame [0-9]*/6 " "$1/logs/task-$k.log" || fail "no progress lines in task-$k.log"
  done
}

# 1. The array and the encode job, undisturbed.
SECONDS=0
submit "$tmp/farm"
wait_for_state "$encode_job" COMPLETED 180
same_as_plain "$tmp/farm"
echo "job array $array_job + encode $encode_job: same frames as the plain render, ${SECONDS}s"

# 2. Task 0 cancelled after its first frame, then requeued: it renders only what is missing.
SECONDS=0
submit "$tmp/farm-requeued"
log=$tmp/farm-requeued/logs/task-0.log
for ((i = 0; i < 1200; ++i)); do
  grep -q '^frame 1/6 ' "$log" 2>/dev/null && break
  sleep 0.05
done
grep -q '^frame 1/6 ' "$log" || fail "task 0 did not start rendering"
scancel "${array_job}_0"
wait_for_state "${array_job}_0" CANCELLED 60
done_before=$(grep -c ' done in ' "$log" || true)
((done_before >= 1 && done_before < 6)) || fail "task 0 was not cancelled mid-render ($done_before of 6 frames)"
for k in 1 2; do wait_for_state "${array_job}_$k" COMPLETED 120; done
# afterok can no longer be satisfied (Slurm marks it DependencyNeverSatisfied on its next pass):
# the encode job waits and writes nothing.
[ "$(state "$encode_job")" = PENDING ] || fail "encode job: $(state "$encode_job")"
[ ! -e "$tmp/farm-requeued/t.mkv" ] || fail "a video was written with a task missing"

# docs/farm.md, "Re-running failed tasks": requeue, skip Slurm's requeue delay, and point the
# encode job at the re-run task.
scontrol requeue "${array_job}_0"
scontrol update JobId="${array_job}_0" StartTime=now
scontrol update JobId="$encode_job" Dependency="afterok:${array_job}_0"
wait_for_state "$encode_job" COMPLETED 180
same_as_plain "$tmp/farm-requeued"
grep -q 'restart 1' "$log" || fail "task 0 did not run again"
kept=$(grep -c ' kept ' "$log" || true)
((kept >= 1)) || fail "the requeued task kept no frame of its first run"
echo "task 0 cancelled after $done_before frames, requeued: kept $kept, same frames, ${SECONDS}s"
