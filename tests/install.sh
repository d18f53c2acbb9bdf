#!/bin/sh
# tests/install.sh: `make install DESTDIR=...` puts the binary, its figure library, the man page, every preset,
# every lesson and the three shell completions where README says, and `make uninstall` takes every one
# of them away again. Uses the build under test ($BUILD, $SPRINGSIM) and the default PREFIX,
# so that nothing is recompiled. Prints "install: N passed, M failed".
NAME=install
. tests/lib/check.sh
BUILD=${BUILD:-build}
stage=$tmp/stage
p=/usr/local

# make TARGET: this tree's Makefile on the build under test, make's own settings kept out.
mk() {
    env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s "$1" BUILD="$BUILD" BIN="$SPRINGSIM" \
        DESTDIR="$stage" >"$tmp/make.out" 2>&1
}

if ! mk install; then
    fail "make install: $(tail -n 10 "$tmp/make.out" | tr '\n' '|')"
    summary
    exit
fi
files="$p/bin/springsim $p/share/man/man1/springsim.1
    $p/share/bash-completion/completions/springsim $p/share/zsh/site-functions/_springsim
    $p/share/fish/vendor_completions.d/springsim.fish $p/lib/springsim/springsim-fig.so"
for f in $(cd presets && ls *.ini); do
    files="$files $p/share/springsim/presets/$f"
done
for f in $(cd lessons && ls *.lesson); do
    files="$files $p/share/springsim/lessons/$f"
done
for f in $files; do
    [ -s "$stage$f" ] && pass || fail "make install put nothing at $f"
done
[ -x "$stage$p/bin/springsim" ] && pass || fail "the installed springsim is not executable"
for f in springsim.bash _springsim springsim.fish; do
    case $f in
    *.bash) to=$p/share/bash-completion/completions/springsim ;;
    _*) to=$p/share/zsh/site-functions/_springsim ;;
    *) to=$p/share/fish/vendor_completions.d/springsim.fish ;;
    esac
    cmp -s "$BUILD/completions/$f" "$stage$to" && pass || fail "$to is not $BUILD/completions/$f"
done

mk uninstall || fail "make uninstall: $(tail -n 10 "$tmp/make.out" | tr '\n' '|')"
left=$(find "$stage" ! -type d)
[ -z "$left" ] && pass || fail "make uninstall left: $(echo $left)"


# Paths with blanks and non-ASCII bytes (issue 23): install puts everything under the one
# DESTDIR named, nothing in the source tree; uninstall removes nothing but its own files,
# not a file whose name is DESTDIR's first word, nor a preset someone put beside ours.
before=$(ls -A)
mkdir -p "$tmp/h"
echo keep >"$tmp/h/victimfile"
stage="$tmp/h/victimfile stage/dest dir/ünï cödé"
if mk install; then
    [ -s "$stage$p/bin/springsim" ] && [ -s "$stage$p/share/springsim/presets/resonance.ini" ] &&
        pass || fail "make install with DESTDIR '$stage' put nothing at $p/bin/springsim"
else
    fail "make install DESTDIR='$stage': $(tail -n 10 "$tmp/make.out" | tr '\n' '|')"
fi
[ "$(ls -A)" = "$before" ] && pass || fail "make install left in the source tree: $(ls -A | tr '\n' ' ')"
echo mine >"$stage$p/share/springsim/presets/mine.ini"
mk uninstall || fail "make uninstall DESTDIR='$stage': $(tail -n 10 "$tmp/make.out" | tr '\n' '|')"
[ "$(cat "$tmp/h/victimfile" 2>/dev/null)" = keep ] && pass ||
    fail "make uninstall DESTDIR='$stage' removed $tmp/h/victimfile"
left=$(find "$stage" ! -type d)
[ "$left" = "$stage$p/share/springsim/presets/mine.ini" ] && pass ||
    fail "make uninstall with a preset of someone else's: left '$left'"
[ "$(ls -A)" = "$before" ] && pass || fail "make uninstall left in the source tree: $(ls -A | tr '\n' ' ')"

summary
