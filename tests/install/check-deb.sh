#!/usr/bin/env bash
# The Debian package (docs/packaging.md): `apt-get install ./candela_*.deb` on this machine installs
# it with nothing else to fetch (its Depends are this machine's libraries); /usr/bin/candela renders
# the default scene and a sample model (DamagedHelmet, when the shared assets are there) from an
# empty folder; `apt-get purge candela` then removes every file it installed and leaves every other
# package as it was. Needs root (or sudo without a password) and no candela package installed
# already; otherwise skipped (exit 77).
#   tests/install/check-deb.sh PACKAGE_DIR SOURCE_DIR    (ctest: package.deb)
set -euo pipefail
packages=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
fail() { echo "FAIL: $*" >&2; exit 1; }

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo -n true 2>/dev/null || { echo "skipped: installing a package needs root or sudo without a password"; exit 77; }
  sudo="sudo -n"
fi
command -v apt-get >/dev/null || { echo "skipped: no apt-get"; exit 77; }
if dpkg-query -W -f='${Status}' candela 2>/dev/null | grep -q "install ok installed"; then
  echo "skipped: a candela package is installed already; the test would replace and remove it"
  exit 77
fi
debs=("$packages"/candela_*_amd64.deb)
[ -f "${debs[0]}" ] || fail "no .deb in $packages (the package.build test makes it)"

tmp=$(mktemp -d)
installed=""
cleanup() {
  [ -n "$installed" ] && $sudo env DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq candela >/dev/null 2>&1 || true
  rm -rf "$tmp"
}
trap cleanup EXIT

dpkg-query -W -f='${Package} ${Version} ${Status}\n' | grep -v '^candela ' | sort > "$tmp/before"
echo "Depends: $(dpkg-deb -f "${debs[0]}" Depends)"
installed=yes
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${debs[0]}" > "$tmp/apt.log" 2>&1 ||
  { cat "$tmp/apt.log"; fail "apt-get install ${debs[0]}"; }
dpkg-query -L candela > "$tmp/files"
echo "installed: $(wc -l < "$tmp/files") paths"
[ "$(command -v candela)" = /usr/bin/candela ] || fail "candela is not /usr/bin/candela on PATH"
for file in /usr/share/man/man1/candela.1 /usr/share/bash-completion/completions/candela /usr/share/doc/candela/copyright; do
  grep -qx "$file" "$tmp/files" || fail "$file is not in the package"
done

mkdir "$tmp/empty"
(
  cd "$tmp/empty"
  export XDG_CACHE_HOME=$tmp/cache
  candela --version
  candela render --width 96 --height 54 --out grid.png || fail "the default scene"
  [ -s grid.png ] || fail "no grid.png"
  helmet=${CANDELA_SHARED_ASSETS:-$source/../shared/assets}/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
  if [ -f "$helmet" ]; then
    candela render --scene "$helmet" --width 96 --height 96 --out helmet.png || fail "DamagedHelmet"
    [ -s helmet.png ] || fail "no helmet.png"
  else
    echo "note: $helmet is absent; only the default scene rendered"
  fi
  # Debian's Python finds the module without PYTHONPATH.
  env -u PYTHONPATH /usr/bin/python3 "$source/tests/install/check-python.py" /usr || fail "import candela"
)

$sudo env DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq candela > "$tmp/apt.log" 2>&1 ||
  { cat "$tmp/apt.log"; fail "apt-get purge candela"; }
installed=""
dpkg-query -W candela >/dev/null 2>&1 && fail "dpkg still knows the candela package"
while read -r path; do
  [ -d "$path" ] && continue  # folders other packages share (/usr/share/man/man1)
  [ -e "$path" ] && fail "$path is left behind"
done < "$tmp/files"
[ -e /usr/share/doc/candela ] && fail "/usr/share/doc/candela is left behind"
dpkg-query -W -f='${Package} ${Version} ${Status}\n' | grep -v '^candela ' | sort > "$tmp/after"
diff "$tmp/before" "$tmp/after" || fail "installing and removing candela changed other packages"
echo "ok"
