#!/bin/sh
# tests/design.sh: docs/design.md stays true of the tree. Every file it names exists (a
# path such as src/core/sim.c or tests/test_*.c, or a file name such as `keys.c`
# somewhere under src/, tests/ or mk/); it names nothing outside the repository; and the
# rules it states hold: no two files call each other (read from the objects' symbols:
# a file using a function another file defines), the .c files' #includes make no circle,
# and no two source files' names differ only by a trailing "s". Run from the repository
# root after the build; $BUILD the build directory. Ends with "design: N passed, M failed".
NAME=design
. "$(dirname "$0")/lib/check.sh"
BUILD=${BUILD:-build}
DOC=${DESIGN_DOC:-docs/design.md}

# doc_files DOC: the files DOC names that are not in the tree, one a line. A path is a
# token that starts with one of the tree's top directories (a pattern such as
# tests/test_*.c must match a file); a file name in backquotes (`keys.c`, `run_*.c`; a
# placeholder such as `view_NAME.c` has capitals and is not one) must
# be somewhere under src/, tests/ or mk/.
doc_files() {
    grep -o '\(src\|tests\|mk\|man\|docs\|presets\|lessons\|debian\)/[A-Za-z0-9_.*/-]*[A-Za-z0-9_*]' "$1" |
        sort -u | while read -r p; do
            # shellcheck disable=SC2086
            set -- $p
            [ -e "$1" ] || echo "$p"
        done
    grep -o '`[a-z][a-z0-9_*]*\.[ch]`' "$1" | tr -d '`' | sort -u | while read -r n; do
        [ -n "$(find src tests mk -name "$n" | head -n 1)" ] || echo "$n"
    done
}

# 1. Every file the page names is in the tree (and it names some of each kind).
doc_files "$DOC" >"$tmp/missing"
if [ -s "$tmp/missing" ]; then
    fail "docs/design.md names files that are not in the tree: $(tr '\n' ' ' <"$tmp/missing")"
elif ! grep -q 'src/core/' "$DOC" || ! grep -q '`[a-z_]*\.c`' "$DOC"; then
    fail "docs/design.md names no path or no file (the check itself is broken)"
else pass; fi

# 2. The check sees a file that is gone.
printf 'the map names `gone_file.c`, src/core/gone.c and src/core/sim.c\n' >"$tmp/bad.md"
if [ "$(doc_files "$tmp/bad.md" | tr '\n' ' ')" = "src/core/gone.c gone_file.c " ]; then pass; else
    fail "doc_files did not list exactly the two missing files: $(doc_files "$tmp/bad.md")"
fi

# 3. Nothing outside the repository: no parent directory, no document the tree lacks.
if grep -n '\.\./\|SPEC\|STYLE\.md' "$DOC" >"$tmp/outside"; then
    fail "docs/design.md points outside the repository: $(head -n 1 "$tmp/outside")"
else pass; fi

# 4. No two files call each other. For each object of the program, the functions it
# defines (T) and the ones it uses (U); an edge A -> B when A uses a function B defines.
objs=$(find "$BUILD" -maxdepth 2 -name '*.o' ! -path "*/tests/*" ! -path "*/mk/*" ! -path "*/fuzz/*")
if [ -z "$objs" ]; then
    fail "no objects under $BUILD: build first"
else
    for o in $objs; do
        n=${o#"$BUILD"/}
        nm "$o" | awk -v f="${n%.o}" '$2 == "T" { print "D", $3, f } $1 == "U" { print "U", $2, f }'
    done | awk '$1 == "D" { def[$2] = $3; next }
                { use[++n] = $2; by[n] = $3 }
                END { for (i = 1; i <= n; i++)
                          if ((use[i] in def) && def[use[i]] != by[i]) print by[i], def[use[i]] }' |
        sort -u >"$tmp/calls"
    awk '{ e[$1 " " $2] = 1 } END { for (k in e) { split(k, a, " ");
         if ((a[2] " " a[1]) in e && a[1] < a[2]) print a[1] " <-> " a[2] } }' "$tmp/calls" >"$tmp/pairs"
    if [ ! -s "$tmp/calls" ]; then
        fail "no calls between files found in $BUILD's objects (the check itself is broken)"
    elif [ -s "$tmp/pairs" ]; then
        fail "files that call each other: $(tr '\n' ' ' <"$tmp/pairs")"
    else pass; fi
    # Longer circles of calls too (tsort reports a loop on standard error).
    if tsort "$tmp/calls" >/dev/null 2>"$tmp/loop"; then pass; else
        fail "a circle of calls between files: $(grep -v 'input contains' "$tmp/loop" | tr '\n' ' ')"
    fi
fi

# 5. The .c files' includes of the project's own headers make no circle. One awk over
# every file: a quoted include is looked for beside the file, then under src/ (as the
# compiler's -Isrc does), ".." folded; an edge from the .c file's module to the header's.
find src -name '*.h' >"$tmp/headers"
find src -name '*.c' -exec grep -H '^#include "' {} + |
    awk -F: 'NR == FNR { have[$0] = 1; next }
        function fold(p,    n, a, out, i, k) {
            n = split(p, a, "/"); k = 0
            for (i = 1; i <= n; i++)
                if (a[i] == "..") k--; else if (a[i] != ".") out[++k] = a[i]
            p = out[1]; for (i = 2; i <= k; i++) p = p "/" out[i]
            return p
        }
        { c = $1; h = $2; sub(/^#include "/, "", h); sub(/".*/, "", h)
          d = c; sub(/\/[^\/]*$/, "", d)
          t = fold(d "/" h); if (!(t in have)) { t = fold("src/" h); if (!(t in have)) next }
          from = c; sub(/\.c$/, "", from); to = t; sub(/\.h$/, "", to)
          if (from != to) print from, to }' "$tmp/headers" - | sort -u >"$tmp/includes"
if [ ! -s "$tmp/includes" ]; then
    fail "no includes between files found (the check itself is broken)"
elif tsort "$tmp/includes" >/dev/null 2>"$tmp/loop"; then pass; else
    fail "a circle of includes: $(grep -v 'input contains' "$tmp/loop" | tr '\n' ' ')"
fi

# 6. No twin names: NAME.c beside NAMEs.c anywhere under src/.
find src -name '*.[ch]' | sed 's,.*/,,; s/\.[ch]$//' | sort -u >"$tmp/modules"
twins=$(while read -r n; do grep -qx "${n}s" "$tmp/modules" && echo "$n/${n}s"; done <"$tmp/modules")
if [ -s "$tmp/modules" ] && [ -z "$twins" ]; then pass; else
    fail "source files whose names differ only by a trailing s: $twins"
fi

# A circle is seen (tsort is what checks 4 and 5 rest on).
printf 'a b\nb c\nc a\n' >"$tmp/circle"
if tsort "$tmp/circle" >/dev/null 2>&1; then fail "tsort did not see a circle"; else pass; fi

summary
