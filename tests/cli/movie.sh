#!/usr/bin/env bash
# The film of the default ride (python/slidesim/movie.py), a few frames:
# `python3 -m slidesim.movie` and `slidesim-plot --movie` write an .mp4 with
# ffmpeg (1280 x 720, exactly the frames asked, larger than an empty film),
# a .gif with Pillow when asked for one (the frames asked); a result that is
# not a ride is refused naming the file (exit status 1, no film). Needs
# Debian's ffmpeg and python3-matplotlib (scripts/install-dependencies.sh).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
unset DISPLAY
export PYTHONPATH=$root/python${PYTHONPATH:+:$PYTHONPATH}
command -v ffmpeg >/dev/null || { echo "FAIL ffmpeg not found (scripts/install-dependencies.sh installs it)"; exit 1; }
"$slidesim" -q -o "$work/ride.h5" >/dev/null 2>&1 || fail "slidesim (the default ride)"
frames=4
frames_of() {   # FILM: its number of frames
  ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$1"
}
"$python" -m slidesim.movie "$work/ride.h5" -o "$work/ride.mp4" --frames $frames >"$work/out" 2>&1 \
  || { cat "$work/out"; fail "python3 -m slidesim.movie"; }
if [ -f "$work/ride.mp4" ]; then
  [ "$(frames_of "$work/ride.mp4")" = "$frames" ] || fail "ride.mp4 has $(frames_of "$work/ride.mp4") frames, not $frames"
  size=$(ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$work/ride.mp4")
  [ "$size" = "1280,720" ] || fail "ride.mp4 is $size, not 1280,720"
  # an empty 4-frame film of this size is about 10 kB; the slide, the rider and the curves make it more
  bytes=$(stat -c %s "$work/ride.mp4")
  [ "$bytes" -gt 20000 ] || fail "ride.mp4 has only $bytes bytes"
else
  fail "no ride.mp4"
fi
ls -a "$work" | grep -q '\.tmp' && fail "a temporary film was left: $(ls -a "$work")"
"$python" -m slidesim.movie "$work/ride.h5" -o "$work/ride.gif" --frames 3 >"$work/out" 2>&1 \
  || { cat "$work/out"; fail "python3 -m slidesim.movie -o ride.gif"; }
gif_frames=$("$python" -c "from PIL import Image; print(Image.open('$work/ride.gif').n_frames)" 2>&1)
[ "$gif_frames" = 3 ] || fail "ride.gif has $gif_frames frames, not 3"
if "$python" -c "import slidesim.plot" 2>/dev/null; then
  "$python" -m slidesim.plot "$work/ride.h5" -o "$work/ride.png" --movie "$work/plot.mp4" --movie-frames 2 >"$work/out" 2>&1 \
    || { cat "$work/out"; fail "slidesim-plot --movie"; }
  [ -s "$work/plot.mp4" ] || fail "slidesim-plot --movie wrote no film"
fi
# not a ride: refused, named, no film
"$slidesim" -q -o "$work/slide.h5" inputs/demo_slide/slide.nml >/dev/null 2>&1 || fail "slidesim slide.nml"
"$python" -m slidesim.movie "$work/slide.h5" -o "$work/slide.mp4" --frames 2 >"$work/out" 2>&1
rc=$?
[ "$rc" = 1 ] || fail "a geometry result: exit status $rc, not 1"
grep -q "slide.h5: a 'geometry' result" "$work/out" || fail "a geometry result: $(cat "$work/out")"
[ -e "$work/slide.mp4" ] && fail "a geometry result left a film"
[ "$failures" = 0 ] && echo "film checks passed"
[ "$failures" = 0 ]
