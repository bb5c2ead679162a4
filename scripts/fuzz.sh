#!/usr/bin/env bash
# A fuzzing campaign: builds the fuzzer in Release and checks N random scenes (seeds 1..N unless --seed
# says otherwise) with every solver. Each failing scene is shrunk to the fewest bodies that still fail and
# written to fuzz-failures/ (or --out DIR), with a README.md line giving the command that shows it.
#   bash scripts/fuzz.sh 1000                  a thousand scenes
#   bash scripts/fuzz.sh 200 --seed 5000       another stretch of seeds
#   bash scripts/fuzz.sh 1 --seed 27           one scene again, as the quick pass names it
#   bash scripts/fuzz.sh 100 --kinds all       with segments, polygons, boxes and links too
# Other options (--solvers, --time, --cap, --bodies, --jobs, --no-shrink, --scene FILE, ...):
#   dotnet src/Fuzzer/bin/Release/net10.0/Fuzzer.dll --help
# Exit 0 when nothing failed, 1 when something did, 2 on bad options.
set -euo pipefail
cd "$(dirname "$0")/.."

count=100
if [ $# -gt 0 ] && [[ "$1" != -* ]]; then
  if ! [[ "$1" =~ ^[1-9][0-9]*$ ]]; then
    echo "fuzz.sh: the scene count must be a whole number of at least 1, not '$1'" >&2
    exit 2
  fi
  count="$1"
  shift
fi

dotnet build src/Fuzzer/Fuzzer.vbproj -c Release -nologo -v quiet
exec dotnet src/Fuzzer/bin/Release/net10.0/Fuzzer.dll --scenes "$count" "$@"
