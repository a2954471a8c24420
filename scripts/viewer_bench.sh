#!/usr/bin/env bash
# Frame times of the animated viewer (docs/performance.md): adds the harness
# render/viewer/bench.js (never part of a shipped page) to a page written by
# `gridlock animate`, plays FRAMES frames in headless Chromium and prints the
# page's bench summary as JSON (ms_per_frame: script, style and layout).
#   scripts/viewer_bench.sh PAGE.html [FRAMES] [full]
# "full" recomputes every part and region each frame (the baseline).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
page=${1:?usage: scripts/viewer_bench.sh PAGE.html [FRAMES] [full]}
frames=${2:-600}
mode=${3:-}
chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] || { echo "viewer_bench.sh: chromium is not installed (scripts/setup.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$page" "$root/render/viewer/bench.js" "$work/bench.html" <<'PY'
import sys
page = open(sys.argv[1], encoding='utf-8').read()
harness = open(sys.argv[2], encoding='utf-8').read()
end = page.rfind('</body>')
if end < 0:
    sys.exit('viewer_bench.sh: %s is not a gridlock animation page' % sys.argv[1])
open(sys.argv[3], 'w', encoding='utf-8').write(page[:end] + '<script>\n' + harness + '</script>\n' + page[end:])
PY
hash="#bench=$frames${mode:+&$mode}"
timeout 600 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$work/profile" --window-size=1000,700 \
  --virtual-time-budget=3000 --dump-dom "file://$work/bench.html$hash" 2>/dev/null |
  python3 -c '
import html, json, re, sys
m = re.search(r"<pre id=\"state\">(.*?)</pre>", sys.stdin.read(), re.S)
if not m: sys.exit("viewer_bench.sh: the page wrote no state")
s = json.loads(html.unescape(m.group(1)))
if s.get("errors"): sys.exit("viewer_bench.sh: script errors: %s" % s["errors"])
print(json.dumps(s["bench"]))'
