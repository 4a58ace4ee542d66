#!/usr/bin/env bash
# The Slurm job array of docs/guides/campaigns.md on a real Slurm: installs Debian's
# slurm-wlm and munge if missing, starts a one-node cluster on this machine
# (munged, slurmctld and slurmd as root, everything in a temporary directory,
# nothing under /etc), submits the guide's job-array script over 8 demo
# datasets as --array=0-3%2, cancels task 0 (scancel) once its first report is
# written, resubmits the whole array (what was reported is kept, not fitted
# again), merges, and checks the merged table equals a serial run's apart from
# timings. Stops the daemons it started, also on failure. Exits 0 only if all
# held. Usage: bash scripts/slurm_check.sh (after scripts/build.sh; root or sudo).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
ringid=$root/build/ringid
[ -x "$ringid" ] || { echo "slurm_check: $ringid missing: run scripts/build.sh first" >&2; exit 2; }
bash scripts/install_deps.sh slurm-wlm munge
t_install=$SECONDS
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
say() { echo "slurm_check: $*"; }
fail() { echo "slurm_check: FAILED: $*" >&2; exit 1; }
idle() { [ -z "$(squeue -h 2> /dev/null)" ]; }
gone() { ! kill -0 "$1" 2> /dev/null; }
# Polls `$@` every 0.1 s for at most $1 seconds; false on time-out.
wait_for() {
  local limit=$1; shift
  local end=$((SECONDS + limit))
  until "$@"; do [ $SECONDS -lt $end ] || return 1; sleep 0.1; done
}

# Daemons left by an earlier check that was itself killed (its owner process
# gone): each is stopped only if its command line names that check's
# directory. The directory, its logs, stays.
for old in "${TMPDIR:-/tmp}"/ringid-slurm-check.*; do
  [ -f "$old/owner.pid" ] && gone "$(cat "$old/owner.pid")" || continue
  if grep -qaF "$old/" "/proc/$(cat "$old/slurmctld.pid" 2> /dev/null)/cmdline" 2> /dev/null; then
    say "cancelling the jobs of an earlier check's cluster in $old"
    SLURM_CONF=$old/slurm.conf scancel --quiet --user="$(id -un)" 2> /dev/null || true
    SLURM_CONF=$old/slurm.conf wait_for 20 idle || true
  fi
  for pidfile in "$old"/munged.pid "$old"/slurmctld.pid "$old"/slurmd.pid; do
    pid=$(cat "$pidfile" 2> /dev/null) || continue
    if grep -qaF "$old/" "/proc/$pid/cmdline" 2> /dev/null; then
      say "stopping $(basename "$pidfile" .pid) (pid $pid) left by an earlier check in $old"
      $sudo kill -TERM "$pid" 2> /dev/null || true
    fi
  done
  rm -f "$old/owner.pid"
done

work=$(mktemp -d "${TMPDIR:-/tmp}/ringid-slurm-check.XXXXXX")
echo $$ > "$work/owner.pid"
export SLURM_CONF=$work/slurm.conf
started=()  # pid files of the daemons this check started
stop_all() {
  local status=$?
  set +e
  if [ -f "$work/slurmctld.pid" ]; then  # no task of ours left running under slurmstepd
    scancel --quiet --user="$(id -un)" 2> /dev/null
    wait_for 20 idle
  fi
  local f pid
  for ((i = ${#started[@]} - 1; i >= 0; --i)); do  # slurmd, slurmctld, then munged
    f=${started[i]}
    pid=$(cat "$work/$f.pid" 2> /dev/null) || continue
    $sudo kill -TERM "$pid" 2> /dev/null
    wait_for 10 gone "$pid" || $sudo kill -KILL "$pid" 2> /dev/null
  done
  if [ $status -eq 0 ]; then
    $sudo rm -rf "$work"
  else
    echo "slurm_check: logs kept in $work" >&2
  fi
}
trap stop_all EXIT
trap 'exit 143' TERM INT

# The cluster: one node, this machine. Free ports, so that another cluster
# (the system's, another check's) is left alone.
read -r ctld_port node_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
host=$(hostname -s)
memory=$(awk '/MemTotal/ { m = int($2 / 1024 / 4); print (m < 1024 ? m : 1024) }' /proc/meminfo)
mkdir -p "$work/munge" "$work/state" "$work/spool"
chmod 700 "$work/munge"
cat > "$SLURM_CONF" <<EOF
ClusterName=ringidcheck
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/state/slurmctld.pid
SlurmdPidFile=$work/spool/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
KillWait=5
MinJobAge=3600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=check Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
if command -v mungekey > /dev/null; then
  mungekey --create --keyfile="$work/munge/key"
else
  dd if=/dev/urandom of="$work/munge/key" bs=1024 count=1 status=none
fi
chmod 400 "$work/munge/key"
$sudo chown -R root:root "$work/munge"
t_start=$SECONDS
# Each daemon in the foreground, in the background here, its pid recorded.
start() {
  local name=$1; shift
  $sudo "$@" > "$work/$name.out" 2>&1 &
  echo $! > "$work/$name.pid"
  started+=("$name")
}
start munged munged --foreground --force --key-file="$work/munge/key" \
  --socket="$work/munge/socket" --pid-file="$work/munge/pid" \
  --log-file="$work/munge/log" --seed-file="$work/munge/seed"
wait_for 20 test -S "$work/munge/socket" || fail "munged did not start: $(cat "$work/munged.out")"
start slurmctld slurmctld -D -f "$SLURM_CONF"
start slurmd slurmd -D -f "$SLURM_CONF"
node_idle() { [ "$(sinfo -h -n "$host" -o %T 2> /dev/null)" = idle ]; }
wait_for 60 node_idle || fail "node $host not idle: $(sinfo -N 2>&1); see $work/*.log"
say "one-node cluster up in $((SECONDS - t_start))s: $(sinfo -h -N -o '%N %c CPUs %m MB %T')"

# The campaign: 8 demo datasets; case004, task 0's second, at 2 speeds (twice
# the modes, 3 times case000's work) so that it is still being fitted when
# task 0's first report appears and the cancel lands.
campaign=$work/campaign reports=$work/reports
bash scripts/campaign_demo.sh "$campaign" 8 > /dev/null
"$ringid" simulate --parameters=datasets/paper/parameters.json --seed=5 --set=m_a=15 \
  --speeds=0,30 --output="$campaign/datasets/case004.json" \
  --truth="$campaign/truth/case004.json" > /dev/null
# The campaigns guide's job script, its placeholders pointed at this campaign.
awk '/^A Slurm job array/ { f = 1 } f && /^```sh$/ { b = 1; next } b && /^```$/ { exit } b' docs/guides/campaigns.md |
  sed "s|/data/campaign|$campaign/datasets|; s|/data/reports|$reports|" > "$work/job.sh"
grep -q -- "--shard=slurm" "$work/job.sh" && grep -qF "$reports" "$work/job.sh" ||
  fail "no job-array script using /data/campaign, /data/reports and --shard=slurm in docs/guides/campaigns.md"
say "job script (docs/guides/campaigns.md):"; sed 's/^/    /' "$work/job.sh"
# Two tasks at once on this 2-CPU node: one CPU each, not the guide's 2.
submit() {
  timeout 300 sbatch --parsable --array=0-3%2 --cpus-per-task=1 --chdir="$root" \
    --output="$work/slurm-%A_%a.out" "$@" "$work/job.sh" | cut -d';' -f1
}
shard0() { local n=0 f; for f in case000 case004; do [ ! -e "$reports/$f.json" ] || n=$((n + 1)); done; echo $n; }
shard0_started() { [ "$(shard0)" -ge 1 ]; }

t1=$SECONDS
job=$(submit)
say "submitted array job $job (--array=0-3%2)"
wait_for 120 shard0_started ||
  fail "task 0 wrote no report within 120 s: $(cat "$work"/slurm-"${job}"_0.out 2>&1)"
scancel "${job}_0"
say "task 0 has written its first report ($(cd "$reports" && echo case00[04].json)); scancel ${job}_0"
wait_for 180 idle || fail "array job $job still running after 180 s"
state=$(scontrol show job "${job}_0" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
kept0=$(shard0)
[ "$state" = CANCELLED ] || fail "task 0 is $state, not CANCELLED: $(cat "$work/slurm-${job}_0.out")"
[ "$kept0" -lt 2 ] || fail "task 0 wrote both its reports before the cancel landed"
say "task cancelled: ${job}_0 is $state with $kept0 of 2 reports written; its log:"
sed 's/^/    /' "$work/slurm-${job}_0.out"
for i in 1 2 3; do
  s=$(scontrol show job "${job}_$i" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
  [ "$s" = COMPLETED ] || fail "task $i is $s: $(cat "$work/slurm-${job}_$i.out")"
done
# What was reported before the resubmission, to see that it is kept unchanged.
(cd "$reports" && for f in case*.json; do echo "$f $(stat -c %y "$f") $(sha256sum < "$f")"; done) \
  > "$work/before.txt"

job2=$(submit --wait) || fail "the resubmitted array failed: $(tail -n 3 "$work"/slurm-*.out)"
say "resubmitted the whole array as job $job2; all 4 tasks done in $((SECONDS - t1))s since the first submission"
(cd "$reports" && for f in case*.json; do echo "$f $(stat -c %y "$f") $(sha256sum < "$f")"; done) \
  > "$work/after.txt"
"$ringid" merge --output_dir="$reports" > /dev/null
# The serial run: the same script outside Slurm, without --shard.
sed "s| --shard=slurm||; s|$reports|$work/serial|" "$work/job.sh" > "$work/serial.sh"
t2=$SECONDS
(cd "$root" && bash "$work/serial.sh" > "$work/serial.out" 2>&1) || fail "serial run: $(cat "$work/serial.out")"
say "serial run (the same script, no --shard, outside Slurm) in $((SECONDS - t2))s"

python3 - "$work" "$kept0" <<'PY'
import json, sys
work, kept0 = sys.argv[1], int(sys.argv[2])
before = dict(l.split(" ", 1) for l in open(f"{work}/before.txt").read().splitlines())
after = dict(l.split(" ", 1) for l in open(f"{work}/after.txt").read().splitlines())
ok = True
for i in range(4):
    shard = json.load(open(f"{work}/reports/campaign.{i}-of-4.json"))
    rows = shard["datasets"]
    kept = [r["report_file"].split("/")[-1] for r in rows if r.get("resumed")]
    fitted = [r["report_file"].split("/")[-1] for r in rows if not r.get("resumed")]
    reported = [f for f in (r["report_file"].split("/")[-1] for r in rows) if f in before]
    unchanged = all(before[f] == after.get(f) for f in kept)
    good = sorted(kept) == sorted(reported) and shard["resumed"] == len(kept) and unchanged
    good = good and (i != 0 or (len(kept) == kept0 and len(fitted) == len(rows) - kept0))
    ok = ok and good
    what = "task resumed" if i == 0 else "task kept"
    print(f"slurm_check: {what}: task {i} of the resubmitted array kept {len(kept)} of {len(rows)} "
          f"({', '.join(kept) or 'none'}; files unchanged: {'yes' if unchanged else 'NO'}), "
          f"fitted {len(fitted)} ({', '.join(fitted) or 'none'}){'' if good else '  <- WRONG'}")
def table(path):
    return [{k: v for k, v in r.items() if k not in ("seconds", "report_file", "resumed")}
            for r in json.load(open(path))["datasets"]]
merged, serial = table(f"{work}/reports/campaign.json"), table(f"{work}/serial/campaign.json")
same = merged == serial and len(merged) == 8 and all(r["status"] == "success" for r in merged)
print(f"slurm_check: merged == serial: {'yes' if same else 'NO'} "
      f"({len(merged)} rows from 4 shard summaries; timings aside)")
sys.exit(0 if ok and same else 1)
PY
say "passed in $((SECONDS - t_install))s (package check $((t_install))s)"
