#!/usr/bin/python3
"""tests/lib/xcolours.py: in a screenshot of a real terminal, each legend mark's colour
against the colour of its own curve in its chart's image: the mark's pixels (its cell's,
away from the background) and the pixels of that one curve, told apart from the others
by where the run puts it.

  xcolours.py DIR COLS ROWS SPEC...

DIR holds out.shot and winsize (tests/lib/xfeed.py's) and shot.png (the screenshot, the
terminal's window at the top left of a black screen). Each SPEC says how a chart's curves
are told apart, the chart named by a word of its title (on the rows above its image):

  WORD[@FROM-TO]=A,B,C   in each pixel column of the image (FROM% to TO% of its width:
                         default all) whose curve pixels make exactly that many separate
                         runs, the top run is curve A's, the next B's, ...
  WORD=|NAME             the column with the longest upright run of curve pixels (over
                         60% of the image's height) is NAME's (the drive's frequency)

A curve's colour is the median of the core (the quarter farthest from the background) of
its pixels, from 10 columns or more. Each legend mark (━, ┅, ┃ on a frame's bottom border
or the energy view's legend row) is judged against its own curve in the chart above it
(below it, for the energy view's legend), or where that chart has no SPEC, against the
same name's curve in a chart that has. Prints a line a mark: "NAME mark L*a*b*=L,a,b
curve L*a*b*=L,a,b dE D [in CHART]"; "FAIL" ends the line (and the exit status is 1)
where dE is over 10 or the curve could not be told apart."""
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


def core(pixels, bg):
    """The colour of pixels: the median of the quarter farthest from the background."""
    pixels = sorted(pixels, key=lambda p: -de(p, bg))
    c = pixels[:max(1, len(pixels) // 4)]
    return tuple(sorted(p[k] for p in c)[len(c) // 2] for k in range(3))


def parse_spec(s):
    """(word, from, to, order or None, upright name or None) of a SPEC."""
    m = re.fullmatch(r'([^@=]+)(?:@([0-9]+)-([0-9]+))?=(\|?)(.+)', s)
    if not m:
        raise SystemExit('bad SPEC ' + s)
    lo, hi = float(m.group(2) or 0) / 100, float(m.group(3) or 100) / 100
    if m.group(4):
        return (m.group(1), lo, hi, None, m.group(5))
    return (m.group(1), lo, hi, m.group(5).split(','), None)


class Shot:
    """The screenshot's pixels, in L*a*b*, and the background's."""

    def __init__(self, d):
        size = subprocess.run(['identify', '-format', '%w %h', d + '/shot.png'],
                              capture_output=True, text=True, check=True).stdout.split()
        self.W, self.H = int(size[0]), int(size[1])
        self.raw = subprocess.run(['convert', d + '/shot.png', '-depth', '8', 'rgb:-'],
                                  capture_output=True, check=True).stdout

    def px(self, x, y):
        i = 3 * (y * self.W + x)
        return self.raw[i], self.raw[i + 1], self.raw[i + 2]

    def lab(self, x, y):
        return lab(self.px(x, y))


def ink(p, bg):
    """A curve's pixel: away from the background, and not a light grey (gridlines, the
    zero line, the grey blends at a black line's edges)."""
    return de(p, bg) > 20 and not (math.hypot(p[1], p[2]) < 12 and p[0] > 35)


def runs(flags):
    """The runs of true in flags (gaps of one false joined): lists of indices."""
    out, gap = [], 9
    for i, f in enumerate(flags):
        if f:
            if gap > 1:
                out.append([])
            out[-1].append(i)
            gap = 0
        else:
            gap += 1
    return out


def curves(shot, image, spec, bg):
    """{name: (colour or None, columns)} of the curves spec tells apart in image."""
    ix, iy, iw, ih = image
    _, lo, hi, order, upright = spec
    x1, y1 = min(ix + iw, shot.W), min(iy + ih, shot.H)
    got, cols = {}, {}
    best = (0, None)
    for x in range(ix + int(lo * iw), min(ix + int(hi * iw), x1)):
        col = [shot.lab(x, y) for y in range(iy, y1)]
        groups = runs([ink(p, bg) for p in col])
        if upright:
            longest = max(groups, key=len, default=[])
            if len(longest) > best[0]:
                best = (len(longest), [col[i] for i in longest])
        elif len(groups) == len(order):
            for name, g in zip(order, groups):
                got.setdefault(name, []).extend(col[i] for i in g)
                cols[name] = cols.get(name, 0) + 1
    if upright:
        ok = best[0] > 0.6 * ih
        return {upright: (core(best[1], bg) if ok else None, 10 if ok else 0)}
    return {n: (core(got[n], bg) if cols.get(n, 0) >= 10 else None, cols.get(n, 0))
            for n in order}


def chart_of(lines, image, cw, words):
    """The SPEC word in the title of the chart of image (r, c, w): on the five rows above
    it, nearest first, over its columns."""
    r, c, w = image
    for row in range(r - 2, max(r - 7, -1), -1):
        text = lines[row][max(0, c - 10):c - 1 + w // cw + 10]
        for word in words:
            if word in text:
                return word
    return None


def marks(lines, shot, x0, y0, cw, ch, bg):
    """Each legend mark: (name, its colour, its pixel x and y, on a border)."""
    for r, line in enumerate(lines):
        border = line[:1] in ('└', '╰', 'm')  # m: └ as DEC's line drawing (TERM=xterm)
        if not border and 'kinetic' not in line:
            continue
        for c, ch_ in enumerate(line):
            if ch_ not in '━┅┃':
                continue
            name = re.match(r'[━┅┃] ?([0-9]+|[a-z]+)?', line[c:]).group(1) or '?'
            name = name.rstrip('qjmx') or name  # DEC line drawing's q after it
            cell = [shot.lab(x0 + c * cw + i, y0 + r * ch + j) for i in range(cw)
                    for j in range(ch)]
            inked = [p for p in cell if de(p, bg) > 20]
            if inked:
                yield name, core(inked, bg), x0 + c * cw, y0 + r * ch, border


def nearest(images, mx, my, border, ch, cw):
    """The chart's image of a mark: above a border's legend (below the energy view's),
    the nearest, the legend starting left of the image under the y labels."""
    best = None
    for key, (ix, iy, iw, ih) in images.items():
        dist = my - (iy + ih) if border else iy - my
        gap = max(0, ix - mx, mx - (ix + iw))
        if dist >= -ch and gap < 12 * cw and (best is None or dist + gap < best[0]):
            best = (dist + gap, key)
    return best and best[1]


def main():
    d, cols, rows = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    specs = [parse_spec(s) for s in sys.argv[4:]]
    wrows, wcols, xpix, ypix = (int(v) for v in open(d + '/winsize').read().split())
    cw, ch = xpix // wcols, ypix // wrows
    shot = Shot(d)
    # The window: the first pixel that is not the screen's black, then xterm's border.
    wy = next(y for y in range(shot.H) if shot.px(shot.W // 4, y) != (0, 0, 0))
    wx = next(x for x in range(shot.W) if shot.px(x, wy + 5) != (0, 0, 0))
    x0, y0 = wx + 2, wy + 2
    bg = shot.lab(wx + 1, wy + 1)
    data = open(d + '/out.shot', 'rb').read()
    images = {}  # the images on the screen at the end: a later one covers earlier ones
    for im in re.finditer(rb'\x1b\[(\d+);(\d+)H\x1bP[^q]*q"1;1;(\d+);(\d+)', data):
        r, c, w, h = (int(v) for v in im.groups())
        new = (x0 + (c - 1) * cw, y0 + (r - 1) * ch, w, h)
        images = {k: o for k, o in images.items()
                  if not (o[0] < new[0] + w and new[0] < o[0] + o[2] and
                          o[1] < new[1] + h and new[1] < o[1] + o[3])}
        images[(r, c)] = new
    lines = screen.screen(d + '/out.shot', cols, rows, 'end')
    # Each chart with a SPEC: its curves' colours, by name.
    measured = {}  # image key: (word, {name: (colour, columns)})
    for key, im in images.items():
        word = chart_of(lines, (key[0], key[1], im[2]), cw, [s[0] for s in specs])
        for s in specs:
            if s[0] == word:
                found = measured.setdefault(key, (word, {}))[1]
                found.update(curves(shot, im, s, bg))
    bad = 0
    for name, mark, mx, my, border in marks(lines, shot, x0, y0, cw, ch, bg):
        key = nearest(images, mx, my, border, ch, cw)
        if key is None:
            continue
        where = [measured[key]] if key in measured else []
        where += [m for k, m in measured.items() if k != key and name in m[1]]
        where = [m for m in where if name in m[1]]
        colour = where[0][1][name][0] if where else None
        said = '%s mark L*a*b*=%s' % (name, ','.join('%d' % round(v) for v in mark))
        if colour is None:
            print('%s: no curve of its own told apart (%s) FAIL' %
                  (said, where[0][0] if where else 'no chart names it'))
            bad += 1
            continue
        e = de(mark, colour)
        print('%s curve L*a*b*=%s dE %.1f in %s%s' %
              (said, ','.join('%d' % round(v) for v in colour), e, where[0][0],
               '' if e <= 10 else ' FAIL'))
        bad += e > 10
    sys.exit(1 if bad else 0)


main()
