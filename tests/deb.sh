#!/bin/sh
# tests/deb.sh: `make deb` builds the Debian package (lintian finding no error), which is
# unpacked into a throwaway root with dpkg -x; the program there reports the package's
# version, finds the packaged presets and makes the same headless run as the binary under
# test. Skipped under make sanitize (DEB_CHECK=no): the package is built with Debian's
# flags, not the sanitizers, and make check has tested it. Prints "deb: N passed, M failed".
NAME=deb
. tests/lib/check.sh
BUILD=${BUILD:-build}

if [ "${DEB_CHECK:-yes}" = no ]; then
    echo "deb: skipped (DEB_CHECK=no: make sanitize; make check builds and tests the package)"
    summary
    exit
fi
plain_env

# Every package mk/deps.sh's build group asks for (but the compiler, which build-essential
# brings) is in debian/control's Build-Depends.
for p in $(sed -n '/^    build)/,/;;/p' mk/deps.sh | awk '/want_(pc|bin)/ { print $3 }'); do
    [ "$p" = gcc ] && continue
    grep -qE "^ *(Build-Depends: *)?$p[ ,(]" debian/control && pass ||
        fail "mk/deps.sh build needs $p, debian/control's Build-Depends lacks it"
done

# The package, built as a user would (make's own settings kept out of it).
version=$(sed -n 's/^VERSION = //p' Makefile)
start=$(date +%s)
if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s deb BUILD="$BUILD" >"$tmp/make.out" 2>&1; then
    fail "make deb: $(tail -n 15 "$tmp/make.out" | tr '\n' '|')"
    summary
    exit
fi
echo "deb: make deb took $(($(date +%s) - start)) s"
pass
grep -E '^(E|W): ' "$tmp/make.out" | sed 's/^/deb: lintian: /'
grep -q '^E: ' "$tmp/make.out" && fail "lintian reported errors" || pass
deb=$(ls "$BUILD"/springsim_"$version"_*.deb 2>/dev/null | head -n 1)
if [ -z "$deb" ]; then
    fail "make deb left no $BUILD/springsim_${version}_*.deb"
    summary
    exit
fi
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] && pass ||
    fail "package version $(dpkg-deb -f "$deb" Version), Makefile's $version"
dpkg-deb -f "$deb" Depends | grep -q 'libncursesw6' && pass ||
    fail "Depends lacks the libraries the binary links: $(dpkg-deb -f "$deb" Depends)"
dpkg-deb -f "$deb" Depends | grep -q 'libcairo2' && pass ||
    fail "Depends lacks the figure library's cairo: $(dpkg-deb -f "$deb" Depends)"

# Unpacked into a throwaway root: what is there.
root=$tmp/root
dpkg -x "$deb" "$root" || fail "dpkg -x $deb"
for f in usr/bin/springsim usr/share/man/man1/springsim.1.gz usr/share/doc/springsim/copyright \
    usr/share/bash-completion/completions/springsim usr/share/zsh/vendor-completions/_springsim \
    usr/share/fish/vendor_completions.d/springsim.fish \
    "usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)/springsim/springsim-fig.so"; do
    [ -s "$root/$f" ] && pass || fail "the package has no /$f"
done
want=$(cd presets && ls *.ini)
got=$(cd "$root/usr/share/springsim/presets" 2>/dev/null && ls *.ini)
[ -n "$want" ] && [ "$got" = "$want" ] && pass ||
    fail "packaged presets '$(echo $got)', expected those in presets/: '$(echo $want)'"
want=$(cd lessons && ls *.lesson)
got=$(cd "$root/usr/share/springsim/lessons" 2>/dev/null && ls *.lesson)
[ -n "$want" ] && [ "$got" = "$want" ] && pass ||
    fail "packaged lessons '$(echo $got)', expected those in lessons/: '$(echo $want)'"
gzip -dc "$root/usr/share/man/man1/springsim.1.gz" | cmp -s - man/springsim.1 && pass ||
    fail "the packaged man page is not man/springsim.1"

# The program from there: its version, its compiled-in preset directory, and a run on a
# packaged preset (found through SPRINGSIM_PRESETS, which comes before any installed
# directory) that matches the binary under test to 1e-9 (both built from this tree; the
# package's compiler flags differ).
bin=$root/usr/bin/springsim
[ "$("$bin" --version 2>&1)" = "springsim $version" ] && pass ||
    fail "packaged springsim --version: $("$bin" --version 2>&1 | head -c 200)"
"$bin" --help | tr '\n' ' ' | grep -q '/usr/share/springsim/presets' && pass ||
    fail "packaged springsim --help does not name /usr/share/springsim/presets"
"$bin" --help | tr '\n' ' ' | grep -q '/usr/share/springsim/lessons' && pass ||
    fail "packaged springsim --help does not name /usr/share/springsim/lessons"
run="--headless -p resonance --duration 5 --sample 0.5 --energy"
(cd "$tmp" && SPRINGSIM_PRESETS=$root/usr/share/springsim/presets "$bin" $run) \
    >"$tmp/deb.csv" 2>"$tmp/deb.err"
rc=$?
"$SPRINGSIM" $run >"$tmp/here.csv" 2>/dev/null
if [ $rc -ne 0 ] || [ -s "$tmp/deb.err" ]; then
    fail "packaged springsim $run: exit $rc, $(head -c 300 "$tmp/deb.err")"
elif [ "$(wc -l <"$tmp/deb.csv")" -ne 12 ]; then
    fail "packaged springsim $run: $(wc -l <"$tmp/deb.csv") lines, expected a header and 11 rows"
elif awk -F, 'NR == FNR { a[FNR] = $0; next }
    FNR == 1 { if ($0 != a[1]) bad = 1; next }
    { n = split(a[FNR], x, ",")
      if (n != NF) bad = 1
      for (i = 1; i <= NF; i++) {
          d = $i - x[i]; if (d < 0) d = -d
          s = x[i] < 0 ? -x[i] : x[i]
          if (d > 1e-9 * (s > 1 ? s : 1)) bad = 1 } }
    END { exit !bad }' "$tmp/here.csv" "$tmp/deb.csv"; then
    fail "packaged springsim $run differs from $SPRINGSIM's: $(sed -n 2p "$tmp/deb.csv")"
else
    pass
fi

# Its figure library, loaded as the program does (beside it here: the package is not
# installed), draws a figure.
cp "$root/usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)/springsim/springsim-fig.so" \
    "$root/usr/bin/" 2>/dev/null
if "$bin" --headless --duration 1 --figure "$tmp/deb.png" >/dev/null 2>"$tmp/fig.err" &&
    [ "$(head -c 8 "$tmp/deb.png" | od -An -c | tr -d ' ')" = '211PNG\r\n032\n' ]; then
    pass
else
    fail "packaged springsim --figure: $(head -c 300 "$tmp/fig.err")"
fi
summary
