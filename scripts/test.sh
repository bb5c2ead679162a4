#!/usr/bin/env bash
# Runs every test: engine, command line, presenter and the real window under Xvfb; then the engine's
# tests again on its netstandard2.0 build (the one the app loads) under Mono.
# Installs what the tests need (Mono, Xvfb, xdotool, ImageMagick) when it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh test

results="$(mktemp -d)"
trap 'rm -rf "$results"' EXIT
status=0
# A test that stops making progress is killed after 20 minutes (and named), rather than holding CI to its limit.
dotnet test PhysicsEngine.sln -c Release --blame-hang-timeout 20m --logger "trx" --results-directory "$results" "$@" || status=$?

# One plain count over every test project, read from the TRX files.
passed=0; failed=0; skipped=0
for f in "$results"/*.trx; do
  [ -f "$f" ] || continue
  line=$(grep -o '<Counters [^>]*>' "$f" | head -n 1)
  p=$(sed -n 's/.* passed="\([0-9]*\)".*/\1/p' <<<"$line"); passed=$((passed + ${p:-0}))
  x=$(sed -n 's/.* failed="\([0-9]*\)".*/\1/p' <<<"$line"); failed=$((failed + ${x:-0}))
  n=$(sed -n 's/.* notExecuted="\([0-9]*\)".*/\1/p' <<<"$line"); skipped=$((skipped + ${n:-0}))
done

# The engine's tests on its netstandard2.0 build: the code paths that only .NET Framework and Mono
# take (no 256-bit vectors). A net48 program with its own small runner (tests/Engine.Tests.Mono).
echo "Engine tests on the netstandard2.0 build, under Mono:"
mono_status=0
if dotnet build tests/Engine.Tests.Mono -c Release -nologo -v q >"$results/mono-build.txt" 2>&1; then
  mono tests/Engine.Tests.Mono/bin/Release/net48/Engine.Tests.exe | tee "$results/mono.txt" || mono_status=$?
else
  cat "$results/mono-build.txt"
  mono_status=1
fi
mp=0; mf=0; ms=0
mono_line=$(grep -E '^mono: [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$' "$results/mono.txt" 2>/dev/null | tail -n 1 || true)
if [ -n "$mono_line" ]; then
  read -r mp mf ms < <(sed 's/mono: \([0-9]*\) passed, \([0-9]*\) failed, \([0-9]*\) skipped/\1 \2 \3/' <<<"$mono_line")
else
  mono_line="mono: no result (the build or the run stopped early)"
  mono_status=1
fi
[ "$status" -eq 0 ] && status=$mono_status

# Each run on its own line, then one plain closing line over both.
echo "dotnet: $passed passed, $failed failed, $skipped skipped"
echo "$mono_line"
echo "tests: $((passed + mp)) passed, $((failed + mf)) failed, $((skipped + ms)) skipped"
if [ "$status" -eq 0 ] && [ "$passed" -eq 0 ]; then
  echo "no test ran" >&2
  exit 1
fi
exit "$status"
