#!/usr/bin/env bash
# Builds the Box2D 2.4.1 reference for the benchmark's box piles (src/Benchmarks/box2d/box_pile.cpp)
# against Debian's libbox2d-dev, and prints the path of the program.
#   bash scripts/box2d-reference.sh              installs libbox2d-dev when it is missing (root or sudo)
#   bash scripts/box2d-reference.sh --no-install  only builds, when the package is already there
#   bash scripts/box2d-reference.sh [--no-install] SCENE.txt [--runs K]   builds, then runs it on a pile
# The pile file is what the benchmark writes (see Box2dReference.SceneText). On any failure it says why
# on standard error, in one line, and exits 1; the benchmark then reports Box2D as not run, with that line.
set -euo pipefail
cd "$(dirname "$0")/.."

install=1
if [ "${1:-}" = "--no-install" ]; then install=0; shift; fi

src=src/Benchmarks/box2d/box_pile.cpp
out=src/Benchmarks/box2d/bin
program="$out/box_pile"

have_box2d() { [ -f /usr/include/box2d/box2d.h ] && dpkg-query -W -f='${Status}' libbox2d-dev 2>/dev/null | grep -q "install ok installed"; }

if ! have_box2d; then
  if [ "$install" = 0 ]; then
    echo "box2d-reference: libbox2d-dev (Box2D 2.4.1) is not installed; scripts/box2d-reference.sh installs it" >&2
    exit 1
  fi
  mkdir -p "$out"
  if ! bash scripts/install-deps.sh box2d 2>"$out/install.log"; then
    echo "box2d-reference: libbox2d-dev could not be installed: $(tail -n1 "$out/install.log")" >&2
    exit 1
  fi
fi
version="$(dpkg-query -W -f='${Version}' libbox2d-dev 2>/dev/null || true)"
case "$version" in
  2.4.1*) ;;
  *) echo "box2d-reference: libbox2d-dev is version ${version:-unknown}, not 2.4.1" >&2; exit 1 ;;
esac

if ! command -v g++ >/dev/null 2>&1; then
  echo "box2d-reference: g++ is not installed" >&2
  exit 1
fi
mkdir -p "$out"
if [ ! -x "$program" ] || [ "$src" -nt "$program" ]; then
  if ! g++ -O2 -std=c++17 -o "$program.tmp" "$src" -lbox2d 2>"$out/build.log"; then
    echo "box2d-reference: the reference did not build: $(head -n1 "$out/build.log")" >&2
    exit 1
  fi
  mv "$program.tmp" "$program"
fi

if [ $# -gt 0 ]; then
  exec "$program" "$@"
fi
echo "$program"
