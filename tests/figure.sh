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
MOTOR=0,0,0

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

# 2. Sizes for a report (issue 28): 160 mm wide, 100 mm high for one panel and 50 more
# for each panel under it, the PNG at 300 dpi (160 mm: 1890 pixels; 200 mm: 2362).
run --headless --figure "$tmp/h.png" -o /dev/null
expect "$cmd: exit status" "$rc" 0
expect "$cmd: PNG size" "$($fc png "$tmp/h.png" 2>&1)" "1890 2362"
run --modes --figure "$tmp/m1.pdf" -o /dev/null
expect "$cmd: PDF page (points)" "$(pdfinfo "$tmp/m1.pdf" | sed -n 's/^Page size: *\([0-9.]*\) x \([0-9.]*\) pts.*/\1 \2/p')" \
    "453.543 283.465"
small=$($fc textsize "$tmp/m1.pdf")
awk -v s="$small" 'BEGIN { exit !(s >= 8 && s <= 10) }' && pass ||
    fail "$cmd: the smallest text is $small pt (expected 8 to 10 pt)"
run --headless --duration 2 --figure "$tmp/big.pdf" --figure-size 120x80 -o /dev/null
expect "$cmd: PDF page (points)" "$(pdfinfo "$tmp/big.pdf" | sed -n 's/^Page size: *\([0-9.]*\) x \([0-9.]*\) pts.*/\1 \2/p')" \
    "340.157 226.772"
run --sweep 1:2:10 --figure "$tmp/size.png" --figure-size 100x50 -o /dev/null
expect "$cmd: PNG size" "$($fc png "$tmp/size.png" 2>&1)" "1181 591"
refused "--figure-size: '160' is not WxH (expected WxH in millimetres, each 50 to 1000, e.g. 160x100)" \
    --headless --figure "$tmp/x.svg" --figure-size 160
refused "--figure-size: '10x100' is out of range" --headless --figure "$tmp/x.svg" --figure-size 10x100
refused "--figure-size: 'ax5' is not WxH" --modes --figure "$tmp/x.svg" --figure-size ax5
refused "--figure-title: shapes --figure's file, but no --figure was given" --headless \
    --figure-title T
refused "--figure-title: 'a\\xffb' is not UTF-8 text" --headless --figure "$tmp/u.svg" \
    --figure-title "$(printf 'a\377b')"
[ -e "$tmp/u.svg" ] && fail "a refused --figure-title left its figure" || pass
refused "--figure-size: shapes --figure's file, but no --figure was given" --plain \
    --figure-size 100x100
refused "--figure: applies to the output of --headless, --modes or --sweep" --plain \
    --figure "$tmp/p.svg" --figure-size 100x100

# Titles say what the figure shows; --figure-title replaces them; the preset's name only
# while the settings are the preset's.
title() { $fc text "$1" | head -n 1; }
run --headless --duration 1 --figure "$tmp/t.pdf" -o /dev/null
expect "$cmd: title" "$(title "$tmp/t.pdf")" "Displacement, velocity and acceleration"
run --modes --figure "$tmp/t.pdf" -o /dev/null
expect "$cmd: title" "$(title "$tmp/t.pdf")" "Mode shapes"
run --sweep 1:2:5 --figure "$tmp/t.pdf" -o /dev/null
expect "$cmd: title" "$(title "$tmp/t.pdf")" "Frequency response"
run --sweep 1:2:5 --figure "$tmp/t.pdf" --figure-title "Lab 3: a chain of two" -o /dev/null
expect "$cmd: title" "$(title "$tmp/t.pdf")" "Lab 3: a chain of two"
expect "$cmd: the PDF's title" "$(pdfinfo "$tmp/t.pdf" | sed -n 's/^Title: *//p')" "Lab 3: a chain of two"
run --sweep 1:2:5 --figure "$tmp/t.svg" --figure-title "Lab 3: a chain of two" -o /dev/null
expect "$cmd: exit status" "$rc" 0
# The SVG's text is glyph outlines: its title is its <title> element, the XML's escapes
# undone (the file parses).
svg_title() {
    python3 -c 'import sys, xml.etree.ElementTree as E
t = E.parse(sys.argv[1]).getroot().find("{http://www.w3.org/2000/svg}title")
print("" if t is None else t.text)' "$1" 2>&1
}
expect "$cmd: the SVG's title" "$(svg_title "$tmp/t.svg")" "Lab 3: a chain of two"
run --headless --duration 1 --figure "$tmp/t.svg" --figure-title "Lab <3> & Zebra" -o /dev/null
expect "$cmd: the SVG's title" "$(svg_title "$tmp/t.svg")" "Lab <3> & Zebra"
run --modes --figure "$tmp/t.svg" -o /dev/null
expect "$cmd: the SVG's title" "$(svg_title "$tmp/t.svg")" "Mode shapes"
run -p resonance --modes --figure "$tmp/t.pdf" -o /dev/null
$fc text "$tmp/t.pdf" | sed -n 2p | grep -qi '^resonance' && pass ||
    fail "$cmd: the subtitle should name the preset: $($fc text "$tmp/t.pdf" | sed -n 2p)"
run -p resonance --damping 0.5 --modes --figure "$tmp/t.pdf" -o /dev/null
$fc text "$tmp/t.pdf" | sed -n 2p | grep -qi 'resonance' &&
    fail "$cmd: the settings are not the preset's, but the subtitle names it" || pass

# Axes (issue 28, issue 33 item 7): the frequency axis labelled at 1-2-5 within the data's
# range, labels inside one decade, the phase broken where it wraps, one notation per axis,
# whole masses, a run of no length.
run --sweep 0.1:3:500 --figure "$tmp/s5.svg" -o /dev/null
run --sweep 0.1:3:500 --figure "$tmp/s5.pdf" -o /dev/null
expect "$cmd: frequency labels" "$($fc xticks "$tmp/s5.pdf" frequency | sort -u)" "0.1 0.2 0.5 1 2"
for c in $M1 $M2; do
    j=$($fc phasejump "$tmp/s5.svg" $c 214,214,214)
    awk -v j="$j" 'BEGIN { exit !(j <= 90) }' && pass ||
        fail "$cmd: a phase segment in $c spans $j degrees (expected none over 90)"
done
run --sweep 2:5:100 --figure "$tmp/s25.pdf" -o /dev/null
n=$($fc xticks "$tmp/s25.pdf" frequency | head -n 1 | wc -w)
[ "$n" -ge 3 ] && pass || fail "$cmd: $n frequency labels: $($fc xticks "$tmp/s25.pdf" frequency)"
run --sweep 2:2.5:50 --figure "$tmp/s22.pdf" -o /dev/null
n=$($fc xticks "$tmp/s22.pdf" frequency | head -n 1 | wc -w)
[ "$n" -ge 3 ] && pass || fail "$cmd: $n frequency labels: $($fc xticks "$tmp/s22.pdf" frequency)"
# One notation per axis: every y label of a panel in plain decimals, or every one with an
# exponent; the amplitude here spans 1e-6 to 10 m.
run --sweep 0.05:40:300 -n 3 --figure "$tmp/s40.pdf" -o /dev/null
$fc yticks "$tmp/s40.pdf" frequency >"$tmp/yt"
$fc xticks "$tmp/s40.pdf" frequency >>"$tmp/yt"
while read -r line; do
    e=$(echo "$line" | tr ' ' '\n' | grep -c e) w=$(echo "$line" | wc -w)
    [ "$e" -eq 0 ] || [ "$e" -eq "$w" ] && pass || fail "$cmd: one axis mixes notations: $line"
done <"$tmp/yt"
[ "$(wc -l <"$tmp/yt")" -eq 4 ] && pass || fail "$cmd: expected four axes, got $(cat "$tmp/yt")"
run --modes -n 3 --figure "$tmp/mw.pdf" -o /dev/null
expect "$cmd: mass labels" "$($fc xticks "$tmp/mw.pdf" mass)" "0 1 2 3 4"
run --modes -n 12 --figure "$tmp/mw.pdf" -o /dev/null
$fc xticks "$tmp/mw.pdf" mass | tr ' ' '\n' | grep -q '\.' &&
    fail "$cmd: a mass label that is not whole: $($fc xticks "$tmp/mw.pdf" mass)" || pass
# The same digits for every frequency in the modes' legend.
d=$($fc text "$tmp/mw.pdf" | grep -o '[0-9.]* Hz' | sed 's/[0-9]*\.\([0-9]*\) Hz/\1/' | awk '{ print length($0) }' | sort -u)
[ "$(echo "$d" | wc -l)" -eq 1 ] && pass || fail "$cmd: the legend's frequencies differ in digits"
run --headless --duration 0 -n 1 --figure "$tmp/d0.svg" -o /dev/null
run --headless --duration 0 -n 1 --figure "$tmp/d0.pdf" -o /dev/null
expect "$cmd: time labels" "$($fc xticks "$tmp/d0.pdf" t | head -n 1 | cut -d' ' -f1)" "0.0"
[ "$($fc fills "$tmp/d0.svg" $M1)" -ge 1 ] && pass || fail "$cmd: the one instant is not drawn"
# The legend never cut: ten masses and the motor all named.
run --headless --duration 1 -n 10 --figure "$tmp/l10.pdf" -o /dev/null
expect "$cmd: legend" "$($fc text "$tmp/l10.pdf" | grep -o 'mass [0-9]*\|motor u(t)' | tr '\n' ' ')" \
    "mass 1 mass 2 mass 3 mass 4 mass 5 mass 6 mass 7 mass 8 mass 9 mass 10 motor u(t) "
# The motor line only when the motor moves.
run --headless --duration 1 --amplitude 0 --x0 0.1 --figure "$tmp/a0.svg" -o /dev/null
expect "$cmd: motor curves" "$($fc curves "$tmp/a0.svg" $MOTOR)" 0

# --energy --figure: the balance as its own panel, each term in the energy view's colour,
# and the largest error said is the CSV's.
run --headless -n 2 --duration 5 --energy --figure "$tmp/e.svg" -o "$tmp/e.csv"
run --headless -n 2 --duration 5 --energy --figure "$tmp/e.pdf" -o /dev/null
expect "$cmd: exit status" "$rc" 0
expect "$cmd: curves of mass 1's colour (x, v, a, kinetic)" "$($fc curves "$tmp/e.svg" $M1)" 4
expect "$cmd: curves of the motor's colour (u, motor work)" "$($fc curves "$tmp/e.svg" $MOTOR)" 2
$fc text "$tmp/e.pdf" >"$tmp/e.txt"
grep -qx 'time t (s)' "$tmp/e.txt" && pass || fail "$cmd: no x axis title 'time t (s)'"
for w in kinetic potential dissipated "motor work" contact "balance error"; do
    grep -q "$w" "$tmp/e.txt" && pass || fail "$cmd: no '$w' in the energy panel's legend"
done
said=$(sed -n 's/.*balance error (largest \([^ ]*\) J).*/\1/p' "$tmp/e.txt")
want=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    { b = $col["kinetic"] + $col["potential"] + $col["dissipated"] + $col["contact"] - $col["motor_work"]
      if (NR == 2) b0 = b; d = b - b0; if (d < 0) d = -d; if (d > m) m = d }
    END { printf "%.3g", m }' "$tmp/e.csv")
awk -v a="$said" -v b="$want" 'BEGIN { r = a / b; exit !(b > 0 && r > 0.9 && r < 1.1) }' && pass ||
    fail "$cmd: the figure says the largest error is $said J, the CSV gives $want J"
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
expect "$cmd: PNG size" "$($fc png "$tmp/s.png" 2>&1)" "1890 1772"

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
# and through symbolic links to a file not yet made (the CSV was lost): a link beside it,
# a relative link from a directory below, a link to the directory, in either order.
mkdir "$tmp/same/sub"
ln -s new.svg "$tmp/same/dangling.svg"
ln -s ../new.svg "$tmp/same/sub/up.svg"
ln -s . "$tmp/same/here"
for pair in "$tmp/same/new.svg $tmp/same/dangling.svg" "$tmp/same/dangling.svg $tmp/same/new.svg" \
    "$tmp/same/sub/up.svg $tmp/same/dangling.svg" "$tmp/same/new.svg $tmp/same/sub/up.svg" \
    "$tmp/same/d.svg $tmp/same/here/d.svg"; do
    set -- $pair
    run --headless --duration 1 -o "$1" --figure "$2"
    usage_error "$cmd" "--figure: '$2' is also -o's file (expected a different file for each output)"
    expect "$cmd: nothing written" "$(ls "$tmp/same" | grep -cx -e new.svg -e d.svg)" 0
    rm -f "$tmp/same/new.svg" "$tmp/same/d.svg"
done
(cd "$tmp/same" && "$SPRINGSIM" --headless --duration 1 -o ./e.svg --figure e.svg >/dev/null 2>&1)
expect "-o ./e.svg --figure e.svg: exit status" "$?" 2
rm "$tmp/same/dangling.svg" "$tmp/same/here"
rm -r "$tmp/same/sub"
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

# A course's examples say what drives them and every damper: the tuned-mass damper's
# subtitle names the spring damper between the masses and the force on mass 1, its sweep's
# axis is the force's frequency (no motor moves); duffing's names its cubic spring; a
# motor and a force together are the drive's frequency.
run --sweep 0.2:2:20 -p tuned-mass-damper --figure "$tmp/tmd.pdf" -o /dev/null
expect "$cmd: exit status" "$rc" 0
$fc text "$tmp/tmd.pdf" >"$tmp/tmd.txt"
grep -q 'spring dampers 0–0.038329 N·s/m' "$tmp/tmd.txt" && pass ||
    fail "$cmd: the subtitle does not name the spring damper: $(head -3 "$tmp/tmd.txt" | tr '\n' '|')"
grep -q 'force: sine, 0.5 N at 0.503292 Hz on mass 1' "$tmp/tmd.txt" && pass ||
    fail "$cmd: the subtitle does not name the force: $(head -3 "$tmp/tmd.txt" | tr '\n' '|')"
expect "$cmd: frequency axes" "$(grep -c '^force frequency f (Hz)$' "$tmp/tmd.txt")" 2
# The energy panel of a chain a force drives has the force's work, which the balance
# holds (without it the dampers take energy from nothing); a chain without has none.
run --headless -p tuned-mass-damper --energy --duration 30 --figure "$tmp/tmde.pdf" -o /dev/null
$fc text "$tmp/tmde.pdf" >"$tmp/tmde.txt"
expect "$cmd: the force's work in the legend" "$(grep -c 'force work' "$tmp/tmde.txt")" 1
run --headless --energy --duration 3 --figure "$tmp/nof.pdf" -o /dev/null
$fc text "$tmp/nof.pdf" >"$tmp/nof.txt"
expect "$cmd: no force work without a force" "$(grep -c 'force work' "$tmp/nof.txt")" 0
run --headless -p duffing --duration 1 --figure "$tmp/duf.pdf" -o /dev/null
$fc text "$tmp/duf.pdf" >"$tmp/duf.txt"
grep -q 'k3 0–4 N/m³' "$tmp/duf.txt" && pass ||
    fail "$cmd: the subtitle does not name the cubic spring: $(head -3 "$tmp/duf.txt" | tr '\n' '|')"
run --sweep 0.2:2:20 --force 1 --figure "$tmp/both.pdf" -o /dev/null
$fc text "$tmp/both.pdf" >"$tmp/both.txt"
expect "$cmd: frequency axes" "$(grep -c '^drive frequency f (Hz)$' "$tmp/both.txt")" 2
run --sweep 0.2:2:20 --figure "$tmp/motor.pdf" -o /dev/null
$fc text "$tmp/motor.pdf" >"$tmp/motor.txt"
expect "$cmd: frequency axes" "$(grep -c '^motor frequency f (Hz)$' "$tmp/motor.txt")" 2

summary
