#!/usr/bin/env bash
# Starts the classroom simulator on Linux: installs Mono and libgdiplus from the distribution when
# they are missing, builds the app (net48) and runs it under Mono. Arguments go to the app.
#   bash scripts/run.sh                  build, then run
#   bash scripts/run.sh --no-build ...   run the build that is there (the GUI tests start the app this way)
#   bash scripts/run.sh lesson.json      open that scene at the start (a path from where you are)
set -euo pipefail

# A scene file named relative to where the script was started from: made absolute before the cd
# below, so "bash scripts/run.sh my-scene.json" opens the file in the caller's folder. The values
# of --gas, --stats and --frame-benchmark (a number, or a lesson scene's name) stay as they are.
caller="$PWD"
args=()
takes_value=0
for a in "$@"; do
  if [ "$takes_value" = 1 ]; then
    takes_value=0
  elif [[ "$a" == --gas || "$a" == --stats || "$a" == --frame-benchmark ]]; then
    takes_value=1
  elif [[ "$a" != -* && "$a" != /* ]]; then
    a="$caller/$a"
  fi
  args+=("$a")
done
set -- ${args[@]+"${args[@]}"}
cd "$(dirname "$0")/.."

if [ "${1:-}" = "--no-build" ]; then
  shift
else
  bash scripts/install-deps.sh app
  dotnet build src/SimulatorApp/SimulatorApp.vbproj -c "${CONFIGURATION:-Release}" -nologo -v quiet
fi

# Mono's X input method can crash the app (SIGSEGV in Xutf8LookupString) when a key types a letter
# outside ASCII (é on a French keyboard) and the locale's character set is not UTF-8. Turn the
# input method off (plain key lookup still types é, ß and €) unless the user chose a style, and
# use a UTF-8 character set so those keys type their letters. The app does the same for itself
# when started without this script; doing it here as well covers Mono versions that read the
# settings before the app can set them.
export MONO_WINFORMS_XIM_STYLE="${MONO_WINFORMS_XIM_STYLE:-disabled}"
if [ "$(locale charmap 2>/dev/null || true)" != "UTF-8" ]; then
  export LC_ALL=C.UTF-8
fi

exec mono "src/SimulatorApp/bin/${CONFIGURATION:-Release}/net48/SimulatorApp.exe" "$@"
