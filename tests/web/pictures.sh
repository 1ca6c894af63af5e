#!/usr/bin/env bash
# A script drawn in the page is the picture `glimmer render` draws of it,
# within what two rasterizers may differ by (same_picture): an ES scene at
# its default and with a value set as --set sets it (which must change the
# picture), the seed bloom and a compatibility scene through the page's
# translation, uniform initialisers; and tools/render-web.sh prints the
# page's messages as text.
# Usage: tests/web/pictures.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

# An ES scene (drawn as written) and the seed bloom and a glman classroom
# scene (desktop GLSL, translated in the page by glslang and SPIRV-Cross).
# The seed bloom at its grid texture's own size, 512x512: at 256x256 the
# 2:1 minification samples the grid exactly between texels, where the two
# rasterizers may each take either neighbour (948 one-pixel grid-line
# edges, 1.4%, PSNR 49.7 dB: the same class of tie as an edge on a pixel
# centre, but over a whole line).
# Uniform initialisers (`uniform float uY0 = 1.;`), which GLSL ES 3.00 has
# not, set by the page itself (issue 31).
for case in "tests/data/web/lit_es.glib||256x256" "tests/data/web/lit_es.glib|uStripes=3|256x256" \
            "scripts/bloom.glib|uAdd=2|512x512" "tests/data/web/compat_scene.glib||256x256" \
            "tests/data/web/uniform_init.glib||64x64"; do
  IFS='|' read -r script sets size <<<"$case"
  desk="$pictures/desktop.png" shot="$pictures/page.png"
  args=(); [ -n "$sets" ] && args=(--set "$sets")
  "$g" -q render "$script" --size "$size" "${args[@]}" -o "$desk"
  echo "  page against render: $script ${sets:-(defaults)} at $size"
  if page_picture "$script" "$size" "$sets" "$shot" && same_picture "$shot" "$desk"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "DIFFERS: $script drawn in the page ${sets:+with $sets }is not render's picture"
  fi
  [ "$script" = tests/data/web/lit_es.glib ] && cp "$shot" "$pictures/page_${sets:-default}.png" 2>/dev/null
done
# The set value reached the picture: the two page pictures differ.
[ "$(compare -metric AE "$pictures/page_default.png" "$pictures/page_uStripes=3.png" null: 2>&1)" -gt 1000 ]
tally $? "uStripes=3 did not change the page's picture"

# render-web.sh prints the page's messages as glimmer render does: text,
# not the page's markup around each file:line:col (issue 31).
said="$(WEB_BUILD="$web" tools/render-web.sh tests/data/web/broken.glib -o "$pictures/broken.png" 2>&1 >/dev/null)"
[[ "$said" == *": error: "* && "$said" != *"<"*">"* ]]
tally $? "render-web.sh printed markup or no error for broken.glib: $said"

finish
