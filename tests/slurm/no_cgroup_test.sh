#!/usr/bin/env bash
# scripts/slurm-local.sh must start a cluster where /sys/fs/cgroup has nothing mounted (a chroot
# with /sys bound without its submounts, some containers): slurmd 22.05 fails to start there with
# its default cgroup.conf. This machine's cgroups are hidden in a private mount namespace, then a
# cluster is started and runs one job. Exit 77 (skipped) only where a mount namespace cannot be
# made (no CAP_SYS_ADMIN); the full Slurm test runs regardless.
# Usage: no_cgroup_test.sh SOURCE_DIR
set -euo pipefail
src=$(cd "$1" && pwd)
if [ "${SDFREEL_IN_NAMESPACE:-}" != 1 ]; then
  unshare -m --propagation private true 2>/dev/null || { echo "cannot make a mount namespace"; exit 77; }
  exec env SDFREEL_IN_NAMESPACE=1 unshare -m --propagation private "$0" "$@"
fi
# Inside the namespace: unmount every cgroup file system (nothing to do where none is mounted).
if mountpoint -q /sys/fs/cgroup; then umount -R /sys/fs/cgroup; fi
fstype=$(stat -f -c %T /sys/fs/cgroup 2>/dev/null || echo none)
case $fstype in cgroup* | tmpfs) echo "FAIL: /sys/fs/cgroup is still $fstype" >&2; exit 1 ;; esac

tmp=$(mktemp -d)
trap '"$src/scripts/slurm-local.sh" stop "$tmp/cluster"; rm -rf "$tmp"' EXIT
"$src/scripts/slurm-local.sh" start "$tmp/cluster"
. "$tmp/cluster/env"
timeout 120 sbatch --wait --quiet -o "$tmp/job.out" --wrap 'echo "ran job $SLURM_JOB_ID"'
grep -q '^ran job [0-9]' "$tmp/job.out" || { echo "FAIL: the job did not run" >&2; exit 1; }
echo "slurmd started and ran a job with /sys/fs/cgroup as $fstype"
