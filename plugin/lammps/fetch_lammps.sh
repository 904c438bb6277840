#!/usr/bin/env bash
# Fetches LAMMPS stable 4 Feb 2025, the upstream tarball of Debian trixie's
# `lammps` source package (20250204+dfsg.1-2), through a private apt list
# (the machine's own apt sources stay as they are), checks its SHA-256 and
# unpacks cmake/ and src/ into DEST. Usage: plugin/lammps/fetch_lammps.sh DEST
# Does nothing when DEST already holds this version.
set -euo pipefail
dest=$1
version=20250204+dfsg.1-2
tarball=lammps_20250204+dfsg.1.orig.tar.xz
sha256=3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7
if [ -f "$dest/.fetched-$sha256" ]; then exit 0; fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. /etc/os-release
uri=$(grep -h -m1 -E '^URIs:.*debian/?$' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2; exit}' || true)
uri=${uri:-http://deb.debian.org/debian}
mkdir -p "$work/lists/partial"
echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $uri trixie main" > "$work/sources.list"
apt_opts=(-o "Dir::Etc::SourceList=$work/sources.list" -o Dir::Etc::SourceParts=/dev/null
          -o "Dir::State::Lists=$work/lists" -o APT::Sandbox::User=root)
echo "fetch_lammps: fetching LAMMPS $version (132 MB) from Debian trixie's source archive"
(cd "$work" && apt-get "${apt_opts[@]}" update -q >apt.log 2>&1 &&
   apt-get "${apt_opts[@]}" source --download-only --tar-only "lammps=$version" >>apt.log 2>&1) \
  || { cat "$work/apt.log"; echo "fetch_lammps: apt-get source lammps=$version failed" >&2; exit 1; }
echo "$sha256  $work/$tarball" | sha256sum -c --quiet - \
  || { echo "fetch_lammps: $tarball: SHA-256 differs from $sha256" >&2; exit 1; }
rm -rf "$dest"
mkdir -p "$dest"
tar -xf "$work/$tarball" -C "$dest" --strip-components=1 --wildcards 'lammps-4Feb2025/cmake/*' 'lammps-4Feb2025/src/*'
touch "$dest/.fetched-$sha256"
echo "fetch_lammps: LAMMPS source ready in $dest"
