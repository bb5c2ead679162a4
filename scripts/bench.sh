#!/usr/bin/env bash
# Speed against error: builds the benchmark in Release and runs it.
#   bash scripts/bench.sh            the full run (every scene, dt and gas size; about 15 minutes on 2 cores):
#                                    rewrites docs/benchmarks.md, docs/benchmark-*.svg and the README's figures
#   bash scripts/bench.sh --quick    a run of about a minute, for CI: written to a scratch folder (printed at
#                                    the end), never over the committed report; add --out DIR to keep it
# Other options go to the benchmark, e.g. --json results.json (see: dotnet src/Benchmarks/bin/Release/net10.0/Benchmarks.dll --help).
set -euo pipefail
cd "$(dirname "$0")/.."

dotnet build src/Benchmarks/Benchmarks.vbproj -c Release -nologo -v quiet

# The full run also measures the app's frame budget under Xvfb when mono is here, so build the app too.
if [[ " $* " != *" --quick "* ]] && command -v mono >/dev/null 2>&1; then
  dotnet build src/SimulatorApp/SimulatorApp.vbproj -c Release -nologo -v quiet ||
    echo "bench: the app did not build; the frame budget section will say so" >&2
fi

out=(--out docs --readme README.md)
if [[ " $* " == *" --quick "* ]]; then
  out=(--out "$(mktemp -d -t bench-quick.XXXXXX)")
fi
if [[ " $* " == *" --out "* ]]; then
  out=()
fi
exec dotnet src/Benchmarks/bin/Release/net10.0/Benchmarks.dll "${out[@]}" "$@"
