#!/bin/sh
# tests/docs.sh: the README's set-up names every Debian package mk/deps.sh wants for the
# build and the tests (issue 22, item 14: it had left out libgsl-dev, which the binary
# links, and the packages the pixel and completion tests use). Run from the repository
# root as `sh tests/docs.sh`. Ends with "docs: N passed, M failed".
NAME=docs
. "$(dirname "$0")/lib/check.sh"

# the packages of one group of mk/deps.sh: the last word of its want_* lines and of
# its need="$need PACKAGE" lines
group() {
    sed -n "/^    $1)/,/;;/p" mk/deps.sh |
        sed -n 's/^ *want_[a-z]* [^ ]* \([^ ]*\)$/\1/p; s/.*need="\$need \([^"]*\)".*/\1/p'
}
# the README's set-up section, from its heading to "Other targets:"
setup=$(sed -n '/^## Set-up/,/^Other targets:/p' README.md)

for g in build test; do
    pkgs=$(group $g)
    if [ "$(echo "$pkgs" | grep -c .)" -lt 5 ]; then
        fail "mk/deps.sh: group $g should name at least 5 packages; found: $(echo $pkgs)"
        continue
    fi
    missing=
    for p in $pkgs; do
        printf '%s\n' "$setup" | grep -qF "\`$p\`" || missing="$missing $p"
    done
    if [ -z "$missing" ]; then pass; else
        fail "README set-up: the $g packages of mk/deps.sh not named (in backquotes):$missing"
    fi
done

summary
