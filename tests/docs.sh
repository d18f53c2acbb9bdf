#!/bin/sh
# tests/docs.sh: the documents agree with the program (issue 21). The README and the man
# page have sections generated from the program's tables (mk/docs.sh); this fails when
# one is stale, and, reading each document as a user would, when the README, the man
# page, --help, --keys, the completions and the program's own defaults (the command line
# --meta writes for a run given no option) disagree on an option, a key, a default or a
# preset. Also (issue 22, item 14) that the README names every Debian package mk/deps.sh
# wants. Run from the repository root; $SPRINGSIM the binary, $DOCGEN mk/docgen.c built,
# $COMPLETIONS the completions' directory. Ends with "docs: N passed, M failed".
NAME=docs
. "$(dirname "$0")/lib/check.sh"
plain_env
DOCGEN=${DOCGEN:-build/mk/docgen}
COMPLETIONS=${COMPLETIONS:-build/completions}
README=${README:-README.md}
MANPAGE=${MANPAGE:-man/springsim.1}

# 1. Every generated section is what the tables give now.
if sh mk/docs.sh --check "$SPRINGSIM" "$DOCGEN" 2>"$tmp/stale"; then pass; else
    fail "generated sections stale or broken: $(cat "$tmp/stale")"
fi

# The man page as text: comments and the font macros' names dropped (.TP, .SH and the
# like kept, to tell entries apart), font changes and escapes undone.
sed -e '/^\.\\"/d' -e 's/^\.\(B\|BR\|BI\|I\|IR\|RB\) *//' -e 's/\\f[BIRP]//g' -e 's/\\-/-/g' \
    -e 's/\\(ua/↑/g; s/\\(da/↓/g; s/\\(<-/←/g; s/\\(->/→/g' -e 's/\\e/\\/g' -e 's/\\&//g' \
    -e 's/"//g' "$MANPAGE" >"$tmp/man.src"
# man_entry TAG: the text of the .TP entry whose tag line is TAG, joined on one line.
man_entry() {
    awk -v tag="$1" '
        /^\.TP/ { if (found) exit; want = 1; next }
        want { want = 0; if ($0 == tag) { found = 1; next } }
        found && /^\.(SH|SS|PP)/ { exit }
        found && !/^\./ { printf "%s ", $0 }
    ' "$tmp/man.src"
}
# 2. The options: each one --help lists, with its argument and its default.
run --help
cp "$out" "$tmp/help"
# "  -n, --masses N    number of masses (...; default 2)" and its continuation lines,
# joined: spelling<TAB>text.
awk '
    /^  (-[a-z], |    )--[a-z]/ {
        if (spell != "") print spell "\t" text
        line = substr($0, 3); sub(/^ +/, "", line)
        n = index(line, "  ")
        if (n) { spell = substr(line, 1, n - 1); text = substr(line, n); sub(/^ +/, "", text) }
        else { spell = line; text = "" }
        next
    }
    spell != "" && /^                               / { t = $0; sub(/^ +/, "", t); text = text (text == "" ? "" : " ") t; next }
    spell != "" { print spell "\t" text; spell = "" }
    END { if (spell != "") print spell "\t" text }
' "$tmp/help" >"$tmp/options"
count=$(grep -c . "$tmp/options")
if [ "$count" -ge 30 ]; then pass; else fail "--help: expected the option table, read $count options"; fi

# The program's own defaults: the command line --meta writes for a run given nothing.
defaults=$("$SPRINGSIM" --modes --meta | sed -n 2p)

readme_opts=$(sed -n '/BEGIN generated options/,/END generated options/p' "$README")
while IFS='	' read -r spell text; do
    long=$(printf '%s\n' "$spell" | sed 's/.*--\([a-z0-9-]*\).*/\1/')
    def=$(printf '%s\n' "$text" | sed -n 's/.*[(;] *default \([^;)]*\)).*/\1/p; s/.*, default \([^;)]*\)).*/\1/p' | head -n 1)
    problems=
    # README: a row with the same spelling and the same text.
    row="| $(printf '%s' "$spell" | sed 's/^\(-[a-z]\), /`\1`, /; s/\(--.*\)/`\1`/; s/|/\\|/g') | $(printf '%s' "$text" | sed 's/|/\\|/g') |"
    printf '%s\n' "$readme_opts" | grep -qxF -- "$row" || problems="$problems README row '$row' missing;"
    # man page: an entry tagged with the spelling, saying the same default.
    entry=$(man_entry "$spell")
    if [ -z "$entry" ]; then
        problems="$problems man page has no entry '$spell';"
    elif [ -n "$def" ] && ! printf '%s\n' "$entry" | grep -qF -- "default $def"; then
        problems="$problems man page's '$spell' does not say 'default $def';"
    fi
    # completions: each shell offers the option.
    grep -qF -- "--$long" "$COMPLETIONS/springsim.bash" || problems="$problems bash completion lacks --$long;"
    grep -qF -- "--$long" "$COMPLETIONS/_springsim" || problems="$problems zsh completion lacks --$long;"
    grep -qF -- "-l $long " "$COMPLETIONS/springsim.fish" || problems="$problems fish completion lacks -l $long;"
    # the program: a setting --meta writes has the default --help states.
    meta=$(printf '%s\n' "$defaults" | tr ' ' '\n' | awk -v o="--$long" 'p { print; exit } $0 == o { p = 1 }')
    if [ -n "$meta" ] && [ -n "$def" ] && [ "$meta" != "$def" ]; then
        problems="$problems --help says default $def, a run uses $meta;"
    fi
    if [ -z "$problems" ]; then pass; else fail "option --$long:$problems"; fi
done <"$tmp/options"

# 3. The keys: each --keys line in the README's table and the man page's KEYS.
run --keys
readme_keys=$(sed -n '/BEGIN generated keys/,/END generated keys/p' "$README")
while IFS='	' read -r keys what; do
    problems=
    row="| $(printf '%s' "$keys" | sed 's/|/\\|/g; s/, /`, `/g; s/^/`/; s/$/`/') | $(printf '%s' "$what" | sed 's/|/\\|/g') |"
    printf '%s\n' "$readme_keys" | grep -qxF -- "$row" || problems="$problems README row '$row' missing;"
    entry=$(sed -n '/^\.SH KEYS/,/^\.SH /p' "$tmp/man.src" | awk -v k="$keys" -v w="$what" '
        prev == k && $0 == w { ok = 1 } { prev = $0 } END { print ok + 0 }')
    [ "$entry" = 1 ] || problems="$problems man KEYS lacks '$keys: $what';"
    if [ -z "$problems" ]; then pass; else fail "key $keys:$problems"; fi
done <"$out"
n=$(grep -c . "$out")
[ "$n" -ge 20 ] && pass || fail "--keys: expected the key table, got $n lines"

# 4. The presets: each built-in one --list-presets gives, in the README and the man page.
run --list-presets
cut -d ' ' -f 1 "$out" >"$tmp/presets"
for p in $(cat "$tmp/presets"); do
    [ -f "presets/$p.ini" ] || continue
    problems=
    grep -qF "| \`$p\` |" "$README" || problems="$problems not in the README;"
    grep -qxF ".B $(printf '%s' "$p" | sed 's/-/\\-/g')" "$MANPAGE" || problems="$problems not in the man page;"
    if [ -z "$problems" ]; then pass; else fail "preset $p:$problems"; fi
done

# 5. The README names every Debian package of mk/deps.sh's build and test groups.
group() {
    sed -n "/^    $1)/,/;;/p" mk/deps.sh |
        sed -n 's/^ *want_[a-z]* [^ ]* \([^ ]*\)$/\1/p; s/.*need="\$need \([^"]*\)".*/\1/p' |
        awk '!seen[$0]++' # a package named for several of its programs, once
}
for g in build test; do
    pkgs=$(group $g)
    if [ "$(echo "$pkgs" | grep -c .)" -lt 5 ]; then
        fail "mk/deps.sh: group $g should name at least 5 packages; found: $(echo $pkgs)"
        continue
    fi
    missing=
    for p in $pkgs; do
        grep -qE "apt-get install( [^ ]+)* $p( |\$)" "$README" || missing="$missing $p"
    done
    if [ -z "$missing" ]; then pass; else
        fail "README: the $g packages of mk/deps.sh not in its apt-get lines:$missing"
    fi
done

# 6. docs/design.md says what every source file owns: each src/ file is named there.
missing=
for f in src/*.c src/*/*.c; do
    b=$(basename "$f" .c)
    grep -qE "\`$b(\.c)?\`|$b\.c" docs/design.md || missing="$missing $f"
done
if [ -z "$missing" ]; then pass; else fail "docs/design.md does not name:$missing"; fi

summary
