#!/usr/bin/env bash
# How whole runs speed up with threads, against what the machine gives the
# same work run as independent processes.
#
#   bench/scaling.sh                       # koch, bush-context, decomposition, structs
#   MODELS="koch structs" THREADS="1 2" ROUNDS=11 bench/scaling.sh
#
# For each model and thread count n it times, in interleaved rounds:
#   - one run on n threads (`sylva run --string none --threads n`);
#   - n one-thread runs started together, which share nothing but the
#     machine (cores, caches, memory bandwidth, the hypervisor's page
#     faults).
# and prints the medians with two ratios: the speed-up of the n-thread run
# over one thread, and the machine's capacity, n × (one run alone) / (n runs
# together): the speed-up n independent runs get. On a virtual machine whose
# cores share memory bandwidth, or whose fresh pages are slow to fault in,
# the capacity is well under n, and no threading of one run beats it.
#
# Environment: SYLVA (default build/src/sylva), BENCH (the L+C benchmark
# suite, default ../shared/lpfg-bench), MODELS, THREADS (default 1 2 4 ... up
# to the cores), ROUNDS (default 7), WORK (scratch, default ./perf-work).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
SYLVA=$(realpath "${SYLVA:-$root/build/src/sylva}")
BENCH=${BENCH:-$root/../shared/lpfg-bench}
MODELS=${MODELS:-koch bush-context decomposition structs}
ROUNDS=${ROUNDS:-7}
WORK=${WORK:-$PWD/perf-work}
if [ -z "${THREADS:-}" ]; then
  THREADS=1
  for ((n = 2; n <= $(nproc); n *= 2)); do THREADS="$THREADS $n"; done
fi
[ -x "$SYLVA" ] || { echo "no sylva at $SYLVA: build it first (README.md)" >&2; exit 1; }
mkdir -p "$WORK"
export SYLVA_CACHE_DIR="$WORK/sylva-cache"
for model in $MODELS; do
  [ -f "$BENCH/$model/lsystem.l" ] || { echo "no model $BENCH/$model/lsystem.l (set BENCH)" >&2; exit 1; }
  "$SYLVA" run "$BENCH/$model/lsystem.l" --string none --threads 1 >/dev/null  # compiled outside the timing
done

python3 - "$SYLVA" "$BENCH" "$ROUNDS" "$MODELS" "$THREADS" <<'PY'
import statistics, subprocess, sys, time
sylva, bench, rounds = sys.argv[1], sys.argv[2], int(sys.argv[3])
models, threads = sys.argv[4].split(), [int(n) for n in sys.argv[5].split()]

def timed(commands):
    """Seconds until every command, all started at once, has ended."""
    start = time.perf_counter()
    running = [subprocess.Popen(c, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE) for c in commands]
    for p in running:
        _, err = p.communicate()
        if p.returncode != 0:
            sys.exit(f"{' '.join(commands[0])} failed:\n{err.decode()}")
    return time.perf_counter() - start

print(f"median of {rounds} interleaved rounds, seconds")
print("| model | threads | one run | speed-up | that many one-thread runs at once | capacity |")
print("|---|--:|--:|--:|--:|--:|")
for model in models:
    run = lambda n: [sylva, "run", f"{bench}/{model}/lsystem.l", "--string", "none", "--threads", str(n)]
    alone, together = {n: [] for n in threads}, {n: [] for n in threads}
    for _ in range(rounds):
        for n in threads:
            alone[n].append(timed([run(n)]))
            if n > 1: together[n].append(timed([run(1)] * n))
    one = statistics.median(alone[1]) if 1 in alone else float("nan")
    for n in threads:
        t = statistics.median(alone[n])
        if n == 1:
            print(f"| {model} | 1 | {t:.3f} | 1 | | 1 |")
            continue
        c = statistics.median(together[n])
        print(f"| {model} | {n} | {t:.3f} | {one / t:.2f} | {c:.3f} | {n * one / c:.2f} |")
PY
