#!/usr/bin/env bash
# Sylva's end-to-end timings on the L+C benchmark suite (../shared/lpfg-bench),
# side by side with lpfg when it is built.
#
#   bench/side_by_side.sh                 # Sylva alone
#   LPFG_ROOT=/path/to/vlab bench/side_by_side.sh   # with lpfg: ratios
#
# With lpfg (LPFG_ROOT as ../shared/tools/build-lpfg.sh makes it) this runs
# ../shared/tools/perf-compare.sh, interleaving the two programs, with
# `sylva run --string none` as Sylva's derive-only run, and prints the ratios
# lpfg time / Sylva time (derive only; Sylva's --string FILE against lpfg's
# -out; first run with an empty cache). Extra perf-compare settings pass
# through the environment (MODELS, PAIRS, OOFS for the two vlab objects ...).
#
# Without lpfg it times Sylva alone, median of ROUNDS runs: the 0-step run,
# derive only, the string written to a file, and the first run.
#
# Environment: SYLVA (default build/src/sylva), BENCH (the suite's folder),
# WORK (scratch, default ./perf-work), ROUNDS (default 3).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
export SYLVA=${SYLVA:-$root/build/src/sylva}
SYLVA=$(realpath "$SYLVA")
BENCH=${BENCH:-$root/../shared/lpfg-bench}
WORK=${WORK:-$PWD/perf-work}
ROUNDS=${ROUNDS:-3}
[ -x "$SYLVA" ] || { echo "no sylva at $SYLVA: build it first (README.md)" >&2; exit 1; }
[ -d "$BENCH" ] || { echo "no benchmark suite at $BENCH (set BENCH)" >&2; exit 1; }
mkdir -p "$WORK"

if [ -n "${LPFG_ROOT:-}" ] && [ -x "$LPFG_ROOT/bin/lpfg" ]; then
  export BENCH WORK OUT=${OUT:-$WORK} SYLVA_DERIVE="$here/sylva_derive.sh"
  bash "$root/../shared/tools/perf-compare.sh"
  python3 - "$OUT/perf-summary.tsv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1]), delimiter='\t'))
get = lambda m, s, k: next((float(r[k]) for r in rows if r['model'] == m and r['system'] == s and r['phase'] == 'derive'), float('nan'))
print('| model | derive only | `--string FILE` vs lpfg `-out` | first run (lpfg / Sylva s) | peak MB (lpfg / Sylva) |')
print('|---|--:|--:|--:|--:|')
for m in dict.fromkeys(r['model'] for r in rows):
    derive = get(m, 'lpfg', 'derive_wall_s') / get(m, 'sylva-drv', 'derive_wall_s')
    out = get(m, 'lpfg-out', 'full_wall_med') / get(m, 'sylva', 'full_wall_med')
    print(f"| {m} | {derive:.2f} | {out:.2f} | {get(m, 'lpfg', 'first_run_wall_med'):.2f} / "
          f"{get(m, 'sylva', 'first_run_wall_med'):.2f} | {get(m, 'lpfg', 'peak_rss_mb'):.0f} / "
          f"{get(m, 'sylva-drv', 'peak_rss_mb'):.0f} |")
PY
  exit 0
fi

echo "lpfg not built (LPFG_ROOT): Sylva alone, median of $ROUNDS runs" >&2
export SYLVA_CACHE_DIR="$WORK/sylva-cache"
median() { sort -g | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
timed() {  # prints "wall_s max_rss_kb" of one run
  /usr/bin/time -f '%e %M' -o "$WORK/time.txt" "$@" >/dev/null 2>"$WORK/stderr.txt" ||
    { cat "$WORK/stderr.txt" >&2; exit 1; }
  cat "$WORK/time.txt"
}
printf '| model | 0 steps s | derive only s | --string FILE s | peak MB | first run s |\n|---|--:|--:|--:|--:|--:|\n'
for dir in "$BENCH"/*/; do
  m=$(basename "$dir")
  [ -f "$dir/lsystem.l" ] || continue
  cp -r "$dir" "$WORK/$m" 2>/dev/null || true
  model="$WORK/$m/lsystem.l"
  "$SYLVA" run "$model" -n 0 --string none  # compiles once
  zero=() derive=() written=() rss=() first=()
  for ((k = 0; k < ROUNDS; ++k)); do
    zero+=("$(timed "$SYLVA" run "$model" -n 0 --string none | cut -d' ' -f1)")
    read -r w r < <(timed "$SYLVA" run "$model" --string none); derive+=("$w"); rss+=("$r")
    written+=("$(timed "$SYLVA" run "$model" --string "$WORK/$m/string.txt" | cut -d' ' -f1)")
    first+=("$(SYLVA_CACHE_DIR=$(mktemp -d "$WORK/first.XXXX") timed "$SYLVA" run "$model" -n 0 --string none | cut -d' ' -f1)")
  done
  rm -rf "$WORK"/first.* "$WORK/$m/string.txt"
  printf '| %s | %s | %s | %s | %.0f | %s |\n' "$m" \
    "$(printf '%s\n' "${zero[@]}" | median)" "$(printf '%s\n' "${derive[@]}" | median)" \
    "$(printf '%s\n' "${written[@]}" | median)" "$(echo "$(printf '%s\n' "${rss[@]}" | median) / 1024" | bc -l)" \
    "$(printf '%s\n' "${first[@]}" | median)"
done
