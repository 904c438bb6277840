#!/usr/bin/env bash
# Fetches the LIGGGHTS 3.8.0 upstream source from Debian's `liggghts` source
# package (tarball only: the Debian patch archive may not be served) and
# applies plugin/liggghts/patches/*.patch. Usage: plugin/liggghts/fetch_liggghts.sh DEST
# Leaves DEST/src ready; does nothing when DEST already holds this patch set.
set -euo pipefail
dest=$1
here=$(cd "$(dirname "$0")" && pwd)
stamp=$(cat "$here"/patches/*.patch | sha256sum | cut -c1-16)
if [ -f "$dest/.patched-$stamp" ]; then exit 0; fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fetch() { (cd "$work" && apt-get source --tar-only liggghts >"$work/apt.log" 2>&1); }
if ! fetch; then
  # apt-get source needs a deb-src entry: add one for Debian's main archive
  echo "fetch_liggghts: adding a deb-src entry for Debian main and updating the package lists"
  . /etc/os-release
  uri=$(grep -h -m1 -E '^URIs:.*debian/?$' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2}' || true)
  uri=${uri:-http://deb.debian.org/debian}
  cat > /etc/apt/sources.list.d/liggghts-src.sources <<SRC
Types: deb-src
URIs: $uri
Suites: $VERSION_CODENAME
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  apt-get update -q >/dev/null
  fetch || { cat "$work/apt.log"; echo "fetch_liggghts: apt-get source liggghts failed" >&2; exit 1; }
fi
tarball=$(ls "$work"/liggghts_*.orig.tar.* | head -1)
rm -rf "$dest"
mkdir -p "$dest"
tar -xf "$tarball" -C "$dest" --strip-components=1
for p in "$here"/patches/*.patch; do
  patch -s -p1 -d "$dest" < "$p"
done
touch "$dest/.patched-$stamp"
echo "fetch_liggghts: LIGGGHTS source ready in $dest"
