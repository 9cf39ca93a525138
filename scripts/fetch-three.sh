#!/usr/bin/env bash
# Re-fetches the vendored three.js of the scene view (crates/cli/assets/three/) from the npm
# registry with `npm pack`, and checks it against the stored SHA-256 sums.
#
# Pinned: three@0.170.0, the last release whose `build/three.module.min.js` is one file (from
# r171 on it imports `three.core.min.js`), so the page inlines it as one module script.
#
#   scripts/fetch-three.sh          # fetch into a scratch folder, compare with the vendored copy
#   scripts/fetch-three.sh --write  # fetch, check the sums, and (re)write the vendored copy
set -euo pipefail
cd "$(dirname "$0")/.."
VERSION=0.170.0
DEST=crates/cli/assets/three
# sha256 of the npm tarball and of the two files kept
TGZ_SHA=4a608a355dcaba72e0e5383cdc814303f5b6060b43c238cdf6932dceb699238d
JS_SHA=08fd7545d13d2c7fb65ab691530a802dafefd638596501854f267d0fb13c39e7
LICENSE_SHA=4c40a1ef62450b857c3b2aaf294936304cd552d965fbcd9d32d4c5bcf4ba4454

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
(cd "$scratch" && npm pack --silent "three@$VERSION" >/dev/null)
tgz="$scratch/three-$VERSION.tgz"
check() { # file expected-sha
    local got
    got=$(sha256sum "$1" | cut -d' ' -f1)
    if [ "$got" != "$2" ]; then
        echo "fetch-three: $1 has sha256 $got; expected $2" >&2
        exit 1
    fi
}
check "$tgz" "$TGZ_SHA"
tar -xzf "$tgz" -C "$scratch" package/build/three.module.min.js package/LICENSE
check "$scratch/package/build/three.module.min.js" "$JS_SHA"
check "$scratch/package/LICENSE" "$LICENSE_SHA"
if [ "${1:-}" = "--write" ]; then
    mkdir -p "$DEST"
    cp "$scratch/package/build/three.module.min.js" "$DEST/three.module.min.js"
    cp "$scratch/package/LICENSE" "$DEST/LICENSE"
    echo "$VERSION" >"$DEST/VERSION"
    echo "fetch-three: wrote three@$VERSION into $DEST"
else
    check "$DEST/three.module.min.js" "$JS_SHA"
    check "$DEST/LICENSE" "$LICENSE_SHA"
    echo "fetch-three: the vendored three@$(cat "$DEST/VERSION") matches the registry's three@$VERSION"
fi
