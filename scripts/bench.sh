#!/usr/bin/env bash
# Speed against error: builds the benchmark in Release and runs it.
#   bash scripts/bench.sh            the full run (every scene, dt and gas size; about 15 minutes on 2 cores):
#                                    rewrites docs/benchmarks.md, docs/benchmark-*.svg and the README's figures
#   bash scripts/bench.sh --quick    a run of about a minute, for CI: written to a scratch folder (printed at
#                                    the end), never over the committed report; add --out DIR to keep it
# The box piles also run in Box2D 2.4.1 (scripts/box2d-reference.sh builds it; the full run installs
# libbox2d-dev when missing, the quick run only uses it when present).
# Other options go to the benchmark, e.g. --json results.json (see: dotnet src/Benchmarks/bin/Release/net10.0/Benchmarks.dll --help).
set -euo pipefail
cd "$(dirname "$0")/.."

# The commit just before the event solver's restructure. The full run builds the engine and benchmark
# of this commit apart (in a scratch folder) and times its elastic gas beside the engine now, so the
# report shows that the gas is no slower than before the restructure.
BASELINE_COMMIT=4f483eebcd2f32da4c7cdaed442b4ff9934acc19

dotnet build src/Benchmarks/Benchmarks.vbproj -c Release -nologo -v quiet

quick=0
if [[ " $* " == *" --quick "* ]]; then quick=1; fi

# The full run also measures the app's frame budget under Xvfb when mono is here, so build the app too.
if [ "$quick" = 0 ] && command -v mono >/dev/null 2>&1; then
  dotnet build src/SimulatorApp/SimulatorApp.vbproj -c Release -nologo -v quiet ||
    echo "bench: the app did not build; the frame budget section will say so" >&2
fi

# The baseline build: the commit's files from git (git archive: the work tree and the repository's
# list of work trees are left as they are), built in Release in a scratch folder removed at the end.
# Anything that goes wrong becomes a note in the report, never the end of the run.
baseline=()
scratch=""
trap 'if [ -n "$scratch" ]; then rm -rf "$scratch"; fi' EXIT
if [ "$quick" = 0 ]; then
  short="${BASELINE_COMMIT:0:7}"
  if ! git cat-file -e "${BASELINE_COMMIT}^{commit}" 2>/dev/null; then
    baseline=(--baseline-note "not run: commit $short is not in this clone (a shallow clone has no history: git fetch --unshallow, then run again).")
  else
    scratch="$(mktemp -d -t bench-baseline.XXXXXX)"
    echo "bench: building the engine at $short (before the event solver's restructure) in $scratch"
    if ! git archive --format=tar "$BASELINE_COMMIT" | tar -x -C "$scratch"; then
      baseline=(--baseline-note "not run: the files of commit $short could not be unpacked (git archive).")
    elif ! dotnet build "$scratch/src/Benchmarks/Benchmarks.vbproj" -c Release -nologo -v quiet >"$scratch/build.log" 2>&1; then
      why="$(grep -m1 -E 'error|Error' "$scratch/build.log" | sed -e "s|$scratch/||g" | cut -c1-300 || true)"
      echo "bench: the engine at $short did not build: ${why:-see the build log}" >&2
      baseline=(--baseline-note "not run: the benchmark of commit $short did not build (${why:-no error line in its build log}).")
    else
      baseline=(--baseline-dll "$scratch/src/Benchmarks/bin/Release/net10.0/Benchmarks.dll")
    fi
  fi
  baseline+=(--baseline-commit "$BASELINE_COMMIT")
fi

# Box2D 2.4.1 on the same box piles, for comparison (scripts/box2d-reference.sh): the full run installs
# it when it is missing; the quick run uses it only when it is already installed. A failure becomes a
# note in the report ("not run: ..."), never the end of the run.
box2d_flags=()
if [ "$quick" = 1 ]; then box2d_flags=(--no-install); fi
box2d_err="$(mktemp -t bench-box2d.XXXXXX)"
if box2d_program="$(bash scripts/box2d-reference.sh ${box2d_flags[@]+"${box2d_flags[@]}"} 2>"$box2d_err")"; then
  box2d=(--box2d "$box2d_program")
else
  why="$(tail -n1 "$box2d_err" | sed -e 's/^box2d-reference: //')"
  box2d=(--box2d-note "not run: ${why:-the Box2D reference did not build}.")
fi
rm -f "$box2d_err"

out=(--out docs --readme README.md)
if [ "$quick" = 1 ]; then
  out=(--out "$(mktemp -d -t bench-quick.XXXXXX)")
fi
if [[ " $* " == *" --out "* ]]; then
  out=()
fi
dotnet src/Benchmarks/bin/Release/net10.0/Benchmarks.dll "${out[@]}" ${baseline[@]+"${baseline[@]}"} "${box2d[@]}" "$@"
