#!/usr/bin/env bash
# Runs the windowed hush-viewer under Xvfb on lavapipe (no display or GPU needed),
# presses keys as a user would (a chain, side by side), and saves a screenshot of its
# window. docs/integration.md shows one.
#
# Usage: scripts/viewer_screenshot.sh [out.png] [chain key 1-5] [frames folder]
#   Without a frames folder it renders the Cornell box at 128x128 (16 frames).
# Needs xvfb, x11-apps (xwd), imagemagick (convert) and xdotool: installed here when
# missing (as root), not by scripts/setup.sh, which the tests do not need them for.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out="${1:-viewer.png}"
key="${2:-2}"
frames="${3:-}"
hush=build/samples/cli/hush
viewer=build/samples/viewer/hush-viewer

missing=()
for tool in Xvfb:xvfb xwd:x11-apps convert:imagemagick xdotool:xdotool; do
  command -v "${tool%%:*}" > /dev/null || missing+=("${tool#*:}")
done
if (( ${#missing[@]} )); then
  [[ $(id -u) == 0 ]] || { echo "viewer_screenshot: install ${missing[*]} (apt-get, as root)" >&2; exit 2; }
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
[[ -x "$viewer" ]] || { echo "viewer_screenshot: build first (./scripts/test.sh or cmake --build build)" >&2; exit 2; }

work="$(mktemp -d)"
trap 'kill "${viewer_pid:-}" "${xvfb_pid:-}" 2> /dev/null || true; rm -rf "$work"' EXIT
if [[ -z "$frames" ]]; then
  frames="$work/frames"
  "$hush" render --scene cornell --size 128x128 --frames 16 --reference-spp 0 --channels all --out "$frames" > /dev/null
fi

display=":$(( 90 + RANDOM % 9 ))"
Xvfb "$display" -screen 0 800x600x24 > /dev/null 2>&1 &
xvfb_pid=$!
sleep 1
DISPLAY="$display" HUSH_ADAPTER="${HUSH_ADAPTER:-llvmpipe}" "$viewer" --in "$frames" --scale 2 > "$work/viewer.log" 2>&1 &
viewer_pid=$!
window=""
for _ in $(seq 50); do
  window="$(DISPLAY="$display" xdotool search --name "hush viewer" 2> /dev/null | head -1 || true)"
  [[ -n "$window" ]] && break
  sleep 0.2
done
[[ -n "$window" ]] || { cat "$work/viewer.log" >&2; echo "viewer_screenshot: no viewer window" >&2; exit 1; }
DISPLAY="$display" xdotool windowfocus --sync "$window" key "$key" key s
sleep 8   # a few frames on lavapipe, and the title's timings
DISPLAY="$display" xdotool getwindowname "$window"
DISPLAY="$display" xwd -id "$window" -silent | convert xwd:- "$out"
echo "viewer_screenshot: wrote $out"
