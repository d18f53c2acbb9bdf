#!/bin/sh
# tests/pixels.sh: --graphics in a pseudo-terminal of our own (tests/pixterm.c) that answers
# the program's queries as a sixel terminal, a kitty one, one without images or one that
# answers nothing (issue 18). The images are decoded (tests/sixelcheck.c: libsixel's
# decoder, or cairo's PNG reader for kitty's) and checked against what the terminal shows
# as text (tests/lib/screen.py, pyte's emulator): each sits on its chart's drawing area and
# has its size in pixels, a cosine's peaks lie on the pixel rows the y labels give for
# +-0.5 m, each mass's colour is there; images go only where the terminal says it shows
# them, only when they changed, not over an overlay and again after it. A terminal that
# does not answer, tmux, --graphics braille and --low-bandwidth get braille. The Graphics
# control switches at run time: to braille the images stop (kitty's are deleted) and the
# charts are braille again; back, they are sent again; a terminal never asked is asked then.
# The modes view's shapes are images too, under their cells' text, in the masses' colours.
# A terminal that says it has fewer than 256 sixel colour registers (XTSMGRAPHICS) gets
# images of no more colours than that. The images are in the colours the terminal shows
# the text in (its palette and foreground, asked with OSC 4 and OSC 10): a palette of its
# own, xterm's 8 colours (the masses bold, so bright), the energy view's terms; where it
# does not say, the legends' marks are drawn in the images too.
# Ends with "pixels: N passed, M failed".
NAME=pixels
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM
plain_env
root=$(cd "$(dirname "$0")/.." && pwd)
PIXTERM=${PIXTERM:-$root/build/tests/pixterm}
SIXELCHECK=${SIXELCHECK:-$root/build/tests/sixelcheck}
screen="/usr/bin/python3 $root/tests/lib/screen.py"
# UTF-8 (braille) and box drawing as Unicode, which pyte shows as it is.
LC_ALL=C.UTF-8
NCURSES_NO_UTF8_ACS=1
export LC_ALL NCURSES_NO_UTF8_ACS
M1=005fff
M2=008700
M3=d75f00
MOTOR=000000
COSINE="-n 1 --boundary wall --x0 0.5 --damping 0"

# term KIND KEYS ARGS...: the program ($PROG, or springsim) in a 100x30 terminal of KIND
# with cells of 10 x 20 pixels on white, KEYS typed; its output in $tmp/out, the images
# in $tmp/images.
term() {
    kind=$1 keys=$2
    shift 2
    cmd="pixterm $kind '$keys' springsim $*"
    PIXTERM_PALETTE=${PIXTERM_PALETTE-} PIXTERM_TERM=${PIXTERM_TERM-} \
        "$PIXTERM" "$kind" 100 30 10 20 ffffff "$tmp/out" "$keys" ${PROG:-"$SPRINGSIM"} "$@"
    rc=$?
    "$SIXELCHECK" "$tmp/out" $M1 $M2 $M3 $MOTOR >"$tmp/images"
}
images() { grep -c "^$1 " "$tmp/images"; }
# braille_shown: braille cells (U+2800..U+28FF) in the output.
braille_shown() { LC_ALL=C grep -q "$(printf '\342[\240-\243]')" "$tmp/out"; }
queried() { LC_ALL=C grep -q "$(printf '\033\\[c')" "$tmp/out"; }

# 1. A sixel terminal: the enlarged displacement of an undamped cosine (0.5 m).
term sixel '1 ~~~ ~q' $COSINE
[ "$rc" -eq 0 ] && pass || fail "$cmd: exit $rc"
last=$(grep '^sixel ' "$tmp/images" | tail -n 1)
n=$(images sixel)
[ "$n" -ge 2 ] && pass || fail "$cmd: expected images while running; got $n"
$screen chart "$tmp/out" 100 30 Displacement "$n" >"$tmp/chart"
set -- $(head -n 1 "$tmp/chart")
ay=$1 ax=$2 aw=$3 ah=$4
set -- $last
if [ "$2 $3" = "$ay $ax" ]; then pass; else
    fail "$cmd: the image is at row $2 column $3, the drawing area at $ay $ax"
fi
if [ "$4 $5" = "$((aw * 10)) $((ah * 20))" ]; then pass; else
    fail "$cmd: the image is $4 x $5 pixels, the area $aw x $ah cells of 10 x 20"
fi
# The peaks: mass 1's colour from the row of +0.5 m to that of -0.5 m, by the labels.
span=${6%:*}
if tail -n +2 "$tmp/chart" | awk -v ay="$ay" -v span="$span" '
    { v[NR] = $1; r[NR] = $2; n = NR }
    END { a = (r[n] - r[1]) / (v[n] - v[1]); b = r[1] - a * v[1]
          top = (a * 0.5 + b - ay + 0.5) * 20; bottom = (a * -0.5 + b - ay + 0.5) * 20
          split(span, s, ":")
          exit !(n >= 3 && s[1] >= top - 1 && s[1] <= top + 1 && s[2] >= bottom - 1 &&
                 s[2] <= bottom + 1) }'
then pass; else
    fail "$cmd: mass 1's rows $span, expected the rows of +-0.5 m from the labels: $(tail -n +2 "$tmp/chart" | tr '\n' ' ')(area from row $ay)"
fi
# No braille on the charts' areas: the text there is blank (the chain keeps its braille).
# area_braille N: braille in the drawing area ($ay $ax $aw $ah) after the N-th image.
area_braille() {
    $screen show "$tmp/out" 100 30 "$1" | /usr/bin/python3 -c '
import sys
ay, ax, aw, ah = (int(v) for v in sys.argv[1:])
rows = sys.stdin.read().split("\n")[ay - 1:ay - 1 + ah]
sys.exit(0 if any(0x2801 <= ord(c) <= 0x28ff for r in rows for c in r[ax - 1:ax - 1 + aw]) else 1)
' "$ay" "$ax" "$aw" "$ah"
}
if area_braille "$n"; then
    fail "$cmd: braille left on the drawing area under the image"
else pass; fi

# Sixel goes at the cursor whatever the terminal's sixel display mode was: DECSDM is reset
# before the images (xterm's sixelScrolling false would put them at the top left).
if LC_ALL=C grep -q "$(printf '\033\\[?80l\033\\[[0-9;]*H\033P')" "$tmp/out"; then pass; else
    fail "$cmd: no DECSDM reset (CSI ? 80 l) before the images"
fi

# 2. The six plots of three masses: every mass's colour and the motor's in plot 1's image.
term sixel ' ~~q' -n 3
if grep '^sixel ' "$tmp/images" | awk '{ for (i = 6; i <= 9; i++) { split($i, s, ":"); if (s[3] < 20) next }
    found = 1 } END { exit !found }'; then pass; else
    fail "$cmd: no image holds masses 1, 2, 3 and the motor: $(head -n 6 "$tmp/images" | tr '\n' '|')"
fi

# 3. Only when changed: a chain at rest sends each chart's image once; an overlay (help)
# takes none and its closing sends them again.
places() { awk '$1 == "sixel" { print $2, $3 }' "$tmp/images" | sort -u | wc -l; }
term sixel '~~q'
if [ "$(places)" -ge 2 ] && [ "$(images sixel)" = "$(places)" ]; then pass; else
    fail "$cmd: a still chain sent $(images sixel) images to $(places) charts, expected one each"
fi
term sixel '~?~~\e~~q'
if [ "$(places)" -ge 2 ] && [ "$(images sixel)" = "$((2 * $(places)))" ]; then pass; else
    fail "$cmd: help opened and closed on a still chain: $(images sixel) images to $(places) charts, expected two each"
fi

# 4. Kitty's protocol: PNG images of the areas' size.
term kitty '1 ~~ q' $COSINE
n=$(images kitty)
last=$(grep '^kitty ' "$tmp/images" | tail -n 1)
set -- $last
if [ "$n" -ge 1 ] && [ "$2 $3 $4 $5" = "$ay $ax $((aw * 10)) $((ah * 20))" ] &&
    [ "${6##*:}" -gt 100 ]; then pass; else
    fail "$cmd: expected kitty images of $((aw * 10)) x $((ah * 20)) at $ay $ax in mass 1's colour; got $n, last: $last"
fi
[ "$(images sixel)" = 0 ] && pass || fail "$cmd: sixel sent to kitty"

# 5. Braille: a terminal without images, one that never answers, --graphics braille,
# --low-bandwidth, and inside tmux (not even asked).
for how in "vt220 ~q" "none ~q" "sixel ~q --graphics braille" "sixel ~q --low-bandwidth"; do
    set -- $how
    k=$1 keys=$2
    shift 2
    term "$k" "$keys" "$@"
    if [ "$(images sixel) $(images kitty)" = "0 0" ] && braille_shown; then pass; else
        fail "$cmd: expected braille and no image; images: $(images sixel) sixel, $(images kitty) kitty"
    fi
done
PROG=env term sixel '~q' TMUX=/tmp/x,1,0 "$SPRINGSIM"
if [ "$(images sixel)" = 0 ] && braille_shown && ! queried; then pass; else
    fail "inside tmux: expected braille and no query; images: $(images sixel)"
fi
# Asked for by name in a terminal that gives its cell size: believed.
term vt220 '~q' --graphics sixel
[ "$(images sixel)" -ge 1 ] && pass || fail "$cmd: --graphics sixel sent no image"

# 6. The Graphics control at run time (k selects it from Preset, the last control; h and l
# step it): auto -> braille stops the images and draws braille; braille -> auto sends them.
# braille_at WHEN: braille in the displacement plot's drawing area on the screen as it was
# after the WHEN-th image ("end": at the end).
braille_at() {
    $screen chart "$tmp/out" 100 30 Displacement "$1" >"$tmp/chart6"
    set -- $(head -n 1 "$tmp/chart6") "$1"
    $screen show "$tmp/out" 100 30 "$5" | /usr/bin/python3 -c '
import sys
ay, ax, aw, ah = (int(v) for v in sys.argv[1:])
rows = sys.stdin.read().split("\n")[ay - 1:ay - 1 + ah]
sys.exit(0 if any(0x2801 <= ord(c) <= 0x28ff for r in rows for c in r[ax - 1:ax - 1 + aw]) else 1)
' "$1" "$2" "$3" "$4"
}
shown() { $screen show "$tmp/out" 100 30 end >"$tmp/end" && grep -q -- "$1" "$tmp/end"; }
term sixel '~~k~h~~~q'
n=$(images sixel)
if [ "$n" -ge 2 ] && [ "$n" = "$(places)" ] && ! braille_at "$n" && braille_at end &&
    shown '▸Graphics   braille'; then pass; else
    fail "$cmd: Graphics auto -> braille: expected each chart's image once ($(places) charts, $n images), then braille on the charts and 'Graphics braille'; end: $($screen show "$tmp/out" 100 30 end | grep Graphics)"
fi
term sixel '~~k~h~~~l~~~q'
n=$(images sixel)
if [ "$(places)" -ge 2 ] && [ "$n" = "$((2 * $(places)))" ] && ! braille_at end &&
    shown '▸Graphics   auto (sixel)'; then pass; else
    fail "$cmd: Graphics auto -> braille -> auto: expected each chart's image twice ($(places) charts, $n images), no braille under them at the end, 'Graphics auto (sixel)'"
fi
# kitty's images are deleted when leaving kitty (text does not cover them): at once, not
# when the program ends (before it leaves the alternate screen, CSI ? 1049 l)
term kitty '~~k~h~~q'
if [ "$(images kitty)" -ge 2 ] && braille_at end && /usr/bin/python3 -c '
import sys
d = open(sys.argv[1], "rb").read()
sys.exit(0 if 0 <= d.find(b"\x1b_Ga=d,d=a") < d.rfind(b"\x1b[?1049l") else 1)' "$tmp/out"
then pass; else
    fail "$cmd: Graphics kitty -> braille: expected kitty's images deleted (a=d) at the switch, and braille"
fi
# never asked (--graphics braille): switching to auto asks the terminal then, and shows
# images where it says it can
term sixel '~~k~l~~~q' --graphics braille
if [ "$(LC_ALL=C grep -c "$(printf '\033\\[c')" "$tmp/out")" = 1 ] && [ "$(images sixel)" -ge 2 ] &&
    shown '▸Graphics   auto (sixel)'; then pass; else
    fail "$cmd: --graphics braille, then Graphics auto: expected one query at the switch and images; $(images sixel) images"
fi
# a terminal that answers nothing: sixel by name stays braille and says why
term none '~~k~l~~q'
if [ "$(images sixel)" = 0 ] && braille_at end && shown 'Graphics sixel: the terminal did not say its cell size' &&
    shown '▸Graphics   sixel: braille'; then pass; else
    fail "$cmd: Graphics sixel in a silent terminal: expected braille, 'sixel: braille' and why; $(images sixel) images; end: $($screen show "$tmp/out" 100 30 end | grep -i graphics)"
fi

# 7. The modes view (m) of three equal masses between fixed ends: each mode's shape is an
# image placed three rows under its title ("mode K", its first column), no braille under
# it, the three masses' colours in each; mode 2 has its node at mass 2 (phi = 1, 0, -1):
# mass 2's disc centred on the image's middle row and masses 1 and 3 mirrored about it in
# every frame of the swing; in mode 1 masses 1 and 3 move together (the same rows).
term sixel '~m~~~q' -n 3
$screen show "$tmp/out" 100 30 end >"$tmp/end"
if grep '^sixel ' "$tmp/images" | /usr/bin/python3 -c '
import sys
screen = open(sys.argv[1]).read().split("\n")
places, bad, seen = set(), [], False
for line in sys.stdin:
    f = line.split()
    row, col, w, h = (int(v) for v in f[1:5])
    discs = [tuple(int(v) for v in c.split(":")) for c in f[5:8]]
    title = screen[row - 4][col - 1:].lstrip("▸> ") if row > 3 else ""
    if not title.startswith("mode "):
        if seen:
            bad.append("an image with no mode title 3 rows above: " + line.strip())
        continue  # the plots, before m
    seen = True
    mode = title.split()[1]
    places.add((row, col, mode))
    mid = (h - 1) / 2
    centre = [(t + b) / 2 for t, b, n in discs]
    if h % 20 or w % 10 or any(n < 100 for t, b, n in discs):
        bad.append("size or colours: " + line.strip())
    elif mode == "2" and (abs(centre[1] - mid) > 1 or abs(centre[0] + centre[2] - 2 * mid) > 1):
        bad.append("mode 2 not about its node: " + line.strip())
    elif mode == "1" and abs(centre[0] - centre[2]) > 1:
        bad.append("mode 1 masses 1 and 3 apart: " + line.strip())
    area = [r[col - 1:col - 1 + w // 10] for r in screen[row - 1:row - 1 + h // 20]]
    if any(0x2801 <= ord(c) <= 0x28ff for r in area for c in r):
        bad.append("braille under the image: " + line.strip())
modes = sorted(m for r, c, m in places)
print("; ".join(bad[:3]), modes)
sys.exit(0 if not bad and modes == ["1", "2", "3"] else 1)
' "$tmp/end" >"$tmp/modes"; then pass; else
    fail "$cmd: the modes view's shapes as images: $(cat "$tmp/modes")"
fi

# 8. Sixel colour registers: three masses running, every image decoded. Sixel lines are
# drawn without blends, so an image holds only the colours drawn: on xterm's 256 colours
# (no answer to XTSMGRAPHICS) and on a terminal that says 16, images of at most 16, the
# background white and each mass's and the motor's colour exact in plot 1's; one that
# says 4 gets at most 4 (libsixel's palette for fewer colours than were drawn), still
# more than the background.
# colours_ok MIN MAX: every sixel image holds at most MAX colours, the most coloured at
# least MIN (and there are some).
colours_ok() {
    grep '^sixel ' "$tmp/images" | awk -v lo="$1" -v hi="$2" '
        { split($NF, c, "="); n++; if (c[2] + 0 > hi + 0) bad++; if (c[2] + 0 > top) top = c[2] + 0 }
        END { exit !(n >= 2 && !bad && top >= lo + 0) }'
}
colours() { grep '^sixel ' "$tmp/images" | sed 's/.*colours=//' | sort -n | uniq | tr '\n' ' '; }
# drawn_exact: images of 5 to 16 colours, one holding white, masses 1-3 and the motor.
drawn_exact() {
    "$SIXELCHECK" "$tmp/out" ffffff $M1 $M2 $M3 $MOTOR >"$tmp/images"
    colours_ok 5 16 && grep '^sixel ' "$tmp/images" | awk '
        { for (i = 6; i <= 10; i++) { split($i, s, ":"); if (s[3] < 20) next } found = 1 }
        END { exit !found }'
}
term sixel ' ~~q' -n 3
if drawn_exact; then pass; else
    fail "$cmd: xterm's 256 colours: expected images of at most 16 colours, one holding white and masses 1-3 and the motor exactly; got $(colours); $(grep '^sixel ' "$tmp/images" | head -n 3 | tr '\n' '|')"
fi
term sixel/16 ' ~~q' -n 3
if drawn_exact; then pass; else
    fail "$cmd: 16 colour registers: expected images of at most 16 colours, one holding white and masses 1-3 and the motor exactly; got $(colours); $(grep '^sixel ' "$tmp/images" | head -n 3 | tr '\n' '|')"
fi
term sixel/4 ' ~~q' -n 3
if colours_ok 2 4; then pass; else
    fail "$cmd: 4 colour registers: expected images of 2 to 4 colours; got $(colours)"
fi

# 9. One colour a mass: the images in the terminal's own colours. holding COLOURS...: some
# sixel image holds 20 pixels or more of every colour given (sixelcheck run again for them).
holding() {
    "$SIXELCHECK" "$tmp/out" "$@" >"$tmp/images9"
    grep '^sixel ' "$tmp/images9" | awk -v n="$#" '
        { for (i = 6; i < 6 + n; i++) { split($i, s, ":"); if (s[3] < 20) next } found = 1 }
        END { exit !found }'
}
# lacking COLOUR: no sixel image holds 20 pixels of it.
lacking() {
    "$SIXELCHECK" "$tmp/out" "$1" >"$tmp/images9"
    ! grep '^sixel ' "$tmp/images9" | awk '{ split($6, s, ":"); if (s[3] >= 20) found = 1 }
        END { exit !found }'
}
# A palette of its own: mass 1 (entry 27) teal, mass 3 (166) violet, the foreground dark
# red; mass 2 keeps xterm's green (entry 28).
PIXTERM_PALETTE=27=00af87,166=5f00af,fg=af0000 term sixel ' ~~q' -n 3
if holding 00af87 $M2 5f00af af0000 && lacking $M1 && lacking $M3; then pass; else
    fail "$cmd: the terminal's palette (mass 1 00af87, mass 3 5f00af, motor af0000): $(head -n 3 "$tmp/images9" | tr '\n' '|')"
fi
# TERM=xterm: 8 colours, the masses bold, which xterm shows bright (entries 12, 10, 9);
# in the energy view kinetic, potential and damped are masses 1 to 3's colours, not the
# orange of 256 colours.
PIXTERM_TERM=xterm term sixel ' ~e~~q' -n 3
if holding 5c5cff 00ff00 ff0000 && lacking $M3; then pass; else
    fail "$cmd: TERM=xterm, the energy view: expected bright blue, green and red terms, no orange: $(head -n 3 "$tmp/images" | tr '\n' '|')"
fi
# Direct colour (TERM=xterm-direct): the masses' colours sent as they are (SGR 38:2), the
# images in the same.
PIXTERM_TERM=xterm-direct term sixel ' ~~q' -n 3
if LC_ALL=C grep -q "$(printf '\033')\[38:2::0:95:255m" "$tmp/out" &&
    LC_ALL=C grep -q "$(printf '\033')\[38:2::215:95:0m" "$tmp/out" && holding $M1 $M2 $M3; then
    pass
else
    fail "$cmd: TERM=xterm-direct: expected mass 1 and 3's colours as SGR 38:2 and in the images: $(head -n 3 "$tmp/images9" | tr '\n' '|')"
fi
# A terminal that does not say its colours: the legend in the image as well, its last row
# of cells (masses 1-3 and the motor there in the first image, at rest: each curve is
# then a dot in the middle rows, far above it).
# lastrow_marks: the first sixel image holds 20 pixels of each colour asked, the lowest in
# its last 20 rows.
lastrow_marks() {
    grep -m 1 '^sixel ' "$tmp/images" | awk '{ h = $5; ok = 1; for (i = 6; i <= 9; i++) {
        split($i, s, ":"); if (s[2] < h - 20 || s[3] < 20) ok = 0 } exit !ok }'
}
PIXTERM_PALETTE=none term sixel '~ ~~q' -n 3
if lastrow_marks; then pass; else
    fail "$cmd: no palette answered: expected the legend (masses 1-3, motor) in the first image's last row: $(head -n 2 "$tmp/images" | tr '\n' '|')"
fi
# With the palette said, no legend in the image.
term sixel '~ ~~q' -n 3
if ! lastrow_marks; then pass; else
    fail "$cmd: the palette said, yet the legend is drawn in the image: $(head -n 2 "$tmp/images" | tr '\n' '|')"
fi

summary
