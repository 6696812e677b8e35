#!/usr/bin/env bash
# Do other decoders show the same frames? Every preset GIF in scenes/ is decoded by Pillow,
# ffmpeg and ImageMagick, each composited frame as RGB; the script prints, per preset, the
# frame count and a checksum of all frames per decoder, and fails if any two disagree.
# (tests/presets.rs already checks the gif crate's decoding against the renderer's frames.)
#
# Usage: bench/decoders.sh
# Needs python3 with Pillow, ffmpeg, and ImageMagick (convert or magick); Debian/Ubuntu:
# apt-get install -y python3-pil ffmpeg imagemagick
set -euo pipefail
cd "$(dirname "$0")/.."
magick=$(command -v magick || command -v convert || true)
for tool in python3 ffmpeg "$magick"; do
    if [ -z "$tool" ] || ! command -v "$tool" > /dev/null; then
        echo "needs python3 (Pillow), ffmpeg and ImageMagick" >&2
        exit 1
    fi
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
echo "| preset     | frames | Pillow   | ffmpeg   | ImageMagick | same |"
echo "|------------|-------:|----------|----------|-------------|------|"
for gif in scenes/*.gif; do
    name=$(basename "$gif" .gif)
    python3 - "$gif" > "$out/pillow" <<'PY'
import sys
from PIL import Image, ImageSequence
with Image.open(sys.argv[1]) as im:
    for frame in ImageSequence.Iterator(im):
        sys.stdout.buffer.write(frame.convert("RGB").tobytes())
PY
    ffmpeg -v error -i "$gif" -fps_mode passthrough -f rawvideo -pix_fmt rgb24 - > "$out/ffmpeg"
    "$magick" "$gif" -coalesce -depth 8 rgb:- > "$out/magick"
    size=$(python3 -c "from PIL import Image; w, h = Image.open('$gif').size; print(w * h * 3)")
    frames=$(( $(stat -c %s "$out/pillow") / size ))
    sums=()
    for d in pillow ffmpeg magick; do
        sums+=("$(md5sum < "$out/$d" | cut -c1-8)")
    done
    same=yes
    if [ "${sums[0]}" != "${sums[1]}" ] || [ "${sums[0]}" != "${sums[2]}" ]; then
        same=NO
        status=1
    fi
    printf "| %-10s | %6d | %s | %s | %s    | %s  |\n" "$name" "$frames" "${sums[0]}" "${sums[1]}" "${sums[2]}" "$same"
done
exit $status
