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
# Flat or not: the mean of the first quarter of the samples against that of the last quarter (the
# managed heap saws up and down between collections, so single samples say little), and the largest.
awk '
  /^stats / {
    n++
    for (i = 2; i <= NF; i++) { split($i, kv, "="); val[n, kv[1]] = kv[2] + 0 }
  }
  function mean(key, from, to,   s, k) { s = 0; for (k = from; k <= to; k++) s += val[k, key]; return s / (to - from + 1) }
  function most(key,   m, k) { m = 0; for (k = 1; k <= n; k++) if (val[k, key] > m) m = val[k, key]; return m }
  END {
    if (n == 0) exit 1
    q = int(n / 4); if (q < 1) q = 1
    frames = 0; for (k = 1; k <= n; k++) frames += val[k, "frames"]
    printf "soak: %d samples, %d frames; first quarter -> last quarter (largest)\n", n, frames
    printf "  resident memory   %7.1f -> %7.1f MB   (%.1f MB)\n", mean("rss_mb", 1, q), mean("rss_mb", n - q + 1, n), most("rss_mb")
    printf "  managed heap      %7.1f -> %7.1f MB   (%.1f MB)\n", mean("heap_mb", 1, q), mean("heap_mb", n - q + 1, n), most("heap_mb")
    printf "  frame interval    %7.2f -> %7.2f ms median, 95th percentile %.2f -> %.2f ms (%.2f ms)\n", mean("interval_median_ms", 1, q), mean("interval_median_ms", n - q + 1, n), mean("interval_p95_ms", 1, q), mean("interval_p95_ms", n - q + 1, n), most("interval_p95_ms")
    printf "  engine step       %7.2f -> %7.2f ms median (%.2f ms at the 95th percentile, worst minute)\n", mean("step_median_ms", 1, q), mean("step_median_ms", n - q + 1, n), most("step_p95_ms")
    printf "  canvas paint      %7.2f -> %7.2f ms median (%.2f ms at the 95th percentile, worst minute)\n", mean("paint_median_ms", 1, q), mean("paint_median_ms", n - q + 1, n), most("paint_p95_ms")
  }' "$log"
