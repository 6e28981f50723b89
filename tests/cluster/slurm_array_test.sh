#!/usr/bin/env bash
# A real Slurm run of the README's array job: a one-node cluster (slurmctld,
# slurmd, munge) on localhost from a generated slurm.conf, the README's script
# submitted unchanged as 4 shards, its dependent merge, and the merged bytes
# compared with a one-machine batch. Needs root (slurmd runs jobs as the
# submitting user and must own its spool) and Debian's slurm-wlm and munge.
#   usage: slurm_array_test.sh <procex executable> <repository root>
set -euo pipefail
procex=$(realpath "$1")
repo=$(realpath "$2")
shards=4

fail() { echo "slurm_array_test: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root: slurmd must start jobs and own its spool (CI runs as root)"
for tool in munged slurmctld slurmd sbatch squeue scontrol; do
  command -v "$tool" >/dev/null || fail "$tool is missing: scripts/install-deps.sh installs slurm-wlm and munge"
done

work=$(mktemp -d /tmp/procex-slurm.XXXXXX)
cluster="$work/cluster"
mkdir -p "$cluster/state" "$cluster/spool" "$work/run/parts" "$work/single"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT
show_logs() {
  for log in "$cluster"/*.log; do echo "--- $log"; tail -n 30 "$log"; done >&2
}

# A free TCP port on loopback, by asking the kernel for one.
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

# munge: a private key and socket, so the test needs no system daemon.
dd if=/dev/urandom of="$cluster/munge.key" bs=1024 count=1 status=none
chmod 600 "$cluster/munge.key"
munged --force --foreground --socket="$cluster/munge.socket" --key-file="$cluster/munge.key" \
  --pid-file="$cluster/munged.pid" --log-file="$cluster/munged.log" --seed-file="$cluster/munged.seed" 2>>"$cluster/munged.stderr.log" &
pids+=($!)
for _ in $(seq 100); do [ -S "$cluster/munge.socket" ] && break; sleep 0.1; done
[ -S "$cluster/munge.socket" ] || { show_logs; fail "munged did not start"; }

host=$(hostname -s)
cpus=$(nproc)
cat > "$cluster/slurm.conf" <<CONF
ClusterName=procex-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$cluster/munge.socket
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/slurmctld.log
SlurmdLogFile=$cluster/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
SchedulerParameters=sched_interval=1
NodeName=$host NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=procex Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$cluster/slurm.conf"
slurmctld -D -i -f "$SLURM_CONF" 2>>"$cluster/slurmctld.stderr.log" & pids+=($!)
slurmd -D -f "$SLURM_CONF" 2>>"$cluster/slurmd.stderr.log" & pids+=($!)
for _ in $(seq 150); do
  state=$(sinfo -h -n "$host" -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "${state:-}" = idle ] || { show_logs; fail "the node did not come up (state '${state:-none}')"; }

# The README's array-job script, exactly as the README prints it: the first
# fenced block that holds #SBATCH lines. Its merge is the comment after it.
script="$work/run/city.sbatch"
awk '/^```sh$/ {block=""; inside=1; next} /^```$/ {if (inside && block ~ /#SBATCH/) {printf "%s", block; exit} inside=0; next} inside {block = block $0 "\n"}' \
  "$repo/README.md" > "$script"
grep -q '^#SBATCH' "$script" || fail "no array-job script found in README.md"
# The comment may continue over lines ending in a backslash.
merge_cmd=$(sed -n '/^# then: sbatch/,$ s/^#[[:space:]]*//p' "$script" | sed -e ':a' -e '/\\$/N; s/\\\n[[:space:]]*//; ta' |
  sed -n "s/^then: sbatch --dependency=afterok:<array job id> --wrap '\(.*\)'$/\1/p")
[ -n "$merge_cmd" ] || fail "no dependent merge found in the README's script"

cp "$repo/samples/city.pxg" "$work/run/city.pxg"
cp -r "$repo/samples/meshes" "$work/run/meshes"  # the windows and doors city.pxg places
cp "$repo/samples/footprints/sample_block.geojson" "$work/run/city.geojson"
mkdir -p "$work/bin"
ln -s "$procex" "$work/bin/procex"
export PATH="$work/bin:$PATH"

cd "$work/run"
# The command line overrides the script's #SBATCH lines: 4 shards, and one CPU
# a task so the shards run side by side on a small machine.
array=$(sbatch --parsable --array=0-$((shards - 1)) --cpus-per-task=1 --output="$work/run/shard_%a.out" "$script")
merge=$(sbatch --parsable --dependency=afterok:"$array" --output="$work/run/merge.out" --wrap "$merge_cmd")

# Meanwhile the one-machine run the merged file must equal.
(cd "$work/single" && cp -r ../run/city.pxg ../run/city.geojson ../run/meshes . &&
  procex batch city.pxg --footprints city.geojson -o city.glb --report city.json --no-progress >/dev/null)

deadline=$((SECONDS + 600))
while [ -n "$(squeue -h -j "$array,$merge" 2>/dev/null)" ]; do
  [ $SECONDS -lt $deadline ] || { show_logs; fail "jobs still queued after 600 s"; }
  sleep 1
done

for i in $(seq 0 $((shards - 1))); do
  [ -s "parts/city_$i.glb" ] || { cat shard_*.out >&2; show_logs; fail "shard $i wrote no parts/city_$i.glb"; }
done
[ -s city.glb ] || { cat merge.out shard_*.out >&2; show_logs; fail "the merge job wrote no city.glb"; }
cmp city.glb "$work/single/city.glb" || fail "merged city.glb differs from the one-machine run"
buildings=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["buildings"]))' city.json)
expected=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["features"]))' city.geojson)
[ "$buildings" = "$expected" ] || fail "merged report lists $buildings buildings, the footprints file has $expected"
echo "slurm_array_test: $shards shards on $host, merged city.glb equals the one-machine run ($buildings buildings)"
