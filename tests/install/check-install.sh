#!/usr/bin/env bash
# The install tree (docs/packaging.md): `cmake --install BUILD --prefix P` into a temporary folder
# puts the executable, the manual page, the shell completions and the docs where GNUInstallDirs
# says; nothing installed holds the path of the source or build folder; the manual page formats
# without a warning; the completions parse in bash, zsh and fish and complete a command, a flag
# and an enum's names; the installed candela renders the default scene in an empty folder.
#   tests/install/check-install.sh BUILD_DIR SOURCE_DIR     (ctest: install.tree)
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/opt/candela
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
for file in bin/candela share/man/man1/candela.1 share/bash-completion/completions/candela \
            share/zsh/vendor-completions/_candela share/fish/vendor_completions.d/candela.fish \
            share/doc/candela/README.md share/doc/candela/docs/architecture.md share/doc/candela/docs/images; do
  [ -e "$prefix/$file" ] || fail "$file is not installed"
done
[ -x "$prefix/bin/candela" ] || fail "bin/candela is not executable"
echo "installed: $(find "$prefix" -type f | wc -l) files, $(du -sh "$prefix" | cut -f1)"

# No path of this machine's trees inside (__FILE__, debug information, shader file names).
held=$(grep -rlF -e "$source/" -e "$build/" "$prefix" || true)
[ -z "$held" ] || fail "these installed files hold the path of $source or $build: $held"

man=$prefix/share/man/man1/candela.1
if command -v groff >/dev/null; then
  warnings=$(groff -man -Tutf8 -ww -z "$man" 2>&1)
  [ -z "$warnings" ] || fail "groff warns on the manual page: $warnings"
  formatted=$(groff -man -Tutf8 -P -cbou "$man" 2>/dev/null)  # not piped into grep -q (SIGPIPE under pipefail)
  grep -q -- "--shading-path auto|forward|visibility" <<< "$formatted" || fail "the manual page has no --shading-path"
else
  echo "note: no groff; the manual page's formatting is not checked"
fi

bash_completion=$prefix/share/bash-completion/completions/candela
bash -n "$bash_completion" || fail "bash cannot parse the completion"
complete() {  # complete WORD... : what the bash completion offers for the last word
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _candela; printf "%s\n" "${COMPREPLY[@]}"' \
    _ "$bash_completion" "$@"
}
complete candela ren | grep -qx render || fail "bash: 'candela ren' does not complete to render"
complete candela render --shading-p | grep -qx -- --shading-path || fail "bash: no --shading-path for render"
[ "$(complete candela render --shading-path "" | sort | tr '\n' ' ')" = "auto forward visibility " ] ||
  fail "bash: --shading-path does not offer auto, forward and visibility"
complete candela info --shading-p | grep -q . && fail "bash: info is offered render's --shading-path"
for shell in zsh fish; do
  script=$prefix/share/zsh/vendor-completions/_candela
  [ "$shell" = fish ] && script=$prefix/share/fish/vendor_completions.d/candela.fish
  if command -v "$shell" >/dev/null; then
    "$shell" -n "$script" || fail "$shell cannot parse its completion"
  else
    echo "note: no $shell; its completion is not parsed"
  fi
done
if command -v fish >/dev/null; then
  fish -c "source $prefix/share/fish/vendor_completions.d/candela.fish; complete -C 'candela render --shading-path '" |
    cut -f1 | sort | tr '\n' ' ' | grep -qx "auto forward visibility " || fail "fish: --shading-path does not offer its names"
fi

# The installed executable renders from an empty folder.
mkdir "$tmp/empty"
(cd "$tmp/empty" && "$prefix/bin/candela" render --width 96 --height 54 --out grid.png) || fail "the installed candela does not render"
[ -s "$tmp/empty/grid.png" ] || fail "no grid.png"
# The Python module from the prefix's dist-packages (python/CMakeLists.txt).
python=/usr/bin/python3
site=$(find "$prefix/lib" -maxdepth 2 -name dist-packages -type d)
[ -n "$site" ] && [ -f "$site/candela/__init__.py" ] || fail "the Python package candela is not installed"
(cd "$tmp/empty" && env PYTHONPATH="$site" "$python" "$source/tests/install/check-python.py" "$prefix") ||
  fail "the installed Python module does not render"
echo "ok"
