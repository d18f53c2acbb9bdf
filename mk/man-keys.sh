#!/bin/sh
# mk/man-keys.sh BINARY MANPAGE: rewrites the man page's KEYS list from the program's
# own key table (`springsim --keys`), spelled in roff. tests/cli.sh checks they agree.
bin=${1:-./springsim}
man=${2:-man/springsim.1}
keys=$(mktemp) || exit 1
trap 'rm -f "$keys" "$keys.new"' EXIT
"$bin" --keys | sed 's/\\/\\e/g; s/-/\\-/g; s/↑/\\(ua/g; s/↓/\\(da/g; s/←/\\(<-/g; s/→/\\(->/g' |
    awk -F '\t' '{ print ".TP"; print ".B " $1; print $2 }' >"$keys"
# Replace the .TP entries between ".SH KEYS" and the first .PP after them.
awk -v list="$keys" '
    /^\.SH KEYS/ { inkeys = 1; print; next }
    inkeys && /^\.TP/ && !done { while ((getline l < list) > 0) print l; done = 1; skip = 1; next }
    skip && /^\.PP/ { skip = 0; inkeys = 0 }
    skip { next }
    { print }
' "$man" >"$keys.new" && cat "$keys.new" >"$man"
