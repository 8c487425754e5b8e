#!/bin/sh
# Render every certificate page (default: output/*.certificate.html, the pages of the
# identify, calibrate and tensor decks that `make run` ran) in a headless browser to a PNG
# of one A4 page's width (plots/NAME.certificate.png) and check that each page rendered to
# an image of real content; with the default pages, that a tensor deck's page is among
# them.  Needs Chromium (Debian: apt-get install -y
# chromium); without it the check says so and ends with status 0 after doing nothing
# (`make certificate-check` is not part of `make test`).
#   tests/tools/certificate_check.sh [PAGE.html ...]
set -u
browser=""
for b in chromium chromium-browser google-chrome; do
    if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
done
if [ -z "$browser" ]; then
    echo "certificate-check: skipped: no headless browser (install one with: apt-get install -y chromium)"
    exit 0
fi
n=0; bad=0
if [ $# -eq 0 ]; then
    set -- output/*.certificate.html
    # the tensor decks' pages (title 'Inertia tensor of a body from bifilar hangs')
    if ! grep -l 'Inertia tensor of a body' "$@" >/dev/null 2>&1; then
        echo "certificate-check: no tensor deck's page in output/ (run make run first)" >&2
        bad=$((bad + 1))
    fi
fi
mkdir -p plots
shoot() {  # shoot PAGE PNG: one A4 width (794 px = 210 mm at 96 px/in), 3000 px down
    timeout 120 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
        --window-size=794,3000 --screenshot="$2" "file://$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" \
        >/dev/null 2>&1
}
# the size of a blank page's image, as this browser renders it: a page must hold far more
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
printf '<!DOCTYPE html><html><head><title>blank</title></head><body></body></html>\n' > "$tmp/blank.html"
shoot "$tmp/blank.html" "$tmp/blank.png"
blank=$(wc -c < "$tmp/blank.png" 2>/dev/null || echo 0)
for page in "$@"; do
    [ -f "$page" ] || { echo "certificate-check: $page: no such page (run make run first)" >&2; bad=$((bad + 1)); continue; }
    name=$(basename "$page" .html)
    png=plots/$name.png
    rm -f "$png"
    shoot "$page" "$png"
    size=$(wc -c < "$png" 2>/dev/null || echo 0)
    if [ "$blank" -gt 0 ] && [ "$size" -gt $((blank * 3)) ]; then
        echo "certificate-check: $page -> $png ($size bytes)"
        n=$((n + 1))
    else
        echo "certificate-check: $page did not render ($png: $size bytes, a blank page $blank)" >&2
        bad=$((bad + 1))
    fi
done
echo "certificate-check: $n rendered, $bad failed"
[ "$bad" -eq 0 ]
