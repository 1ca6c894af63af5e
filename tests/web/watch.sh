#!/usr/bin/env bash
# A watch in the page (issue 28): for the same twelve expressions over the
# seed and the exercises as tests/cli/watch_test.cpp, a watch with range
# 0,1 is byte for byte the picture of the shader hand-edited in the page to
# write that value as its colour (tools/page-watch.mjs: both drawn by the
# page's WebGL 2, the hand edit through the page's files as the editor
# writes them); the desktop's `render --watch` of the same expression is the
# same picture within what two rasterizers differ by (same_picture: the
# exercise's sharp blur at its own 512x512, where a smaller screen samples it
# between texels and the two rasterizers may each take either); and a
# refusal is worded as `glimmer check --watch` words it.
# Usage: tests/web/watch.sh DESKTOP_GLIMMER WEB_BUILD_DIR (tests/web/page_lib.sh)
source "$(dirname "$0")/page_lib.sh"

cat > "$pictures/cases.json" <<'JSON'
[{"script": "scripts/bloom.glib", "shader": "shaders/bloom.frag", "line": 11, "expression": "rgb", "colour": "rgb"},
 {"script": "scripts/bloom.glib", "shader": "shaders/bloom.frag", "line": 12, "expression": "rgbblur", "colour": "rgbblur", "sets": ["uHalfSize=3"]},
 {"script": "scripts/bloom.glib", "shader": "shaders/bloom.frag", "line": 12, "expression": "rgbblur.g", "colour": "vec3( rgbblur.g )", "sets": ["uHalfSize=3"]},
 {"script": "scripts/bloom.glib", "shader": "shaders/bloom.frag", "line": 12, "expression": "vST", "colour": "vec3( vST, 0. )"},
 {"script": "scripts/bloom.glib", "shader": "shaders/bloom.frag", "line": 12, "expression": "uAdd*rgbblur*0.25", "colour": "uAdd*rgbblur*0.25", "sets": ["uAdd=3", "uHalfSize=3"]},
 {"script": "scripts/bloom.glib", "shader": "shaders/superblur.frag", "line": 31, "expression": "rgbSum", "colour": "rgbSum", "unit": 6, "sets": ["uHalfSize=3"]},
 {"script": "scripts/bloom.glib", "shader": "shaders/superblur.frag", "line": 16, "expression": "float(halfSize)/11.", "colour": "vec3( float(halfSize)/11. )", "unit": 6, "sets": ["uHalfSize=5"]},
 {"script": "scripts/exercises/ex2_threshold.glib", "shader": "scripts/exercises/bright.frag", "line": 13, "expression": "luminance", "colour": "vec3( luminance )", "unit": 6},
 {"script": "scripts/exercises/ex2_threshold.glib", "shader": "scripts/exercises/bright.frag", "line": 13, "expression": "luminance > uThreshold ? c : vec3(0.)", "colour": "luminance > uThreshold ? c : vec3(0.)", "unit": 6, "sets": ["uThreshold=0.5"]},
 {"script": "scripts/exercises/ex2_threshold.glib", "shader": "scripts/exercises/add.frag", "line": 14, "expression": "blur", "colour": "blur", "sets": ["uSigma=1"], "size": 512},
 {"script": "scripts/exercises/ex3_separable.glib", "shader": "scripts/exercises/gauss1d.frag", "line": 18, "expression": "texel * 100.", "colour": "vec3( texel * 100., 0. )", "unit": 7},
 {"script": "scripts/exercises/ex5_hdr.glib", "shader": "scripts/exercises/tonemap.frag", "line": 14, "expression": "mapped", "colour": "mapped"}]
JSON
NODE_PATH=/usr/share/nodejs timeout 600 node tools/page-watch.mjs "file://$page" "$pictures/cases.json" "$pictures" \
  > "$pictures/page.json" 2> "$pictures/page.err"
echo "  the page: exit $?"
[ -s "$pictures/page.json" ] || { cat "$pictures/page.err"; tally 1 "tools/page-watch.mjs said nothing"; finish; exit; }

count="$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))))' "$pictures/cases.json")"
for ((i = 0; i < count; i++)); do
  IFS=$'\t' read -r script shader line expression size sets < <(python3 -c '
import json, sys
c = json.load(open(sys.argv[1]))[int(sys.argv[2])]
print("\t".join([c["script"], c["shader"], str(c["line"]), c["expression"], str(c.get("size", 96)),
                 " ".join("--set " + s for s in c.get("sets", []))]))' \
    "$pictures/cases.json" "$i")
  said="$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["said"][int(sys.argv[2])])' "$pictures/page.json" "$i")"
  echo "  $said"
  # The page's watch against the page's hand edit: the same bytes.
  [[ "$said" == "watch $shader:$line $expression, "*"range 0 .. 1 (fixed)"* && "$said" != *outside* ]] &&
    [ "$(compare -metric AE "$pictures/watch-$i.png" "$pictures/hand-$i.png" null: 2>&1)" = "0" ]
  tally $? "$shader:$line $expression: the page's watch is not the page's hand-edited picture ($said)"
  # The desktop's render --watch of the same: the same picture, two rasterizers apart.
  # shellcheck disable=SC2086
  "$g" render "$script" --size "${size}x$size" $sets --watch-range 0,1 --watch "$shader:$line:$expression" \
    -o "$pictures/desktop-$i.png" >/dev/null 2>&1 &&
    same_picture "$pictures/desktop-$i.png" "$pictures/watch-$i.png"
  tally $? "$shader:$line $expression: the page's watch is not the desktop's render --watch"
done

# The panel's watch controls, clicked as a student would (issue 39: in the
# page they did nothing, and the checks above drive the watch by command):
# the Watch field typed into and its button, the range's two fields typed
# into and Fix range, then Own range, then Stop; each does what its command does.
clicks="$(NODE_PATH=/usr/share/nodejs timeout 300 node tools/page-watch-controls.mjs "file://$page" scripts/bloom.glib \
  'bloom.frag:12 rgbblur' 0.25 0.75 2> "$pictures/clicks.err")"
echo "  clicked: $clicks"
[ -n "$clicks" ] || cat "$pictures/clicks.err"
step() { python3 -c 'import json, sys; print(json.loads(sys.argv[1])[sys.argv[2]][sys.argv[3]])' "$clicks" "$1" "$2" 2>/dev/null; }
[ "$(step typed spec)" = "bloom.frag:12 rgbblur" ] && [[ "$(step typed summary)" == "vec3 over "*"(its own)"* ]] &&
  [ -z "$(step typed error)" ]
tally $? "typing a watch into the panel's field and clicking Watch did not watch it: $(step typed summary)"
[[ "$(step fixed summary)" == *"range 0.25 .. 0.75 (fixed)"* ]]
tally $? "the range typed into the panel's fields and Fix range did not fix it: $(step fixed summary)"
[[ "$(step own summary)" == *"(its own)"* ]]
tally $? "Own range did not give the values' own range back: $(step own summary)"
[ -n "$(step stopped spec)" ] && [ -z "$(step stopped summary)" ]
tally $? "Stop did not stop the watch: $(step stopped summary)"

# A refusal, in the words of the command line.
want="$("$g" check scripts/bloom.glib --watch 'bloom.frag:11:rgbblur' 2>&1 | grep -A2 ': error: ')"
got="$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["refusal"])' "$pictures/page.json")"
echo "  the page refused: $got"
[ -n "$want" ] && [ "$got" = "$want" ]
tally $? "the page's refusal differs from check --watch's: '$got' against '$want'"
finish
