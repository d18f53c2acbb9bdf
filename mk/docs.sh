#!/bin/sh
# mk/docs.sh [--check] BINARY DOCGEN: writes the generated sections of README.md and
# man/springsim.1 from the program's own tables, so that no key, option, default or
# preset is written by hand in two places:
#
#   keys     the key table (`BINARY --keys`, src/tui/input.c): README and man KEYS
#   options  the option table (DOCGEN, a build tool linked with src/core/config.c):
#            README's table, each man page entry's first lines, and the man page's
#            list of each preset section's keys
#   presets  the built-in presets (`BINARY --list-presets` over presets/*.ini, and
#            `--modes` for their natural frequencies): README and man
#   deps     the Debian packages of mk/deps.sh's build and test groups: README set-up
#
# A generated section sits between marker lines, in Markdown
#     <!-- BEGIN generated NAME: make docs -->  ...  <!-- END generated NAME -->
# and in roff
#     .\" BEGIN generated NAME: make docs       ...  .\" END generated NAME
# and everything outside the markers is left as it is. `make docs` rewrites them in
# place; with --check nothing is written, and each section that differs from what would
# be generated is named (exit 1): tests/docs.sh runs it in `make check`.
check=no
if [ "$1" = --check ]; then
    check=yes
    shift
fi
bin=${1:-./springsim}
docgen=${2:-build/mk/docgen}
readme=${README:-README.md}
man=${MANPAGE:-man/springsim.1}
for f in "$bin" "$docgen"; do
    [ -x "$f" ] || { echo "mk/docs.sh: $f: not an executable (run make first)" >&2; exit 2; }
done

tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
stale=0

# The program as a fresh build sees it: the built-in presets only, no user's.
run() {
    env -u SPRINGSIM_PRESETS -u SPRINGSIM_LESSONS XDG_CONFIG_HOME="$tmp/none" \
        HOME="$tmp/none" LANG=C.UTF-8 LC_ALL=C.UTF-8 "$bin" "$@"
}

# ---- the contents of each section ----

# Keys: "KEY<TAB>WHAT" lines. Markdown: each key in backquotes, | escaped in a table.
run --keys >"$tmp/keys" || { echo "mk/docs.sh: $bin --keys failed" >&2; exit 1; }
{
    echo "| key | what it does |"
    echo "| --- | --- |"
    awk -F '\t' '{
        n = split($1, k, ", "); s = ""
        for (i = 1; i <= n; i++) { gsub(/\|/, "\\|", k[i]); s = s (i > 1 ? ", " : "") "`" k[i] "`" }
        h = $2; gsub(/\|/, "\\|", h)
        print "| " s " | " h " |"
    }' "$tmp/keys"
} >"$tmp/md-keys"
# roff: a .TP entry each, as the man page's KEYS list has always had them.
sed 's/\\/\\e/g; s/-/\\-/g; s/↑/\\(ua/g; s/↓/\\(da/g; s/←/\\(<-/g; s/→/\\(->/g' "$tmp/keys" |
    awk -F '\t' '{ print ".TP"; print ".B " $1; print $2 }' >"$tmp/man-keys"

# Options: the build tool writes both spellings from the option table.
"$docgen" md-options >"$tmp/md-options" || exit 1

# Presets: the names and descriptions --list-presets gives, limited to presets/*.ini
# (an installed or user preset is not the project's), and each one's natural
# frequencies from --modes.
run --list-presets >"$tmp/list" || { echo "mk/docs.sh: $bin --list-presets failed" >&2; exit 1; }
: >"$tmp/presets"
while read -r name desc; do
    [ -f "presets/$name.ini" ] || continue
    freqs=$(run -p "$name" --modes | awk -F , 'NR > 1 { printf "%s%.3f", (NR > 2 ? ", " : ""), $2 }')
    printf '%s\t%s\t%s\n' "$name" "$desc" "$freqs" >>"$tmp/presets"
done <"$tmp/list"
[ -s "$tmp/presets" ] || { echo "mk/docs.sh: no built-in preset found in presets/" >&2; exit 1; }
{
    echo "| \`-p\` name | what it shows | natural frequencies (Hz) |"
    echo "| --- | --- | --- |"
    awk -F '\t' '{ d = $2; gsub(/\|/, "\\|", d); print "| `" $1 "` | " d " | " $3 " |" }' "$tmp/presets"
} >"$tmp/md-presets"
sed 's/\\/\\e/g; s/-/\\-/g' "$tmp/presets" |
    awk -F '\t' '{ print ".TP"; print ".B " $1; print $2 "."; print "Natural frequencies: " $3 " Hz." }' \
        >"$tmp/man-presets"

# Deps: the last word of mk/deps.sh's want_* and need="$need ..." lines of a group.
group() {
    sed -n "/^    $1)/,/;;/p" mk/deps.sh |
        sed -n 's/^ *want_[a-z]* [^ ]* \([^ ]*\)$/\1/p; s/.*need="\$need \([^"]*\)".*/\1/p' |
        awk '!seen[$0]++' # a package named for several of its programs, once
}
{
    echo '    apt-get install '"$(group build | tr '\n' ' ' | sed 's/ $//')"
    echo
    echo 'and for `make check`:'
    echo
    echo '    apt-get install '"$(group test | tr '\n' ' ' | sed 's/ $//')"
} >"$tmp/md-deps"

# ---- writing them between the markers ----

# put FILE NAME CONTENT BEGIN END: FILE with the lines between the line that starts with
# BEGIN and the line END replaced by CONTENT, to $tmp/out. The pair must be there once.
put() {
    # (through the environment: awk -v would take the backslash of .\" as an escape)
    CONTENT=$3 B=$4 E=$5 awk '
        BEGIN { content = ENVIRON["CONTENT"]; b = ENVIRON["B"]; e = ENVIRON["E"] }
        index($0, b) == 1 { print; while ((getline l < content) > 0) print l; skip = 1; begins++; next }
        skip && $0 == e { skip = 0; ends++ }
        skip { next }
        { print }
        END { if (begins != 1 || ends != 1 || skip) exit 3 }
    ' "$1" >"$tmp/out" || {
        echo "mk/docs.sh: $1: the markers of the generated section '$2' are missing, doubled or unclosed" >&2
        exit 2
    }
}

# update FILE KIND NAME CONTENT: one section of FILE (kind md or roff), in place or checked.
update() {
    case $2 in
    md) put "$1" "$3" "$4" "<!-- BEGIN generated $3:" "<!-- END generated $3 -->" ;;
    roff) put "$1" "$3" "$4" ".\\\" BEGIN generated $3:" ".\\\" END generated $3" ;;
    esac
    if ! cmp -s "$1" "$tmp/out"; then
        if [ "$check" = yes ]; then
            echo "mk/docs.sh: $1: the generated section '$3' is stale (run make docs)" >&2
            stale=1
        else
            cat "$tmp/out" >"$1" && echo "mk/docs.sh: $1: section '$3' written"
        fi
    fi
}

update "$readme" md keys "$tmp/md-keys"
update "$readme" md options "$tmp/md-options"
update "$readme" md presets "$tmp/md-presets"
update "$readme" md deps "$tmp/md-deps"
update "$man" roff keys "$tmp/man-keys"
update "$man" roff presets "$tmp/man-presets"
"$docgen" man-preset-keys >"$tmp/man-preset-keys" || exit 1
update "$man" roff preset-keys "$tmp/man-preset-keys"

# The man page's OPTIONS: each option's entry begins with a generated head (its
# spelling, what it does, its range and default), in the table's order; what follows
# the head is the man page's own.
"$docgen" names >"$tmp/names" || exit 1
for o in $(cat "$tmp/names"); do
    "$docgen" man-option "$o" >"$tmp/man-option" || exit 1
    update "$man" roff "option-$o" "$tmp/man-option"
done
want=$(tr '\n' ' ' <"$tmp/names")
have=$(sed -n 's/^\.\\" BEGIN generated option-\([^:]*\):.*/\1/p' "$man" | tr '\n' ' ')
if [ "$want" != "$have" ]; then
    echo "mk/docs.sh: $man: the options' entries ($have) are not the option table's, in its order ($want)" >&2
    stale=1
fi
exit $stale
