#!/usr/bin/env bash
# A longer monkey run than CI's: random clicks, drags, keys, text (accented too), sliders, saves and
# opens in the real window under Xvfb, then the same checks (the app answers, no body inside
# another or outside the walls, every saved scene opens, no NaN or ∞ on screen).
#   bash scripts/monkey.sh [ACTIONS] [SEED]     default 1000 actions, seed from the clock
set -euo pipefail
cd "$(dirname "$0")/.."

actions="${1:-1000}"
seed="${2:-$(date +%s)}"
bash scripts/install-deps.sh test
echo "monkey: $actions actions, seed $seed (rerun the same with: bash scripts/monkey.sh $actions $seed)"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
status=0
MONKEY_ACTIONS="$actions" MONKEY_SEED="$seed" dotnet test tests/App.Tests -c Release \
  --filter "FullyQualifiedName~MonkeyGuiTests" --logger "console;verbosity=detailed" >"$out" 2>&1 || status=$?
grep -E "monkey:|Passed!|Failed!|Error Message" -A3 "$out" | grep -v "^--$" | head -40
exit "$status"
