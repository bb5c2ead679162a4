#!/usr/bin/env bash
# Installs, from the distribution, what this project needs beyond the .NET SDK.
#   install-deps.sh app    Mono + WinForms + libgdiplus (to build and run the net48 app)
#   install-deps.sh test   the above + Xvfb, xdotool, ImageMagick, xwininfo, xprop, setxkbmap (GUI tests)
#   install-deps.sh box2d  Box2D 2.4.1 and g++ (the benchmark's reference, scripts/box2d-reference.sh)
# Installs only what is missing; needs root (or sudo) only when something is missing.
set -euo pipefail

case "${1:-app}" in
  app)   want=(mono-runtime mono-devel libmono-system-windows-forms4.0-cil libgdiplus fonts-dejavu-core) ;;
  test)  want=(mono-runtime mono-devel libmono-system-windows-forms4.0-cil libgdiplus fonts-dejavu-core
               xvfb xdotool imagemagick x11-utils x11-xkb-utils) ;;
  box2d) want=(libbox2d-dev g++) ;;
  *) echo "install-deps: unknown set '$1' (app, test or box2d)" >&2; exit 2 ;;
esac

missing=()
for p in "${want[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: missing ${missing[*]}, and this is not a Debian/Ubuntu machine: install them with your package manager." >&2
  exit 1
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
    echo "install-deps: missing ${missing[*]}; run as root or install sudo." >&2; exit 1
  fi
fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
