#!/bin/sh
# tests/figure.sh: --figure end to end (issue 18): the SVG parses and holds one curve per
# mass in each panel in the mass's colour (the motor's dashed), each curve lies on the
# CSV's rows of the same run, the PNG has the size the page gives, the PDF is a PDF; the
# modes' shapes and the sweep's curves; an unknown extension, an unwritable path and a
# failed run; the file written whole or not at all.
# Prints one line per failing case, then "figure: N passed, M failed".

NAME=figure
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM
plain_env
fc="python3 $(cd "$(dirname "$0")" && pwd)/lib/figcheck.py"

# The terminal's colours (tui/term.c's 256-colour palette), as the figures use them.
M1=0,95,255
M2=0,135,0
M3=215,95,0
MOTOR=215,0,175

# expect WHAT GOT WANT
expect() {
    if [ "$2" = "$3" ]; then pass; else fail "$1: got '$2', expected '$3'"; fi
}

# on_rows WHAT "points rows residual c offset": every point on a row's time and the fit
# within 0.01 pt (cairo keeps coordinates to 1/256 pt), up the page up the axis, and most rows a point (cairo merges
# only runs of segments in one direction).
on_rows() {
    if echo "$2" | awk '{ exit !($1 >= 0.8 * $2 && $1 <= $2 && $3 < 0.01 && $4 < 0 && $5 < 0.01) }'
    then pass; else fail "$1: points rows residual slope offset = $2"; fi
}

# usage_error WHAT NEEDLE: exit 2, one line on stderr holding NEEDLE, no output.
usage_error() {
    if [ "$rc" -eq 2 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -qF -- "$2" "$err" && ! [ -s "$out" ]
    then pass; else fail "$1: exit $rc, stderr: $(cat "$err")"; fi
}

# 1. --headless: three panels, a curve per mass in each, the motor dashed in the first.
run --headless -n 3 --figure "$tmp/h.svg" -o "$tmp/h.csv"
expect "$cmd: exit status" "$rc" 0
expect "$cmd: stderr" "$(cat "$err")" ""
for c in $M1 $M2 $M3; do
    expect "$cmd: curves in $c" "$($fc curves "$tmp/h.svg" $c)" 3
done
expect "$cmd: motor curves" "$($fc curves "$tmp/h.svg" $MOTOR)" 1
expect "$cmd: motor dashed" "$($fc dashed "$tmp/h.svg" $MOTOR)" 1
expect "$cmd: mass curves dashed" "$($fc dashed "$tmp/h.svg" $M1)" 0
# Each curve against its column of the CSV of the same run.
on_rows "$cmd: x1 against the CSV" "$($fc fit "$tmp/h.svg" $M1 0 "$tmp/h.csv" t x1)"
on_rows "$cmd: x3 against the CSV" "$($fc fit "$tmp/h.svg" $M3 0 "$tmp/h.csv" t x3)"
on_rows "$cmd: v2 against the CSV" "$($fc fit "$tmp/h.svg" $M2 1 "$tmp/h.csv" t v2)"
on_rows "$cmd: a1 against the CSV" "$($fc fit "$tmp/h.svg" $M1 2 "$tmp/h.csv" t a1)"
on_rows "$cmd: motor against the CSV" "$($fc fit "$tmp/h.svg" $MOTOR 0 "$tmp/h.csv" t motor)"
# The fit can fail: mass 1's acceleration curve is not mass 2's.
r=$($fc fit "$tmp/h.svg" $M1 2 "$tmp/h.csv" t a2)
if echo "$r" | awk '{ exit !($3 > 1) }'; then pass; else fail "a1's curve fits a2: $r"; fi

# 2. PNG: 720 x 860 points at 2 pixels a point; PDF: a PDF, whole.
run --headless --figure "$tmp/h.png" -o /dev/null
expect "$cmd: exit status" "$rc" 0
expect "$cmd: PNG size" "$($fc png "$tmp/h.png" 2>&1)" "1440 1720"
run --headless --duration 2 --figure "$tmp/H.PDF" -o /dev/null
expect "$cmd: exit status" "$rc" 0
expect "$cmd: PDF header" "$(head -c 5 "$tmp/H.PDF")" "%PDF-"
expect "$cmd: PDF end" "$(tail -c 7 "$tmp/H.PDF" | tr -d '\n')" "%%EOF"

# A long run is cut into buckets: the curve keeps at most 2 points a bucket and still
# lies on the CSV's rows.
run --headless -n 1 --duration 300 --figure "$tmp/long.svg" -o "$tmp/long.csv"
r=$($fc fit "$tmp/long.svg" $M1 0 "$tmp/long.csv" t x1)
if echo "$r" | awk '{ exit !($1 <= 4000 && $1 >= 1000 && $3 < 0.01 && $5 < 0.01) }'; then pass
else fail "$cmd: a long run's curve: points rows residual slope offset = $r"; fi

# 3. --modes: one curve per mode, the shapes of the CSV.
run --modes -n 4 --figure "$tmp/m.svg" -o "$tmp/m.csv"
expect "$cmd: exit status" "$rc" 0
k=0
for c in $M1 $M2 $M3 215,0,0; do
    expect "$cmd: curves in $c" "$($fc curves "$tmp/m.svg" $c)" 1
    r=$($fc modefit "$tmp/m.svg" $c 0 "$tmp/m.csv" $k)
    if echo "$r" | awk '{ exit !($3 < 0.01 && $4 < 0 && $5 < 0.01) }'; then pass
    else fail "$cmd: mode $((k + 1))'s shape: $r"; fi
    k=$((k + 1))
done

# 4. --sweep: amplitude and phase, a curve per mass in each.
run --sweep 0.1:3:200 -n 2 --figure "$tmp/s.svg" -o "$tmp/s.csv"
expect "$cmd: exit status" "$rc" 0
expect "$cmd: curves of mass 1" "$($fc curves "$tmp/s.svg" $M1)" 2
expect "$cmd: curves of mass 2" "$($fc curves "$tmp/s.svg" $M2)" 2
run --sweep 0.1:3:200 -n 2 --figure "$tmp/s.png" -o /dev/null
expect "$cmd: PNG size" "$($fc png "$tmp/s.png" 2>&1)" "1440 1400"

# 5. Errors. An extension that names no format: one line, exit 2, nothing written.
run --headless --figure "$tmp/f.jpg"
usage_error "$cmd" "--figure: '$tmp/f.jpg' has no extension that names a figure format (expected a file name ending in .png, .svg or .pdf)"
expect "$cmd: no file" "$(ls "$tmp" | grep -c 'f\.jpg')" 0
run --headless --figure "$tmp/png"
usage_error "$cmd" "expected a file name ending in .png, .svg or .pdf"
# Only the modes that write CSV draw one.
run --figure "$tmp/f.svg"
usage_error "$cmd" "--figure: applies to the output of --headless, --modes or --sweep, not to the interactive program"
run --headless --summary --figure "$tmp/f.svg"
usage_error "$cmd" "--figure: a --summary run has one row of figures"
# A path that cannot be written: the path and the reason, exit 1, before the run.
run --headless --figure "$tmp/none/f.svg" -o "$tmp/csv-not-written.csv"
expect "$cmd: exit status" "$rc" 1
expect "$cmd: stderr" "$(cat "$err")" "springsim: $tmp/none/f.svg: No such file or directory"
expect "$cmd: no CSV" "$(ls "$tmp" | grep -c csv-not-written)" 0
mkdir "$tmp/dir.svg"
run --modes --figure "$tmp/dir.svg"
expect "$cmd: exit status" "$rc" 1
expect "$cmd: stderr" "$(cat "$err")" "springsim: $tmp/dir.svg: Is a directory"

# The same file for -o and --figure (issue 33 item 10): refused before anything is written,
# whether it is named the same way, through another path, or through a hard link; an
# existing file stays as it was. --record onto either is refused too.
mkdir "$tmp/same"
echo kept >"$tmp/same/old.svg"
ln "$tmp/same/old.svg" "$tmp/same/link.svg"
for pair in "$tmp/same/a.svg $tmp/same/a.svg" "$tmp/same/b.png $tmp/same/../same/b.png" \
    "$tmp/same/old.svg $tmp/same/link.svg"; do
    set -- $pair
    run --headless --duration 1 -o "$1" --figure "$2"
    usage_error "$cmd" "--figure: '$2' is also -o's file (expected a different file for each output)"
done
refused "is also -o's file" --modes -o "$tmp/same/m.pdf" --figure "$tmp/same/m.pdf"
refused "--output: applies to" --plain --record "$tmp/same/r.svg" -o "$tmp/same/r.svg"
refused "--figure: applies to" --plain --record "$tmp/same/r.svg" --figure "$tmp/same/r.svg"
expect "the same file: nothing written" "$(ls "$tmp/same" | tr '\n' ' ')" "link.svg old.svg "
expect "the same file: the old file kept" "$(cat "$tmp/same/old.svg")" "kept"
# Two different files in one directory are two outputs.
run --headless --duration 1 -o "$tmp/same/c.csv" --figure "$tmp/same/c.svg"
expect "$cmd: exit status" "$rc" 0

# 6. Written whole or not at all: a run that blows up leaves the old figure as it was and
# no temporary file beside it.
mkdir "$tmp/w"
echo old >"$tmp/w/f.svg"
run --headless --no-collisions --spring 1e6 --dt 0.05 --duration 5 --figure "$tmp/w/f.svg" \
    -o /dev/null
expect "$cmd: exit status" "$rc" 1
expect "$cmd: the old figure" "$(cat "$tmp/w/f.svg")" "old"
expect "$cmd: files beside it" "$(ls "$tmp/w")" "f.svg"
run --headless --duration 1 --figure "$tmp/w/f.svg" -o /dev/null
expect "$cmd: replaced" "$(head -c 5 "$tmp/w/f.svg")" "<?xml"
expect "$cmd: files beside it" "$(ls "$tmp/w")" "f.svg"

summary
