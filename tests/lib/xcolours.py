#!/usr/bin/python3
"""tests/lib/xcolours.py: in a screenshot of a real terminal, each legend mark's colour
against its chart's image: the mark's pixels (its cell's, away from the background) and
the pixels of the nearest image above it (or, for the energy view's legend above its
chart, below it), placed where the program put it.

  xcolours.py DIR COLS ROWS

DIR holds out.shot and winsize (tests/lib/xfeed.py's) and shot.png (the screenshot, the
terminal's window at the top left of a black screen). Each legend mark (━, ┅, ┃ on a
frame's bottom border or the energy view's legend row) is a line "NAME R,G,B N": N the
image's pixels within CIE76 delta E 10 of the mark's colour; "FAIL" ends the line (and
the exit status is 1) where N is under 20."""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import screen  # noqa: E402


CACHE = {}


def lab(p):
    if p in CACHE:
        return CACHE[p]
    CACHE[p] = lab_of(p)
    return CACHE[p]


def lab_of(p):
    def lin(c):
        c /= 255.0
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (lin(float(v)) for v in p)
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
    f = [t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116 for t in (x, y, z)]
    return (116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2]))


def de(a, b):
    return math.dist(a, b)


def main():
    d, cols, rows = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    wrows, wcols, xpix, ypix = (int(v) for v in open(d + '/winsize').read().split())
    cw, ch = xpix // wcols, ypix // wrows
    size = subprocess.run(['identify', '-format', '%w %h', d + '/shot.png'],
                          capture_output=True, text=True, check=True).stdout.split()
    W, H = int(size[0]), int(size[1])
    raw = subprocess.run(['convert', d + '/shot.png', '-depth', '8', 'rgb:-'],
                         capture_output=True, check=True).stdout

    def px(x, y):
        i = 3 * (y * W + x)
        return raw[i], raw[i + 1], raw[i + 2]
    # The window: the first pixel that is not the screen's black, then xterm's border.
    wy = next(y for y in range(H) if px(W // 4, y) != (0, 0, 0))
    wx = next(x for x in range(W) if px(x, wy + 5) != (0, 0, 0))
    x0, y0 = wx + 2, wy + 2
    bg = lab(px(wx + 1, wy + 1))
    data = open(d + '/out.shot', 'rb').read()
    images = {}
    for im in re.finditer(rb'\x1b\[(\d+);(\d+)H\x1bP[^q]*q"1;1;(\d+);(\d+)', data):
        r, c, w, h = (int(v) for v in im.groups())
        images[(r, c)] = (x0 + (c - 1) * cw, y0 + (r - 1) * ch, w, h)
    lines = screen.screen(d + '/out.shot', cols, rows, 'end')
    bad = 0
    for r, line in enumerate(lines):
        border = line[:1] in ('└', '╰', 'm')  # m: └ as DEC's line drawing (TERM=xterm)
        if not border and 'kinetic' not in line:
            continue
        for c, ch_ in enumerate(line):
            if ch_ not in '━┅┃':
                continue
            name = re.match(r'[━┅┃] ?([0-9]+|[a-z]+)?', line[c:]).group(1) or '?'
            name = name.rstrip('qjmx') or name  # DEC line drawing's q after it
            cell = [lab(px(x0 + c * cw + i, y0 + r * ch + j)) for i in range(cw)
                    for j in range(ch)]
            ink = [p for p in cell if de(p, bg) > 20]
            if not ink:
                continue
            # the glyph's core: the quarter of its pixels farthest from the background
            ink.sort(key=lambda p: -de(p, bg))
            core = ink[:max(1, len(ink) // 4)]
            mark = tuple(sorted(p[k] for p in core)[len(core) // 2] for k in range(3))
            mx, my = x0 + c * cw, y0 + r * ch
            best = None
            for (ix, iy, iw, ih) in images.values():
                # the chart's: above a border's legend (below the energy view's), the
                # nearest, the legend starting left of the image under the y labels
                dist = my - (iy + ih) if border else iy - my
                gap = max(0, ix - mx, mx - (ix + iw))
                if dist >= -ch and gap < 12 * cw and (best is None or dist + gap < best[0]):
                    best = (dist + gap, ix, iy, iw, ih)
            if best is None:
                continue
            _, ix, iy, iw, ih = best
            n = sum(1 for y in range(iy, min(iy + ih, H)) for x in range(ix, min(ix + iw, W))
                    if de(lab(px(x, y)), mark) <= 10)
            rgb = ','.join('%d' % round(v) for v in mark)
            print('%s L*a*b*=%s %d%s' % (name, rgb, n, '' if n >= 20 else ' FAIL'))
            bad += n < 20
    sys.exit(1 if bad else 0)


main()
