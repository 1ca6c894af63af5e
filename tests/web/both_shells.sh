#!/usr/bin/env bash
# One viewer core, two shells (issue 25): the same commands, typed into
# `glimmer view`'s standard input (a real window under Xvfb) and run in the
# page's live view (glimmerPage.command, tools/page-commands.mjs), must say
# the same and save the same pictures:
# - a slider value moved, the heavy blur then redrawn in slices in both
#   (slice budget 2 ms: `frames` reports more than one slice; the probe
#   before it finishes the picture, so a loaded machine still slow to draw
#   it cannot make it look unsliced);
# - the probe at a pixel gives that pixel's values (the two rasterizers,
#   llvmpipe and SwiftShader, may differ by a step: 0.02);
# - "Show values" burns the same box into a saved picture in both;
# - the pass inspector shows the blur target, saved alike;
# - a value out of its range and an unknown name get the same messages.
# Usage: tests/web/both_shells.sh DESKTOP_GLIMMER WEB_BUILD_DIR (tests/web/page_lib.sh)
source "$(dirname "$0")/page_lib.sh"
gabs="$(realpath "$g")"
work="$pictures"
mkdir "$work/desktop" "$work/page"
command -v xvfb-run >/dev/null || { echo "web $group: xvfb-run is missing: run tools/install-deps.sh"; exit 1; }

# The commands, with pauses ("wait MS") where a student would let it draw.
cat > "$work/commands" <<'EOF'
set uAdd 2.5
set uHalfSize 5
wait 5000
probe 100 200
frames
probe 300 40
values on
save values.png
values off
save plain.png
show 6
probe 10 10
save shown.png
show screen
set uAdd 9
set uNoSuch 1
quit
EOF

# The window: each line on its standard input after the pause before it.
(
  sleep 3  # the window opens and draws its first picture
  while IFS= read -r line; do
    if [[ "$line" =~ ^wait\ ([0-9]+)$ ]]; then sleep "$(bc -l <<<"${BASH_REMATCH[1]} / 1000")"; continue; fi
    echo "$line"
    sleep 0.3
  done < "$work/commands"
) | (cd "$work/desktop" && GLIMMER_SLICE_MS=2 timeout 120 xvfb-run -a -s "-screen 0 1400x1000x24" \
      "$gabs" view "$OLDPWD/scripts/bloom.glib" --size 512x512 > stdout 2> stderr)
echo "  the window: exit $?"
# What the window said in answer to the commands: `frames` on stdout, the
# rest on stderr after "glimmer view: " (its own lines about loading and
# the ui scale are not answers).
python3 - "$work/desktop" > "$work/desktop.said" <<'PY'
import sys
d = sys.argv[1]
frames = [l.rstrip("\n") for l in open(d + "/stdout") if l.startswith("frames:")]
for line in open(d + "/stderr"):
    line = line.rstrip("\n")
    if not line.startswith("glimmer view: "):
        continue
    said = line[len("glimmer view: "):]
    if said.startswith(("loaded", "ui scale", "reloaded", "font ")):
        continue
    if said.startswith("saved "):
        said = "saved " + said[len("saved "):].rsplit("/", 1)[-1]
    print(said)
print("\n".join(frames))
PY

# The page: the same lines through glimmerPage.command.
NODE_PATH=/usr/share/nodejs timeout 240 node tools/page-commands.mjs "file://$page" scripts/bloom.glib 512x512 2 \
    "$work/commands" "$work/page" > "$work/page.json" 2> "$work/page.err"
echo "  the page: exit $?"
python3 - "$work/page.json" > "$work/page.said" <<'PY'
import json, sys
said = json.load(open(sys.argv[1]))["said"]
frames = [s for s in said if s.startswith("frames:")]
for s in said:
    if s and not s.startswith("frames:"):
        print(s)
print("\n".join(frames))
PY
echo "  the window said:"; sed 's/^/    /' "$work/desktop.said"
echo "  the page said:"; sed 's/^/    /' "$work/page.said"

# Same answers, line for line; the probe's numbers within a step of the
# two rasterizers (0.02), `frames` only in its slice count (> 1 in both).
python3 - "$work/desktop.said" "$work/page.said" <<'PY'
import re, sys
a = open(sys.argv[1]).read().splitlines()
b = open(sys.argv[2]).read().splitlines()
num = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")
def same(x, y):
    if x.startswith("frames:") and y.startswith("frames:"):
        return True  # times differ by machine; the slices are checked below
    if x.startswith("probe (") and y.startswith("probe ("):
        nx, ny = num.findall(x), num.findall(y)
        return (num.sub("#", x) == num.sub("#", y) and len(nx) == len(ny)
                and all(abs(float(p) - float(q)) <= 0.02 for p, q in zip(nx, ny)))
    return x == y
ok = len(a) == len(b) and len(a) >= 7 and all(same(x, y) for x, y in zip(a, b))
sys.exit(0 if ok else 1)
PY
tally $? "the window and the page answered the same commands differently (above)"

# The heavy blur was drawn in slices in both (a budget of 2 ms cannot hold
# an 11x11 blur of 512x512 on either rasterizer).
for who in desktop page; do
  slices="$(grep -oE '[0-9]+ slices?\)' "$work/$who.said" | head -1 | tr -dc 0-9)"
  [ -n "$slices" ] && [ "$slices" -gt 1 ]
  tally $? "$who: the redraw after 'set uHalfSize 5' was not drawn in slices: $(grep frames: "$work/$who.said")"
done

# The probe read the saved picture: (100, 200) of the desktop's plain.png.
python3 - "$work/desktop.said" "$work/desktop/plain.png" <<'PY'
import re, subprocess, sys
line = next(l for l in open(sys.argv[1]) if l.startswith("probe (100, 200)"))
got = [float(v) for v in re.findall(r"[rgb] (\S+)", line)]
px = subprocess.run(["convert", sys.argv[2], "-crop", "1x1+100+200", "-depth", "8", "txt:-"],
                    capture_output=True, text=True).stdout
want = [int(v) / 255 for v in re.search(r"\((\d+),(\d+),(\d+)", px.splitlines()[-1]).groups()]
sys.exit(0 if all(abs(g - w) <= 1 / 255 + 1e-6 for g, w in zip(got, want)) else 1)
PY
tally $? "the window's 'probe 100 200' is not pixel (100, 200) of its saved picture"

# The pictures: each the same in both shells (within what two rasterizers
# differ by), and the values box really there (values.png is not plain.png).
for png in plain.png values.png shown.png; do
  echo "  $png: the window's against the page's"
  [ -s "$work/desktop/$png" ] && [ -s "$work/page/$png" ] && same_picture "$work/desktop/$png" "$work/page/$png"
  tally $? "$png differs between the window and the page"
done
for who in desktop page; do
  boxed="$(compare -metric AE "$work/$who/values.png" "$work/$who/plain.png" null: 2>&1)"
  [ "${boxed%% *}" -gt 2000 ] 2>/dev/null
  tally $? "$who: 'values on' put no values box on the saved picture ($boxed pixels differ)"
done
# And the plain picture is render's at those values.
"$g" -q render scripts/bloom.glib --size 512x512 --set uAdd=2.5 --set uHalfSize=5 -o "$work/render.png"
echo "  plain.png: the window's against render"
same_picture "$work/desktop/plain.png" "$work/render.png"
tally $? "the window's picture after the commands is not render's with the same --set"

finish
