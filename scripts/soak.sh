#!/usr/bin/env bash
# The soak run (by hand, not in CI): the app runs the 1000-ball elastic gas in its window under Xvfb
# for a long time, printing its frame times and memory once a minute; at the end a summary says
# whether they stayed flat.
#   bash scripts/soak.sh [MINUTES] [BALLS]     default 30 minutes, 1000 balls
set -euo pipefail
cd "$(dirname "$0")/.."

minutes="${1:-30}"
balls="${2:-1000}"
every=60
[ "$minutes" -lt 5 ] && every=15

bash scripts/install-deps.sh test
dotnet build src/SimulatorApp/SimulatorApp.vbproj -c Release -nologo -v quiet

# A free display from :170 on.
display=170
while [ -e "/tmp/.X11-unix/X$display" ] || [ -e "/tmp/.X$display-lock" ]; do display=$((display + 1)); done
log="$(mktemp)"
Xvfb ":$display" -screen 0 1400x900x24 -nolisten tcp -noreset >/dev/null 2>&1 &
xvfb=$!
cleanup() {
  [ -n "${app:-}" ] && kill "$app" 2>/dev/null || true
  kill "$xvfb" 2>/dev/null || true
  rm -f "$log"
}
trap cleanup EXIT
for _ in $(seq 1 50); do [ -e "/tmp/.X11-unix/X$display" ] && break; sleep 0.1; done

echo "soak: $balls-ball elastic gas in the window for $minutes min, a line every $every s (display :$display)"
DISPLAY=":$display" bash scripts/run.sh --no-build --gas "$balls" --stats "$every" >"$log" 2>&1 &
app=$!
end=$(( $(date +%s) + minutes * 60 ))
while [ "$(date +%s)" -lt "$end" ]; do
  if ! kill -0 "$app" 2>/dev/null; then echo "soak: the app stopped" >&2; cat "$log" >&2; exit 1; fi
  sleep 5
done
kill "$app" 2>/dev/null || true
wait "$app" 2>/dev/null || true
app=""

grep '^stats ' "$log" || { echo "soak: no stats were printed" >&2; cat "$log" >&2; exit 1; }
# Flat or not: the first full minute against the last, and the largest.
awk '
  /^stats / {
    for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] + 0 }
    n++
    if (n == 1) { rss0 = v["rss_mb"]; heap0 = v["heap_mb"]; int0 = v["interval_median_ms"]; step0 = v["step_median_ms"]; paint0 = v["paint_median_ms"] }
    rss = v["rss_mb"]; heap = v["heap_mb"]; intv = v["interval_median_ms"]; p95 = v["interval_p95_ms"]; step = v["step_median_ms"]; paint = v["paint_median_ms"]
    if (rss > rssmax) rssmax = rss
    if (heap > heapmax) heapmax = heap
    if (p95 > p95max) p95max = p95
    frames += v["frames"]
  }
  END {
    if (n == 0) exit 1
    printf "soak: %d samples, %d frames\n", n, frames
    printf "  resident memory  %.1f MB first, %.1f MB last, %.1f MB at most (%+.1f%%)\n", rss0, rss, rssmax, 100 * (rss - rss0) / rss0
    printf "  managed heap     %.1f MB first, %.1f MB last, %.1f MB at most\n", heap0, heap, heapmax
    printf "  frame interval   median %.1f ms first, %.1f ms last; 95th percentile at most %.1f ms\n", int0, intv, p95max
    printf "  engine step      median %.2f ms first, %.2f ms last\n", step0, step
    printf "  canvas paint     median %.2f ms first, %.2f ms last\n", paint0, paint
  }' "$log"
