#!/usr/bin/env bash
# The installed program, as a user gets it: `cmake --install` into a staging prefix, then the
# installed relief-cli finds the installed samples (not the source tree's) and renders one;
# its render helper and modules are where the executables look for them (a TGA is read through
# the OpenImageIO module; without the module the message says to reinstall);
# the desktop entry, AppStream metadata and MIME type pass their validators
# (desktop-file-validate, appstreamcli, update-mime-database). Usage: install_test.sh BUILD_DIR
set -euo pipefail
build=$1
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
fail() {
  echo "install_test: $*" >&2
  exit 1
}

cmake --install "$build" --prefix "$stage/usr" >/dev/null
cli=$stage/usr/bin/relief-cli
share=$stage/usr/share
# lib/relief, or lib/<arch>/relief when the prefix is /usr (GNUInstallDirs).
modules=$(dirname "$(find "$stage/usr/lib" -name librelief_oiio.so | head -1)")
for file in "$stage/usr/bin/relief" "$cli" "$share/relief/samples/bricks/bricks.relief" \
  "$stage/usr/libexec/relief/relief-cli-render" "$modules/librelief_oiio.so" \
  "$modules/librelief_assimp.so" \
  "$share/applications/org.reliefeditor.Relief.desktop" \
  "$share/metainfo/org.reliefeditor.Relief.metainfo.xml" \
  "$share/mime/packages/org.reliefeditor.Relief.xml" \
  "$share/icons/hicolor/scalable/apps/org.reliefeditor.Relief.svg" \
  "$share/icons/hicolor/256x256/apps/org.reliefeditor.Relief.png" \
  "$share/man/man1/relief-cli.1.gz" "$share/doc/relief/copyright"; do
  [ -e "$file" ] || fail "not installed: ${file#"$stage"}"
done

# The installed CLI reports the installed samples folder (the build's would be the source tree).
samples=$("$cli" --version | sed -n 's/^samples: //p')
[ "$samples" = "$share/relief/samples" ] || fail "installed relief-cli uses samples from '$samples'"

# It renders an installed sample (under the test run's X display), at the size asked for.
out=$stage/render.png
"$cli" render "$share/relief/samples/bricks/bricks.relief" --out "$out" --size 160x120 \
  || fail "installed relief-cli render failed"
"$cli" info "$out" | grep -q "160x120" || fail "the render is not 160x120: $("$cli" info "$out")"

# A file only OpenImageIO reads loads the installed module (the run path from bin/ to lib/).
convert "$out" "$stage/render.tga"
"$cli" info "$stage/render.tga" | grep -q "format: targa" \
  || fail "the installed relief-cli cannot read a TGA: $("$cli" info "$stage/render.tga" 2>&1)"
# Without the module, the same command fails and says why.
mv "$modules/librelief_oiio.so" "$stage/moved.so"
if message=$("$cli" info "$stage/render.tga" 2>&1); then
  fail "relief-cli read a TGA without its OpenImageIO module"
fi
grep -q "librelief_oiio.so, which cannot be loaded.*reinstall Relief" <<<"$message" \
  || fail "a missing module is reported as: $message"
mv "$stage/moved.so" "$modules/librelief_oiio.so"

desktop-file-validate "$share/applications/org.reliefeditor.Relief.desktop"
appstreamcli validate --no-net "$share/metainfo/org.reliefeditor.Relief.metainfo.xml" >/dev/null \
  || appstreamcli validate --no-net "$share/metainfo/org.reliefeditor.Relief.metainfo.xml"
# The MIME database built from the installed package file knows *.relief.
XDG_DATA_DIRS="$share:/usr/share" update-mime-database "$share/mime" 2>&1 | (! grep .) \
  || fail "update-mime-database complained"
grep -q '\*\.relief' "$share/mime/globs2" || fail "*.relief is not in the MIME globs"
echo "install_test: installed under a staging prefix, rendered $samples/bricks/bricks.relief"
