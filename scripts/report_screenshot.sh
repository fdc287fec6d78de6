#!/usr/bin/env bash
# Opens a sweep's report.html in headless Chromium and saves a screenshot of the page,
# to check that the plots and the crops load (not part of CI: Chromium is large).
# usage: scripts/report_screenshot.sh <sweep folder> [<screenshot.png>] [<width>x<height>]
# Installs Debian's `chromium` with apt when it is missing (as root, or with sudo).
set -euo pipefail

folder="${1:?usage: $0 <sweep folder> [<screenshot.png>] [<width>x<height>]}"
shot="${2:-$folder/report-screenshot.png}"
size="${3:-1280x4000}"
report="$(cd "$folder" && pwd)/report.html"
[[ -f "$report" ]] || { echo "error: $report does not exist (run hush sweep --out $folder first)" >&2; exit 2; }

if ! command -v chromium >/dev/null 2>&1; then
  as_root=()
  [[ "$(id -u)" -ne 0 ]] && as_root=(sudo)
  echo "[screenshot] installing chromium (apt)"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends chromium
fi

# --no-sandbox: the sandbox needs user namespaces, which containers often lack.
# --allow-file-access-from-files: the report's images are files next to it.
chromium --headless --disable-gpu --no-sandbox --hide-scrollbars --allow-file-access-from-files \
  --window-size="${size/x/,}" --screenshot="$shot" "file://$report" 2> "$shot.log" ||
  { echo "error: chromium failed; see $shot.log" >&2; exit 1; }
[[ -s "$shot" ]] || { echo "error: chromium wrote no screenshot; see $shot.log" >&2; exit 1; }
echo "[screenshot] wrote $shot"
