#!/usr/bin/env bash
# The Debian package of this build (CPack, as `make package` makes it from a Release build):
# lintian finds no error in it, its dependencies were computed from the binaries, and it holds
# the files a user needs. Usage: package_test.sh BUILD_DIR
set -euo pipefail
build=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() {
  echo "package_test: $*" >&2
  exit 1
}

(cd "$build" && cpack -G DEB -B "$out" >/dev/null)
deb=$(ls "$out"/relief_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
# OpenImageIO and Assimp are linked by the modules only: dpkg-shlibdeps must find them there.
for package in libqt6widgets6 libopenimageio2.4 libassimp5 qt6-qpa-plugins; do
  case "$depends" in
    *"$package"*) ;;
    *) fail "Depends lacks $package: $depends" ;;
  esac
done
contents=$(dpkg-deb -c "$deb")
for path in ./usr/bin/relief ./usr/bin/relief-cli ./usr/share/relief/samples/bricks/bricks.relief \
  ./usr/libexec/relief/relief-cli-render \
  ./usr/share/applications/org.reliefeditor.Relief.desktop ./usr/share/doc/relief/copyright; do
  grep -q " $path\$" <<<"$contents" || fail "the package lacks $path"
done
# The modules, in lib/relief or lib/<arch>/relief (GNUInstallDirs' choice for the prefix).
for module in librelief_oiio.so librelief_assimp.so; do
  grep -qE " \./usr/lib/([^/]+/)?relief/$module\$" <<<"$contents" || fail "the package lacks $module"
done
# Errors fail; warnings and infos are printed for the log.
lintian --fail-on error "$deb"
echo "package_test: $(basename "$deb"), $(stat -c %s "$deb") bytes, lintian without errors"
