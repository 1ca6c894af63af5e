#!/bin/sh
# Rewrites the Golden pictures (tests/data/glman/expected, compared by
# test_glman's Golden.MatchesTheStoredPicture) from Glimmer's own rendering
# on OSMesa. The only way to change them: a test run never writes them, and
# one started with GLIMMER_UPDATE_EXPECTED set fails (issue 26).
#
#   tools/update-golden.sh BUILD_DIR            # every Golden picture
#   tools/update-golden.sh BUILD_DIR teapot     # only these
#
# BUILD_DIR is a build folder configured with -DGLIMMER_TESTS=ON. Then look at
# every picture it wrote (git status tests/data/glman/expected) before committing.
set -eu
if [ $# -lt 1 ]; then
    echo "usage: tools/update-golden.sh BUILD_DIR [NAME...]" >&2
    exit 2
fi
build=$1
shift
cmake --build "$build" --target glimmer_update_golden -j2
"$build/tests/glimmer_update_golden" "$@"
